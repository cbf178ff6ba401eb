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

Mesh subdivideTriangles(const Mesh& mesh, int k) {
  if (k <= 1 || mesh.topology != Topology::kTriangles) return mesh;
  Mesh out;
  out.topology = mesh.topology;
  out.solid = mesh.solid;
  const float n = static_cast<float>(k);
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const uint32_t v[3] = {mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]};
    const uint32_t first = static_cast<uint32_t>(out.positions.size());
    // Grid point (i, j): weights (k - i - j, i, j) / k on the corners. A point on an
    // edge is the sum of the same two products from either triangle (the third is
    // zero), and float addition commutes: neighbours agree exactly.
    const auto blend = [&](const auto& values, int i, int j) {
      const float wa = static_cast<float>(k - i - j), wb = static_cast<float>(i), wc = static_cast<float>(j);
      return (wa * values[v[0]] + wb * values[v[1]] + wc * values[v[2]]) / n;
    };
    for (int j = 0; j <= k; ++j) {
      for (int i = 0; i + j <= k; ++i) {
        out.positions.push_back(blend(mesh.positions, i, j));
        if (!mesh.normals.empty()) out.normals.push_back(blend(mesh.normals, i, j));
        if (!mesh.texCoords.empty()) out.texCoords.push_back(blend(mesh.texCoords, i, j));
        if (!mesh.colors.empty()) out.colors.push_back(blend(mesh.colors, i, j));
      }
    }
    // Row j holds k - j + 1 points, starting after the rows before it.
    const auto at = [&](int i, int j) { return first + static_cast<uint32_t>(j * (k + 1) - j * (j - 1) / 2 + i); };
    for (int j = 0; j < k; ++j) {
      for (int i = 0; i + j < k; ++i) {
        out.indices.insert(out.indices.end(), {at(i, j), at(i + 1, j), at(i, j + 1)});
        if (i + j + 1 < k) out.indices.insert(out.indices.end(), {at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
      }
    }
  }
  return out;
}

}  // namespace pw::engine
