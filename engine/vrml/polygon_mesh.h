// Polygons with per-corner attribute indices (the shape of VRML97's IndexedFaceSet,
// ElevationGrid and Extrusion) to an indexed triangle mesh: crease-angle normals,
// triangulation of convex (fan) and non-convex (ear clipping) polygons, and one mesh
// vertex per distinct combination of attributes.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "engine/scene/scene.h"

namespace pw::engine::vrml {

inline constexpr uint32_t kNoIndex = 0xFFFFFFFFu;

struct PolygonSoup {
  std::span<const glm::vec3> points;
  // Corners of face f are [faceStart[f], faceStart[f + 1]); faceStart has faces+1 entries.
  std::vector<uint32_t> faceStart{0};
  std::vector<uint32_t> coord;  // per corner, indices into points (all valid)

  // Optional attributes: an array and a per-corner index into it (all valid), or an
  // empty index list for "none". Normals absent: generated from creaseAngle.
  std::span<const glm::vec3> normals;
  std::vector<uint32_t> normalIndex;
  std::span<const glm::vec2> texCoords;
  std::vector<uint32_t> texCoordIndex;
  std::span<const glm::vec3> colors;
  std::vector<uint32_t> colorIndex;

  bool ccw = true;      // corners run counter-clockwise seen from the front
  bool convex = true;   // false: triangulate by ear clipping
  bool solid = true;
  double creaseAngle = 0.0;  // radians; faces meeting at less than this are smoothed

  size_t faceCount() const { return faceStart.size() - 1; }
  void addFace() { faceStart.push_back(static_cast<uint32_t>(coord.size())); }
};

// Builds the triangle mesh. Faces with fewer than three corners are dropped.
Mesh buildPolygonMesh(const PolygonSoup& soup);

// Triangulates one simple polygon (ear clipping on its projection onto the plane
// most facing its normal). Appends index triples into `polygon` (0..n-1) to `out`,
// with the polygon's own winding. Self-intersecting input still gives n-2 triangles.
void triangulatePolygon(std::span<const glm::vec3> polygon, std::vector<uint32_t>& out);

// Newell's method: the polygon's normal scaled by twice its area.
glm::dvec3 newellNormal(std::span<const glm::vec3> points, std::span<const uint32_t> corners);

}  // namespace pw::engine::vrml
