// Extrusion (ISO/IEC 14772-1, 6.18): a cross-section swept along a spine, scaled and
// turned at each spine point, with optional caps.
#include <algorithm>
#include <cmath>

#include "engine/vrml/polygon_mesh.h"
#include "engine/vrml/vrml_fields.h"
#include "engine/vrml/vrml_geometry.h"
#include "engine/vrml/vrml_transform.h"

namespace pw::engine::vrml {

namespace {

constexpr double kTiny = 1e-12;

glm::dvec3 normalizedOr(const glm::dvec3& v, const glm::dvec3& fallback) {
  const double length = glm::length(v);
  return length > kTiny ? v / length : fallback;
}

// The spine-aligned cross-section planes (6.18.2): per spine point the X, Y, Z axes.
std::vector<glm::dmat3> crossSectionPlanes(const std::vector<glm::dvec3>& spine) {
  const size_t n = spine.size();
  const bool closed = n > 2 && glm::length(spine.front() - spine.back()) < kTiny;
  std::vector<glm::dvec3> y(n), z(n);
  for (size_t i = 0; i < n; ++i) {
    glm::dvec3 next, previous;
    if (i == 0) {
      next = spine[1];
      previous = closed ? spine[n - 2] : spine[0];
    } else if (i == n - 1) {
      next = closed ? spine[1] : spine[n - 1];
      previous = spine[n - 2];
    } else {
      next = spine[i + 1];
      previous = spine[i - 1];
    }
    y[i] = next - previous;
    const glm::dvec3 here = (i == n - 1 && closed) ? spine[0] : spine[i];
    if ((i == 0 || i == n - 1) && !closed) {
      z[i] = glm::dvec3(0.0);  // open ends take their neighbour's Z below
    } else {
      z[i] = glm::cross(next - here, previous - here);
    }
  }
  if (n > 2 && !closed) {
    z[0] = z[1];
    z[n - 1] = z[n - 2];
  }
  // Zero Y (coincident points) takes the nearest usable one; all zero means +Y.
  glm::dvec3 lastY(0, 1, 0);
  bool anyY = false;
  for (size_t i = 0; i < n; ++i) {
    if (glm::length(y[i]) > kTiny) {
      lastY = glm::normalize(y[i]);
      if (!anyY) {
        for (size_t k = 0; k < i; ++k) y[k] = lastY;
        anyY = true;
      }
    }
    y[i] = normalizedOr(y[i], lastY);
  }
  // Collinear spines have no Z anywhere: turn the Y=0 plane by the rotation taking +Y
  // to the spine's direction. Elsewhere, a zero Z repeats the previous one, and Z
  // flips to stay on the same side as the previous one.
  bool anyZ = false;
  for (const glm::dvec3& v : z) anyZ = anyZ || glm::length(v) > kTiny;
  std::vector<glm::dmat3> planes(n);
  if (!anyZ) {
    const glm::dvec3 axis = glm::cross(glm::dvec3(0, 1, 0), y[0]);
    const double angle = std::acos(std::clamp(y[0].y, -1.0, 1.0));
    const glm::dmat3 r = glm::length(axis) > kTiny ? rotationMatrix(glm::dvec4(axis, angle))
                         : y[0].y < 0             ? rotationMatrix(glm::dvec4(1, 0, 0, 3.141592653589793))
                                                  : glm::dmat3(1.0);
    for (size_t i = 0; i < n; ++i) planes[i] = r;
    return planes;
  }
  glm::dvec3 lastZ(0.0);
  for (size_t i = 0; i < n; ++i) {
    if (glm::length(z[i]) > kTiny) lastZ = glm::normalize(z[i]);
    if (glm::length(lastZ) == 0.0) {
      for (size_t k = i; k < n && glm::length(lastZ) == 0.0; ++k) {
        if (glm::length(z[k]) > kTiny) lastZ = glm::normalize(z[k]);
      }
    }
    glm::dvec3 zi = glm::length(z[i]) > kTiny ? glm::normalize(z[i]) : lastZ;
    if (i > 0 && glm::dot(zi, glm::dvec3(planes[i - 1][2])) < 0.0) zi = -zi;
    lastZ = zi;
    const glm::dvec3 xi = normalizedOr(glm::cross(y[i], zi), glm::dvec3(1, 0, 0));
    const glm::dvec3 zOrtho = glm::cross(xi, y[i]);
    planes[i] = glm::dmat3(xi, y[i], zOrtho);
  }
  return planes;
}

}  // namespace

Result<std::optional<Mesh>> buildExtrusion(const Node& node, const GeometryOptions& options, Diagnostics* diagnostics) {
  const std::vector<float>& spineFloats = getFloats(node, "spine");
  const std::vector<float>& sectionFloats = getFloats(node, "crossSection");
  const std::vector<float>& scaleFloats = getFloats(node, "scale");
  const std::vector<float>& orientationFloats = getFloats(node, "orientation");
  const size_t n = spineFloats.size() / 3, m = sectionFloats.size() / 2;
  if (n < 2 || m < 2) {
    if (diagnostics) diagnostics->note(node.where() + ": Extrusion with fewer than 2 spine or cross-section points draws nothing");
    return std::optional<Mesh>{};
  }
  if (n * m > kMaxExtrusionPoints) {
    return makeError(node.where() + ": Extrusion of " + std::to_string(n) + " x " + std::to_string(m) +
                     " points is larger than photowalk accepts (at most " + std::to_string(kMaxExtrusionPoints) +
                     " spine times cross-section points)");
  }
  std::vector<glm::dvec3> spine(n);
  for (size_t i = 0; i < n; ++i) spine[i] = {spineFloats[3 * i], spineFloats[3 * i + 1], spineFloats[3 * i + 2]};
  const std::vector<glm::dmat3> planes = crossSectionPlanes(spine);

  std::vector<glm::vec3> points(n * m);
  for (size_t i = 0; i < n; ++i) {
    // One scale / orientation for all spine points, or one each (missing ones repeat the last).
    const size_t si = std::min(i, scaleFloats.size() / 2 - (scaleFloats.size() >= 2 ? 1 : 0));
    const glm::dvec2 scale = scaleFloats.size() >= 2 ? glm::dvec2(scaleFloats[2 * si], scaleFloats[2 * si + 1])
                                                     : glm::dvec2(1.0);
    const size_t oi = std::min(i, orientationFloats.size() / 4 - (orientationFloats.size() >= 4 ? 1 : 0));
    const glm::dmat3 turn = orientationFloats.size() >= 4
                                ? rotationMatrix({orientationFloats[4 * oi], orientationFloats[4 * oi + 1],
                                                  orientationFloats[4 * oi + 2], orientationFloats[4 * oi + 3]})
                                : glm::dmat3(1.0);
    for (size_t j = 0; j < m; ++j) {
      const glm::dvec3 local(scale.x * sectionFloats[2 * j], 0.0, scale.y * sectionFloats[2 * j + 1]);
      points[i * m + j] = glm::vec3(spine[i] + planes[i] * (turn * local));
    }
  }

  PolygonSoup soup = surfaceSoup(node, points);
  // Texture coordinates (6.18.3): sides by arc length along the cross-section (s) and
  // the spine (t); caps by the cross-section's bounding box.
  std::vector<glm::vec2> tex;
  std::vector<uint32_t> texIndex;
  std::vector<double> sAt(m, 0.0), tAt(n, 0.0);
  for (size_t j = 1; j < m; ++j) {
    sAt[j] = sAt[j - 1] + std::hypot(sectionFloats[2 * j] - sectionFloats[2 * j - 2],
                                     sectionFloats[2 * j + 1] - sectionFloats[2 * j - 1]);
  }
  for (size_t i = 1; i < n; ++i) tAt[i] = tAt[i - 1] + glm::length(spine[i] - spine[i - 1]);
  for (size_t i = 0; i < n; ++i) {
    for (size_t j = 0; j < m; ++j) {
      tex.emplace_back(sAt[m - 1] > 0 ? sAt[j] / sAt[m - 1] : 0.0, tAt[n - 1] > 0 ? tAt[i] / tAt[n - 1] : 0.0);
    }
  }
  for (size_t i = 0; i + 1 < n; ++i) {
    for (size_t j = 0; j + 1 < m; ++j) {
      for (size_t k : {i * m + j, i * m + j + 1, (i + 1) * m + j + 1, (i + 1) * m + j}) {
        soup.coord.push_back(static_cast<uint32_t>(k));
        texIndex.push_back(static_cast<uint32_t>(k));
      }
      soup.addFace();
    }
  }
  const bool sectionClosed = sectionFloats[0] == sectionFloats[2 * m - 2] && sectionFloats[1] == sectionFloats[2 * m - 1];
  const size_t capCorners = sectionClosed ? m - 1 : m;
  float minX = sectionFloats[0], maxX = minX, minZ = sectionFloats[1], maxZ = minZ;
  for (size_t j = 0; j < m; ++j) {
    minX = std::min(minX, sectionFloats[2 * j]);
    maxX = std::max(maxX, sectionFloats[2 * j]);
    minZ = std::min(minZ, sectionFloats[2 * j + 1]);
    maxZ = std::max(maxZ, sectionFloats[2 * j + 1]);
  }
  const float capSize = std::max(maxX - minX, maxZ - minZ);
  const uint32_t capTex = static_cast<uint32_t>(tex.size());
  for (size_t j = 0; j < m; ++j) {
    tex.emplace_back(capSize > 0 ? (sectionFloats[2 * j] - minX) / capSize : 0.0f,
                     capSize > 0 ? (sectionFloats[2 * j + 1] - minZ) / capSize : 0.0f);
  }
  if (capCorners >= 3) {
    // The cross-section runs counter-clockwise seen from the spine's direction, so the
    // end cap keeps its order and the begin cap, facing back, reverses it.
    if (getBool(node, "beginCap")) {
      for (size_t j = capCorners; j-- > 0;) {
        soup.coord.push_back(static_cast<uint32_t>(j));
        texIndex.push_back(capTex + static_cast<uint32_t>(j));
      }
      soup.addFace();
    }
    if (getBool(node, "endCap")) {
      for (size_t j = 0; j < capCorners; ++j) {
        soup.coord.push_back(static_cast<uint32_t>((n - 1) * m + j));
        texIndex.push_back(capTex + static_cast<uint32_t>(j));
      }
      soup.addFace();
    }
  }
  if (options.texCoords) {
    soup.texCoords = tex;
    soup.texCoordIndex = std::move(texIndex);
  }
  return std::optional<Mesh>(buildPolygonMesh(soup));
}

}  // namespace pw::engine::vrml
