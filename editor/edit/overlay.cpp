#include "editor/edit/overlay.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "metrology/distortion.h"

namespace pw::edit {
namespace {

using metrology::P1;
using metrology::P2;
using metrology::P3;
using metrology::P4;
using metrology::P5;
using metrology::P6;
using metrology::P7;
using metrology::P8;

ImVec2 im(const glm::dvec2& p) { return ImVec2(static_cast<float>(p.x), static_cast<float>(p.y)); }
ImU32 colour(const glm::u8vec4& c) { return IM_COL32(c.r, c.g, c.b, c.a); }
ImU32 withAlpha(const glm::u8vec4& c, int alpha) { return IM_COL32(c.r, c.g, c.b, alpha); }

const glm::u8vec4 kRecedingColour{255, 230, 80, 255};
const glm::u8vec4 kHorizonColour{255, 90, 210, 255};
const glm::u8vec4 kWallColour{210, 210, 210, 255};
const glm::u8vec4 kFittedColour{255, 255, 255, 255};

// The receding edges, near corner first (vanishing.h's order).
constexpr std::array<std::array<int, 2>, 4> kReceding{{{P7, P1}, {P8, P2}, {P5, P3}, {P6, P4}}};
// The other edges of the box: the far wall's and the near cross-section's.
struct Edge {
  int a, b;
};
constexpr std::array<Edge, 8> kCrossEdges{{{P1, P2}, {P3, P4}, {P1, P3}, {P2, P4}, {P5, P6}, {P7, P8}, {P5, P7}, {P6, P8}}};

// A line through `p` (window pixels) along `direction`, long enough to cross `area`.
void infiniteLine(ImDrawList* list, const glm::dvec2& p, glm::dvec2 direction, const WindowRect& area, ImU32 col,
                  float thickness) {
  if (glm::length(direction) < 1e-12) return;
  direction = glm::normalize(direction);
  const double reach = glm::length(area.size()) + glm::length(p - area.centre()) + 10;
  list->AddLine(im(p - reach * direction), im(p + reach * direction), col, thickness);
}

void textWithShadow(ImDrawList* list, const glm::dvec2& at, ImU32 col, const char* text) {
  list->AddText(im(at + glm::dvec2(1, 1)), IM_COL32(0, 0, 0, 220), text);
  list->AddText(im(at), col, text);
}

// A straight edge of the corridor from photo pixel a to b as the lens shows it: a
// straight line for a pinhole, else a polyline through the distortion (the edge is
// straight between the two corners' pinhole pixels).
void edgeThroughLens(ImDrawList* list, const Canvas& canvas, const metrology::Intrinsics& lens, const glm::dvec2& a,
                     const glm::dvec2& b, ImU32 col, float thickness, bool pinholeEnds = false) {
  if (lens.distortion.isNone()) {
    list->AddLine(im(canvas.toWindow(a)), im(canvas.toWindow(b)), col, thickness);
    return;
  }
  const std::optional<glm::dvec2> pa = pinholeEnds ? std::optional(a) : metrology::undistortPixel(lens, a);
  const std::optional<glm::dvec2> pb = pinholeEnds ? std::optional(b) : metrology::undistortPixel(lens, b);
  if (!pa || !pb) return;
  constexpr int kSteps = 32;
  std::array<ImVec2, kSteps + 1> points;
  for (int i = 0; i <= kSteps; ++i) {
    const glm::dvec2 p = *pa + (*pb - *pa) * (static_cast<double>(i) / kSteps);
    if (!metrology::insideFold(lens, p)) return;
    points[i] = im(canvas.toWindow(metrology::distortPixel(lens, p)));
  }
  list->AddPolyline(points.data(), kSteps + 1, col, 0, thickness);
}

// The shot's lens (its distortion none without one, or without a focal length).
metrology::Intrinsics lensOf(const metrology::Shot& shot) {
  metrology::Intrinsics lens;
  lens.focalPx = shot.focalPx;
  lens.principalPointPx = shot.principalPoint();
  if (shot.distortion && shot.focalPx > 0) lens.distortion = *shot.distortion;
  return lens;
}

// The colour an edge of the box is drawn in: the far wall's, the receding edges', a
// near edge's role, the walls' grey for a near vertical.
glm::u8vec4 edgeColour(int a, int b) {
  const CornerRole ra = cornerRole(a), rb = cornerRole(b);
  if (ra == CornerRole::kFarWall && rb == CornerRole::kFarWall) return roleColour(CornerRole::kFarWall);
  if (ra == CornerRole::kFarWall || rb == CornerRole::kFarWall) return kRecedingColour;
  return ra == rb ? roleColour(ra) : kWallColour;
}

void drawPlanes(ImDrawList* list, const Canvas& canvas, const metrology::Shot& shot) {
  static const std::array<glm::u8vec4, metrology::kPlaneCount> kFill = {
      roleColour(CornerRole::kFarWall), kWallColour, kWallColour, roleColour(CornerRole::kNearFloor),
      roleColour(CornerRole::kNearCeiling)};
  for (int plane = 0; plane < metrology::kPlaneCount; ++plane) {
    const auto& q = metrology::kPlaneCorners[plane];
    list->AddQuadFilled(im(canvas.toWindow(shot.cornersPx[q[0]])), im(canvas.toWindow(shot.cornersPx[q[1]])),
                        im(canvas.toWindow(shot.cornersPx[q[2]])), im(canvas.toWindow(shot.cornersPx[q[3]])),
                        withAlpha(kFill[plane], plane == 1 || plane == 2 ? 22 : 34));
  }
}

void drawHorizon(ImDrawList* list, const Canvas& canvas, const metrology::ImageLine& horizon) {
  const glm::dvec2 normal(horizon.x, horizon.y);
  if (glm::length(normal) < 1e-12) return;
  // The point of the line nearest the canvas's centre, in photo pixels.
  const glm::dvec2 centre = canvas.toPhoto(canvas.area().centre());
  const double distance = (glm::dot(normal, centre) + horizon.z) / glm::dot(normal, normal);
  const glm::dvec2 foot = centre - distance * normal;
  const glm::dvec2 direction(-normal.y, normal.x);
  infiniteLine(list, canvas.toWindow(foot), direction, canvas.area(), withAlpha(kHorizonColour, 200), 1.5f);
  const glm::dvec2 labelAt = canvas.toWindow(foot) + glm::dvec2(0, -16);
  if (canvas.area().contains(labelAt)) textWithShadow(list, labelAt, colour(kHorizonColour), "horizon");
}

void drawFittedBox(ImDrawList* list, const Canvas& canvas, const metrology::Measurement& m) {
  const ImU32 col = withAlpha(kFittedColour, 110);
  const auto w = [&](int k) { return im(canvas.toWindow(m.reprojectedPx[k])); };
  const auto edge = [&](int a, int b) { edgeThroughLens(list, canvas, m.camera, m.reprojectedPx[a], m.reprojectedPx[b], col, 1.0f); };
  for (const auto& [a, b] : kReceding) edge(a, b);
  for (const Edge& e : kCrossEdges) edge(e.a, e.b);
  for (int k = 0; k < metrology::kCornerCount; ++k) {
    const ImVec2 p = w(k);
    list->AddLine({p.x - 3, p.y - 3}, {p.x + 4, p.y + 4}, col, 1.0f);
    list->AddLine({p.x - 3, p.y + 3}, {p.x + 4, p.y - 4}, col, 1.0f);
  }
}

}  // namespace

CornerRole cornerRole(int corner) {
  if (corner == P5 || corner == P6) return CornerRole::kNearFloor;
  if (corner == P7 || corner == P8) return CornerRole::kNearCeiling;
  return CornerRole::kFarWall;
}

glm::u8vec4 roleColour(CornerRole role) {
  switch (role) {
    case CornerRole::kNearFloor: return {70, 220, 90, 255};
    case CornerRole::kNearCeiling: return {70, 180, 255, 255};
    case CornerRole::kFarWall: break;
  }
  return {255, 150, 40, 255};
}

std::array<int, 3> cornerNeighbours(int corner) {
  static constexpr std::array<std::array<int, 3>, metrology::kCornerCount> kNeighbours{{
      {P2, P3, P7}, {P1, P4, P8}, {P4, P1, P5}, {P3, P2, P6}, {P6, P7, P3}, {P5, P8, P4}, {P8, P5, P1}, {P7, P6, P2}}};
  return kNeighbours[std::clamp(corner, 0, metrology::kCornerCount - 1)];
}

int handleAt(const Canvas& canvas, const metrology::Shot& shot, const glm::dvec2& windowPx, double radiusPx) {
  int best = -1;
  double bestDistance = radiusPx;
  for (int k = 0; k < metrology::kCornerCount; ++k) {
    const double d = glm::length(canvas.toWindow(shot.cornersPx[k]) - windowPx);
    if (d <= bestDistance) {
      bestDistance = d;
      best = k;
    }
  }
  return best;
}

void drawOverlay(ImDrawList* list, const OverlayInput& in) {
  const Canvas& canvas = *in.canvas;
  const metrology::Shot& shot = *in.shot;
  const auto w = [&](int k) { return canvas.toWindow(shot.cornersPx[k]); };

  drawPlanes(list, canvas, shot);
  if (in.measurement) drawHorizon(list, canvas, in.measurement->horizon);
  else if (in.vanishing) drawHorizon(list, canvas, in.vanishing->horizon);

  // The receding edges, and beyond the far corners on to the vanishing point. Through a
  // distorting lens the edges are curves in the photo (straight in the world), and the
  // vanishing point is the measurement's, in the undistorted image.
  const metrology::Intrinsics lens = lensOf(shot);
  const bool distorted = !lens.distortion.isNone();
  const metrology::VanishingPoint* vp =
      distorted ? (in.measurement ? &in.measurement->vanishing.corridor : nullptr) : (in.vanishing ? &in.vanishing->corridor : nullptr);
  for (const auto& [nearCorner, farCorner] : kReceding) {
    edgeThroughLens(list, canvas, lens, shot.cornersPx[nearCorner], shot.cornersPx[farCorner], colour(kRecedingColour), 2.0f);
    if (vp && vp->finite && !distorted) {
      list->AddLine(im(w(farCorner)), im(canvas.toWindow(vp->px)), withAlpha(kRecedingColour, 150), 1.0f);
    } else if (vp && vp->finite) {
      if (const auto far = metrology::undistortPixel(lens, shot.cornersPx[farCorner])) {
        edgeThroughLens(list, canvas, lens, *far, vp->px, withAlpha(kRecedingColour, 150), 1.0f, true);
      }
    }
  }
  if (vp && vp->finite) {
    const glm::dvec2 p = canvas.toWindow(distorted ? metrology::distortPixel(lens, vp->px) : vp->px);
    list->AddCircle(im(p), 5.0f, colour(kRecedingColour), 16, 1.5f);
  }
  for (const Edge& e : kCrossEdges) {
    edgeThroughLens(list, canvas, lens, shot.cornersPx[e.a], shot.cornersPx[e.b], colour(edgeColour(e.a, e.b)), 2.0f);
  }
  if (in.measurement) drawFittedBox(list, canvas, *in.measurement);

  for (int k = 0; k < metrology::kCornerCount; ++k) {
    const glm::dvec2 p = w(k);
    const ImU32 col = colour(roleColour(cornerRole(k)));
    if (k == in.selected) list->AddCircle(im(p), 10.0f, IM_COL32(255, 255, 255, 255), 24, 2.0f);
    list->AddCircleFilled(im(p), 5.0f, col, 16);
    list->AddCircle(im(p), 5.5f, IM_COL32(0, 0, 0, 200), 16, 1.5f);
    char label[32];
    if (in.confidence[k]) {
      std::snprintf(label, sizeof label, "%s %.2f", metrology::cornerName(k), *in.confidence[k]);
    } else {
      std::snprintf(label, sizeof label, "%s", metrology::cornerName(k));
    }
    textWithShadow(list, p + glm::dvec2(9, -20), col, label);
  }
}

Loupe placeLoupe(const Canvas& canvas, const glm::dvec2& cornerPx, int corner, const glm::dvec2& besidePx) {
  constexpr double kGapPx = 28;
  const WindowRect& area = canvas.area();
  Loupe loupe;
  loupe.corner = corner;
  glm::dvec2 at = besidePx + glm::dvec2(kGapPx);
  if (at.x + Loupe::kSizePx > area.max.x) at.x = besidePx.x - kGapPx - Loupe::kSizePx;
  if (at.y + Loupe::kSizePx > area.max.y) at.y = besidePx.y - kGapPx - Loupe::kSizePx;
  at = glm::clamp(at, area.min, glm::max(area.min, area.max - glm::dvec2(Loupe::kSizePx)));
  at = glm::floor(at);  // whole pixels: the view's rectangle and the overlay's agree
  loupe.rect = {at, at + glm::dvec2(Loupe::kSizePx)};
  loupe.transform.scale = std::clamp(std::round(4.0 * canvas.scale()), Loupe::kMinScale, Loupe::kMaxScale);
  loupe.transform.offset = loupe.centre() - loupe.transform.scale * cornerPx;
  return loupe;
}

void drawLoupe(ImDrawList* list, const Loupe& loupe, const metrology::Shot& shot) {
  const ImVec2 min = im(loupe.rect.min), max = im(loupe.rect.max);
  list->PushClipRect(min, max, true);
  const glm::dvec2 c = loupe.centre();
  const glm::dvec2 cornerPx = shot.cornersPx[loupe.corner];
  for (int n : cornerNeighbours(loupe.corner)) {
    const glm::dvec2 direction = shot.cornersPx[n] - cornerPx;
    const ImU32 col = colour(edgeColour(loupe.corner, n));
    infiniteLine(list, c, direction, loupe.rect, col, 1.5f);
  }
  // The crosshair: the corner's exact position, with a gap so the pixel stays visible.
  const float gap = static_cast<float>(0.6 * loupe.transform.scale) + 2.0f;
  const ImU32 white = IM_COL32(255, 255, 255, 230), dark = IM_COL32(0, 0, 0, 200);
  const ImVec2 centre = im(c);
  for (const ImU32 col : {dark, white}) {
    const float width = col == dark ? 3.0f : 1.0f;
    list->AddLine({min.x, centre.y}, {centre.x - gap, centre.y}, col, width);
    list->AddLine({centre.x + gap, centre.y}, {max.x, centre.y}, col, width);
    list->AddLine({centre.x, min.y}, {centre.x, centre.y - gap}, col, width);
    list->AddLine({centre.x, centre.y + gap}, {centre.x, max.y}, col, width);
  }
  list->PopClipRect();
  list->AddRect({min.x - 1, min.y - 1}, {max.x + 1, max.y + 1}, IM_COL32(255, 255, 255, 255), 0.0f, 0, 2.0f);
  char label[48];
  std::snprintf(label, sizeof label, "%s  %.0fx", metrology::cornerName(loupe.corner), loupe.transform.scale);
  textWithShadow(list, glm::dvec2(min.x + 4, min.y + 3), IM_COL32(255, 255, 255, 255), label);
}

}  // namespace pw::edit
