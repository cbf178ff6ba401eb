// The web page's viewer (web/src, three.js), bundled at build time: empty when this
// photowalk was built without node and web/node_modules (scripts/install-tools.sh).
#pragma once

#include <string_view>

namespace pw::engine {

std::string_view viewerBundle();

}  // namespace pw::engine
