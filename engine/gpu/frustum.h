// View-frustum culling of world-space boxes on the CPU, per shape and per frame.
#pragma once

#include <array>

#include <glm/glm.hpp>

#include "engine/scene/scene.h"

namespace pw::engine::gpu {

// Six planes (a, b, c, d), inside where a x + b y + c z + d >= 0, from a world-to-clip
// matrix with Vulkan's clip volume -w <= x, y <= w, 0 <= z <= w (Gribb and Hartmann,
// "Fast extraction of viewing frustum planes", 2001, with the near plane z >= 0).
struct Frustum {
  std::array<glm::vec4, 6> planes;
};

Frustum frustumFromViewProjection(const glm::mat4& viewProjection);

// False only when the box lies entirely outside one plane (conservative: boxes near a
// frustum corner may pass although they are outside). Empty bounds are never visible.
bool intersects(const Frustum& frustum, const Bounds& box);

}  // namespace pw::engine::gpu
