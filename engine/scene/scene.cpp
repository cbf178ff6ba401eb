#include "engine/scene/scene.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/constants.hpp>

namespace pw::engine {

Bounds localBounds(const Mesh& mesh) {
  Bounds b;
  for (const glm::vec3& p : mesh.positions) b.add(p);
  return b;
}

Bounds worldBounds(const Shape& shape) {
  Bounds world;
  if (!shape.mesh) return world;
  const Bounds local = localBounds(*shape.mesh);
  if (local.empty()) return world;
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 p((corner & 1) ? local.max.x : local.min.x, (corner & 2) ? local.max.y : local.min.y,
                      (corner & 4) ? local.max.z : local.min.z);
    world.add(glm::vec3(shape.transform * glm::vec4(p, 1.0f)));
  }
  return world;
}

Bounds sceneBounds(const Scene& scene) {
  Bounds b;
  for (const Shape& s : scene.shapes) b.add(worldBounds(s));
  return b;
}

void computeSmoothNormals(Mesh& mesh) {
  mesh.normals.assign(mesh.positions.size(), glm::vec3(0.0f));
  for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    const uint32_t a = mesh.indices[i], b = mesh.indices[i + 1], c = mesh.indices[i + 2];
    const glm::vec3 n = glm::cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);
    mesh.normals[a] += n;
    mesh.normals[b] += n;
    mesh.normals[c] += n;
  }
  for (glm::vec3& n : mesh.normals) {
    const float len = glm::length(n);
    n = len > 0.0f ? n / len : glm::vec3(0, 0, 1);
  }
}

Viewpoint defaultViewpoint(const Scene& scene) {
  Viewpoint v;
  v.description = "Default";
  const Bounds b = sceneBounds(scene);
  if (b.empty()) return v;
  const float radius = 0.5f * glm::length(b.size());
  const float distance = radius / std::sin(v.fieldOfViewRad * 0.5f);
  v.position = b.center() + glm::vec3(0, 0, std::max(distance, 0.1f));
  return v;
}

}  // namespace pw::engine
