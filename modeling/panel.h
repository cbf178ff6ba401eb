// Panels: the flat rectangles a corridor model is made of (floor, ceiling, walls),
// possibly with rectangular openings where one corridor opens into another.
#pragma once

#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "engine/scene/scene.h"

namespace pw::modeling {

// An axis-aligned rectangle in a panel's own (s, t) coordinates, metres.
struct Rect {
  double s0 = 0, t0 = 0, s1 = 0, t1 = 0;
  bool empty() const { return !(s1 > s0) || !(t1 > t0); }
};
Rect intersect(const Rect& a, const Rect& b);

// A rectangle in 3D: point(s, t) = origin + s * sAxis + t * tAxis, for (s, t) in
// `extent`. Its front (the side it is seen and lit from) faces cross(sAxis, tAxis).
struct Panel {
  glm::dvec3 origin{0.0};
  glm::dvec3 sAxis{1, 0, 0};
  glm::dvec3 tAxis{0, 1, 0};
  Rect extent;
  // The (s, t) rectangle whose corners get texture coordinates (0,0)..(1,1)
  // (VRML: t = 0 at the image's bottom). Unset: no texture coordinates.
  std::optional<Rect> textureRect;
  std::vector<Rect> openings;
  // Cells no longer than this (metres; 0: as few as the openings allow), so that a
  // renderer lighting per vertex sees the light fall off along a long wall.
  double maxCellM = 0;

  glm::dvec3 point(double s, double t) const { return origin + s * sAxis + t * tAxis; }
  glm::dvec3 normal() const { return glm::normalize(glm::cross(sAxis, tAxis)); }
};

// Triangles covering the panel minus its openings. The panel is cut along the
// openings' edges into a grid of cells (no T-junctions, so no cracks between cells);
// the cells inside an opening are left out. Texture coordinates, when the panel has
// a textureRect, are the affine map of (s, t): cutting never moves the texture.
// `color`, when given, is written as a per-vertex colour.
engine::Mesh panelMesh(const Panel& panel, const std::optional<glm::vec4>& color = std::nullopt);

}  // namespace pw::modeling
