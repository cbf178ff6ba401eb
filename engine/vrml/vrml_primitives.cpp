// Box, Sphere, Cylinder and Cone with the texture layouts of ISO/IEC 14772-1:
// Box 6.4 (each face shows the whole image upright when seen from outside; top seen
// with -Z up, bottom with +Z up), Sphere 6.44, Cylinder 6.12 and Cone 6.10 (the image
// wraps counter-clockwise seen from above, starting and ending at the back, -Z; caps
// show a circle cut from the image, top seen with -Z up, bottom with +Z up).
#include <cmath>

#include <glm/gtc/constants.hpp>

#include "engine/vrml/vrml_geometry.h"

namespace pw::engine::vrml {

namespace {

void addVertex(Mesh& m, const glm::vec3& p, const glm::vec3& n, const glm::vec2& t, bool texCoords) {
  m.positions.push_back(p);
  m.normals.push_back(n);
  if (texCoords) m.texCoords.push_back(t);
}

uint32_t vertexCount(const Mesh& m) { return static_cast<uint32_t>(m.positions.size()); }

// Direction around the Y axis for texture coordinate s: s = 0 at -Z, 0.25 at -X,
// 0.5 at +Z, 0.75 at +X (counter-clockwise seen from above).
glm::vec3 around(float s) {
  const float theta = s * glm::two_pi<float>();
  return {-std::sin(theta), 0.0f, -std::cos(theta)};
}

void addCap(Mesh& m, float radius, float y, bool top, bool texCoords, int slices) {
  const glm::vec3 normal(0, top ? 1.0f : -1.0f, 0);
  const uint32_t center = vertexCount(m);
  addVertex(m, {0, y, 0}, normal, {0.5f, 0.5f}, texCoords);
  for (int j = 0; j <= slices; ++j) {
    const glm::vec3 d = around(static_cast<float>(j) / slices);
    // Top: seen from above with -Z up, so t grows towards -Z. Bottom: +Z up.
    const glm::vec2 t(0.5f + 0.5f * d.x, top ? 0.5f - 0.5f * d.z : 0.5f + 0.5f * d.z);
    addVertex(m, d * radius + glm::vec3(0, y, 0), normal, t, texCoords);
  }
  for (int j = 0; j < slices; ++j) {
    const uint32_t a = center + 1 + j, b = a + 1;
    if (top) m.indices.insert(m.indices.end(), {center, a, b});
    else m.indices.insert(m.indices.end(), {center, b, a});
  }
}

}  // namespace

Mesh makeBox(const glm::vec3& size, bool texCoords) {
  Mesh m;
  const glm::vec3 h = size * 0.5f;
  // Each face: outward normal and its corners bottom-left, bottom-right, top-right,
  // top-left as the standard orients the image on it.
  struct Face {
    glm::vec3 normal;
    glm::vec3 corners[4];
  };
  const Face faces[6] = {
      {{0, 0, 1}, {{-h.x, -h.y, h.z}, {h.x, -h.y, h.z}, {h.x, h.y, h.z}, {-h.x, h.y, h.z}}},        // front
      {{0, 0, -1}, {{h.x, -h.y, -h.z}, {-h.x, -h.y, -h.z}, {-h.x, h.y, -h.z}, {h.x, h.y, -h.z}}},   // back
      {{1, 0, 0}, {{h.x, -h.y, h.z}, {h.x, -h.y, -h.z}, {h.x, h.y, -h.z}, {h.x, h.y, h.z}}},        // right
      {{-1, 0, 0}, {{-h.x, -h.y, -h.z}, {-h.x, -h.y, h.z}, {-h.x, h.y, h.z}, {-h.x, h.y, -h.z}}},   // left
      {{0, 1, 0}, {{-h.x, h.y, h.z}, {h.x, h.y, h.z}, {h.x, h.y, -h.z}, {-h.x, h.y, -h.z}}},        // top
      {{0, -1, 0}, {{-h.x, -h.y, -h.z}, {h.x, -h.y, -h.z}, {h.x, -h.y, h.z}, {-h.x, -h.y, h.z}}},   // bottom
  };
  const glm::vec2 uv[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (const Face& f : faces) {
    const uint32_t base = vertexCount(m);
    for (int i = 0; i < 4; ++i) addVertex(m, f.corners[i], f.normal, uv[i], texCoords);
    m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
  }
  return m;
}

Mesh makeSphere(float radius, bool texCoords, int slices, int stacks) {
  Mesh m;
  for (int i = 0; i <= stacks; ++i) {
    const float t = static_cast<float>(i) / stacks;
    const float phi = (t - 0.5f) * glm::pi<float>();  // latitude, -pi/2 at the bottom
    for (int j = 0; j <= slices; ++j) {
      const float s = static_cast<float>(j) / slices;
      const glm::vec3 d = around(s) * std::cos(phi) + glm::vec3(0, std::sin(phi), 0);
      addVertex(m, d * radius, d, {s, t}, texCoords);
    }
  }
  const uint32_t row = static_cast<uint32_t>(slices + 1);
  for (int i = 0; i < stacks; ++i) {
    for (int j = 0; j < slices; ++j) {
      const uint32_t a = i * row + j, b = a + 1, c = a + row + 1, d = a + row;
      // Moving along s goes towards +X on the front, along t upwards: a b c d is
      // counter-clockwise seen from outside. Skip the triangles that collapse at a pole.
      if (i > 0) m.indices.insert(m.indices.end(), {a, b, c});
      if (i + 1 < stacks) m.indices.insert(m.indices.end(), {a, c, d});
    }
  }
  return m;
}

Mesh makeCylinder(float radius, float height, bool side, bool top, bool bottom, bool texCoords, int slices) {
  Mesh m;
  const float y = height * 0.5f;
  if (side) {
    const uint32_t base = vertexCount(m);
    for (int j = 0; j <= slices; ++j) {
      const float s = static_cast<float>(j) / slices;
      const glm::vec3 d = around(s);
      addVertex(m, d * radius + glm::vec3(0, -y, 0), d, {s, 0}, texCoords);
      addVertex(m, d * radius + glm::vec3(0, y, 0), d, {s, 1}, texCoords);
    }
    for (int j = 0; j < slices; ++j) {
      const uint32_t b0 = base + 2 * j, t0 = b0 + 1, b1 = b0 + 2, t1 = b0 + 3;
      m.indices.insert(m.indices.end(), {b0, b1, t1, b0, t1, t0});
    }
  }
  if (top) addCap(m, radius, y, true, texCoords, slices);
  if (bottom) addCap(m, radius, -y, false, texCoords, slices);
  return m;
}

Mesh makeCone(float bottomRadius, float height, bool side, bool bottom, bool texCoords, int slices) {
  Mesh m;
  const float y = height * 0.5f;
  if (side) {
    const uint32_t base = vertexCount(m);
    // The side's normal leans up by the cone's half-angle: (h * d + r * up), normalised.
    auto normalAt = [&](float s) {
      const glm::vec3 n = around(s) * height + glm::vec3(0, bottomRadius, 0);
      const float length = glm::length(n);
      return length > 0.0f ? n / length : glm::vec3(0, 1, 0);
    };
    for (int j = 0; j <= slices; ++j) {
      const float s = static_cast<float>(j) / slices;
      addVertex(m, around(s) * bottomRadius + glm::vec3(0, -y, 0), normalAt(s), {s, 0}, texCoords);
      // One apex per slice, with the normal of the slice's middle, for smooth shading.
      const float mid = (static_cast<float>(j) + 0.5f) / slices;
      addVertex(m, {0, y, 0}, normalAt(mid), {mid, 1}, texCoords);
    }
    for (int j = 0; j < slices; ++j) {
      const uint32_t b0 = base + 2 * j, apex = b0 + 1, b1 = b0 + 2;
      m.indices.insert(m.indices.end(), {b0, b1, apex});
    }
  }
  if (bottom) addCap(m, bottomRadius, -y, false, texCoords, slices);
  return m;
}

}  // namespace pw::engine::vrml
