#include "engine/gpu/frustum.h"

namespace pw::engine::gpu {

Frustum frustumFromViewProjection(const glm::mat4& m) {
  // Row i of the matrix (glm is column-major: m[column][row]).
  const auto row = [&](int i) { return glm::vec4(m[0][i], m[1][i], m[2][i], m[3][i]); };
  const glm::vec4 x = row(0), y = row(1), z = row(2), w = row(3);
  Frustum f{{w + x, w - x, w + y, w - y, z, w - z}};
  for (glm::vec4& p : f.planes) {
    const float length = glm::length(glm::vec3(p));
    if (length > 0.0f) p /= length;
  }
  return f;
}

bool intersects(const Frustum& frustum, const Bounds& box) {
  if (box.empty()) return false;
  for (const glm::vec4& p : frustum.planes) {
    // The box corner furthest along the plane's normal (the "positive vertex").
    const glm::vec3 corner(p.x >= 0 ? box.max.x : box.min.x, p.y >= 0 ? box.max.y : box.min.y,
                           p.z >= 0 ? box.max.z : box.min.z);
    if (glm::dot(glm::vec3(p), corner) + p.w < 0.0f) return false;
  }
  return true;
}

}  // namespace pw::engine::gpu
