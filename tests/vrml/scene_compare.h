// Deep comparison of two scenes for round-trip tests: every number bit for bit, and
// the same sharing (two shapes share a mesh, appearance or texture in one scene exactly
// when they do in the other). Texture urls may differ (a writer renames files); their
// decoded pixels may not.
#pragma once

#include <string>

#include "engine/scene/scene.h"

namespace pw::engine {

// "" when equal, else what differs first ("shape 3: mesh positions differ").
std::string sceneDifference(const Scene& a, const Scene& b);

}  // namespace pw::engine
