#include "editor/edit/handle_warnings.h"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numeric>

#include "editor/edit/canvas.h"
#include "editor/edit/warnings.h"
#include "metrology/shot_check.h"
#include "metrology/vanishing.h"

namespace pw::edit {
namespace {

using metrology::kCornerCount;
using metrology::kPlaneCorners;
using metrology::kPlaneCount;
using metrology::Plane;

double cross(const glm::dvec2& a, const glm::dvec2& b) { return a.x * b.y - a.y * b.x; }
bool finite(const glm::dvec2& p) { return std::isfinite(p.x) && std::isfinite(p.y); }
bool isNear(int corner) { return corner >= metrology::P5; }

std::string spokenPlane(int plane) {
  std::string name = metrology::planeName(static_cast<Plane>(plane));
  std::replace(name.begin(), name.end(), '_', ' ');
  return name;
}

std::string quadName(int plane) {
  const auto& q = kPlaneCorners[plane];
  std::string name;
  for (int k : q) name += (name.empty() ? "" : "-") + std::string(metrology::cornerName(k));
  return name;
}

std::string format(const char* fmt, auto... args) {
  char line[320];
  std::snprintf(line, sizeof line, fmt, args...);
  return line;
}

// The measured dimension a plane's shape fixes, and its relative uncertainty: the far
// wall fixes the width and height (the worse is named), every other plane the length
// (its near and far edges give the depth).
std::pair<std::string, double> affectedDimension(int plane, const metrology::Measurement* m) {
  if (!m) return {"", 0};
  const auto relative = [](double sigma, double value) { return value > 0 ? sigma / value : 0.0; };
  const metrology::Dimensions sigma = metrology::cornerSigma(*m);  // what moving corners changes
  if (plane == static_cast<int>(Plane::kFarWall)) {
    const double w = relative(sigma.widthM, m->size.widthM), h = relative(sigma.heightM, m->size.heightM);
    return w >= h ? std::pair<std::string, double>{"width", w} : std::pair<std::string, double>{"height", h};
  }
  return {"length", relative(sigma.lengthM, m->size.lengthM)};
}

// Corners at one point (closer than kCoincidentPx), grouped: one warning per group.
void coincident(const metrology::Shot& shot, std::vector<HandleWarning>& out, std::array<bool, kCornerCount>& inGroup) {
  std::array<int, kCornerCount> group;
  std::iota(group.begin(), group.end(), 0);
  const auto root = [&](int k) {
    while (group[k] != k) k = group[k];
    return k;
  };
  for (int a = 0; a < kCornerCount; ++a) {
    for (int b = a + 1; b < kCornerCount; ++b) {
      if (glm::length(shot.cornersPx[a] - shot.cornersPx[b]) < kCoincidentPx) group[root(b)] = root(a);
    }
  }
  for (int r = 0; r < kCornerCount; ++r) {
    HandleWarning w;
    for (int k = 0; k < kCornerCount; ++k) {
      if (root(k) == r) w.handles.push_back(k);
    }
    if (w.handles.size() < 2) continue;
    std::string names;
    for (int k : w.handles) {
      names += (names.empty() ? "" : " = ") + std::string(metrology::cornerName(k));
      inGroup[k] = true;
    }
    w.label = names;
    w.text = names + " lie on one point: drag them apart, each onto its own corner of the corridor";
    w.blocking = true;
    out.push_back(std::move(w));
  }
}

// Three corners of a plane on (or almost on) one line. The corner named is the odd
// one out: a near corner on a far-wall line (or the reverse), else the middle one.
// The corner moved last, when one of them is it, is the one to move back.
void collinear(const metrology::Shot& shot, const metrology::Measurement* m, const std::array<bool, kCornerCount>& inGroup,
               int moved, std::vector<HandleWarning>& out) {
  std::array<std::array<bool, kCornerCount>, kCornerCount> said{};  // (corner, line's first corner)
  for (int plane = 0; plane < kPlaneCount; ++plane) {
    const auto& q = kPlaneCorners[plane];
    for (int i = 0; i < 4; ++i) {
      const std::array<int, 3> t = {q[i], q[(i + 1) % 4], q[(i + 2) % 4]};
      if (inGroup[t[0]] || inGroup[t[1]] || inGroup[t[2]]) continue;
      const glm::dvec2 a = shot.cornersPx[t[0]], b = shot.cornersPx[t[1]], c = shot.cornersPx[t[2]];
      const glm::dvec2 e1 = b - a, e2 = c - b;
      const double sine = std::abs(cross(e1, e2)) / (glm::length(e1) * glm::length(e2));
      if (!(sine < std::sin(glm::radians(kAlmostCollinearDeg)))) continue;
      const int nearCount = isNear(t[0]) + isNear(t[1]) + isNear(t[2]);
      int odd = t[1];
      if (std::find(t.begin(), t.end(), moved) != t.end()) {
        odd = moved;
      } else if (nearCount == 1 || nearCount == 2) {
        for (int k : t) {
          if ((nearCount == 1) == isNear(k)) odd = k;
        }
      }
      std::array<int, 2> line{};
      int n = 0;
      for (int k : t) {
        if (k != odd) line[n++] = k;
      }
      if (line[0] > line[1]) std::swap(line[0], line[1]);
      if (said[odd][line[0]]) continue;
      said[odd][line[0]] = true;
      const glm::dvec2 p0 = shot.cornersPx[line[0]], p1 = shot.cornersPx[line[1]], p = shot.cornersPx[odd];
      const double distancePx = std::abs(cross(p1 - p0, p - p0)) / glm::length(p1 - p0);
      const bool on = sine < std::sin(glm::radians(kCollinearDeg));
      const auto [dimension, relative] = affectedDimension(plane, m);
      if (!on && m && !(relative > kUncertainFraction)) continue;  // almost, but the measurement holds
      HandleWarning w;
      w.handles = {odd};
      w.related = {line[0], line[1]};
      const char* oddName = metrology::cornerName(odd);
      const char* aName = metrology::cornerName(line[0]);
      const char* bName = metrology::cornerName(line[1]);
      w.label = format("on %s-%s", aName, bName);
      const std::string where = format("%s is %son the line %s-%s (%.1f px from it)", oddName, on ? "" : "almost ",
                                       aName, bName, distancePx);
      if (on) {
        w.blocking = true;
        w.text = where + ": the " + spokenPlane(plane) + " cannot be measured; move " + oddName + " off that line";
      } else if (m) {
        w.dimension = dimension;
        w.text = where + format(": the %s is uncertain to +-%.0f%%; place %s to the pixel, or use a photo where it lies "
                                "farther from that line",
                                dimension.c_str(), 100.0 * relative, oddName);
      } else {
        w.text = where + ": the " + spokenPlane(plane) + " is nearly flat in the photo; move " + oddName +
                 " away from that line";
      }
      out.push_back(std::move(w));
    }
  }
}

bool segmentsCross(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c, const glm::dvec2& d) {
  const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a), d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
  return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0)) && d1 != 0 && d2 != 0 && d3 != 0 && d4 != 0;
}

// A quad that crosses itself: its two opposite edges that cross, and the corners to
// swap; or, when the corner moved last is one of the quad's, that corner to move back.
void crossed(const metrology::Shot& shot, const std::array<bool, kCornerCount>& inGroup, int moved,
             std::vector<HandleWarning>& out) {
  for (int plane = 0; plane < kPlaneCount; ++plane) {
    const auto& q = kPlaneCorners[plane];
    if (inGroup[q[0]] || inGroup[q[1]] || inGroup[q[2]] || inGroup[q[3]]) continue;
    const auto c = [&](int i) { return shot.cornersPx[q[i % 4]]; };
    for (int i = 0; i < 2; ++i) {
      // Edges (i, i+1) and (i+2, i+3) cross: swapping corners i+1 and i+2 uncrosses it.
      if (!segmentsCross(c(i), c(i + 1), c(i + 2), c(i + 3))) continue;
      HandleWarning w;
      const int a = q[(i + 1) % 4], b = q[(i + 2) % 4];
      w.label = "crossed";
      w.blocking = true;
      if (std::find(q.begin(), q.end(), moved) != q.end()) {
        const char* name = metrology::cornerName(moved);
        w.handles = {moved};
        w.text = std::string(name) + " has crossed the " + spokenPlane(plane) + " quad " + quadName(plane) +
                 " over itself: drag " + name + " back onto its own corner";
      } else {
        w.handles = {a, b};
        w.text = "the " + spokenPlane(plane) + " quad " + quadName(plane) + " crosses itself: " + metrology::cornerName(a) +
                 " and " + metrology::cornerName(b) + " look swapped; drag each onto its own corner";
      }
      out.push_back(std::move(w));
      break;
    }
  }
}

// Where the receding edges meet, from the near corners' side: behind the camera when
// the far corners are not between the near ones and that point.
void vanishingBehind(const metrology::Shot& shot, std::vector<HandleWarning>& out) {
  static constexpr std::array<std::array<int, 2>, 4> kReceding{
      {{metrology::P7, metrology::P1}, {metrology::P8, metrology::P2}, {metrology::P5, metrology::P3},
       {metrology::P6, metrology::P4}}};
  std::array<metrology::Segment, 4> segments;
  for (int i = 0; i < 4; ++i) segments[i] = {shot.cornersPx[kReceding[i][0]], shot.cornersPx[kReceding[i][1]]};
  auto vp = metrology::fitVanishingPoint(segments);
  if (!vp || !vp->finite || !finite(vp->px)) return;
  int behind = 0;
  for (const auto& [nearCorner, farCorner] : kReceding) {
    const glm::dvec2 d = shot.cornersPx[farCorner] - shot.cornersPx[nearCorner];
    if (glm::dot(d, d) > 0 && glm::dot(vp->px - shot.cornersPx[nearCorner], d) / glm::dot(d, d) <= 0) ++behind;
  }
  if (behind < 3) return;
  HandleWarning w;
  w.handles = {metrology::P1, metrology::P2, metrology::P3, metrology::P4};
  w.label = "VP behind";
  w.blocking = true;
  w.text = format("the vanishing point (%.0f, %.0f) is behind the camera: the receding edges meet beyond the near corners; "
                  "P1..P4 are the far wall's corners (the smaller rectangle), P5..P8 the near end's",
                  vp->px.x, vp->px.y);
  out.push_back(std::move(w));
}

}  // namespace

std::vector<HandleWarning> handleWarnings(const metrology::Shot& shot, const metrology::Measurement* measurement,
                                          int moved) {
  std::vector<HandleWarning> out;
  for (int k = 0; k < kCornerCount; ++k) {
    if (!finite(shot.cornersPx[k])) {
      out.push_back({{k}, "not a number", std::string(metrology::cornerName(k)) + " is not a finite number: drag it "
                                                                                   "onto its corner",
                     true, ""});
    }
  }
  if (!out.empty()) return out;

  std::array<bool, kCornerCount> inGroup{};
  coincident(shot, out, inGroup);
  if (moved < 0 || moved >= kCornerCount || inGroup[moved]) moved = -1;
  crossed(shot, inGroup, moved, out);
  collinear(shot, measurement, inGroup, moved, out);
  vanishingBehind(shot, out);

  // What metrology's check refuses and nothing above names (corners in the wrong
  // order: a quad that runs anticlockwise), on the corners of the planes concerned.
  const bool blocked = std::any_of(out.begin(), out.end(), [](const HandleWarning& w) { return w.blocking; });
  if (!blocked) {
    if (Status check = metrology::checkShot(shot); !check) {
      HandleWarning w;
      w.label = "order?";
      w.blocking = true;
      w.text = check.message();
      for (int plane = 0; plane < kPlaneCount; ++plane) {
        const auto& q = kPlaneCorners[plane];
        int positive = 0;
        for (int i = 0; i < 4; ++i) {
          const glm::dvec2 a = shot.cornersPx[q[i]], b = shot.cornersPx[q[(i + 1) % 4]], c = shot.cornersPx[q[(i + 2) % 4]];
          positive += cross(b - a, c - b) > 0 ? 1 : 0;
        }
        if (positive == 4) continue;  // clockwise, as it should
        for (int k : q) {
          if (std::find(w.handles.begin(), w.handles.end(), k) == w.handles.end()) w.handles.push_back(k);
        }
      }
      if (std::find(w.handles.begin(), w.handles.end(), moved) != w.handles.end()) {
        const char* name = metrology::cornerName(moved);
        w.handles = {moved};
        w.text = std::string(name) + " moved: " + w.text + "; drag " + name + " back onto its own corner";
      }
      // Checks on the camera rather than the corners have no handle: the panel says them.
      if (!w.handles.empty()) out.push_back(std::move(w));
    }
  }

  const glm::dvec2 pp = shot.principalPoint();
  if (!finite(pp)) {
    out.push_back({{kPrincipalPointHandle}, "not a number", "the principal point is not a finite number: reset it to "
                                                            "the centre in the Camera panel",
                   true, ""});
  } else if (pp.x < -0.5 || pp.y < -0.5 || pp.x > shot.imageWidth - 0.5 || pp.y > shot.imageHeight - 0.5) {
    out.push_back({{kPrincipalPointHandle},
                   "outside",
                   format("the principal point (%.1f, %.1f) is outside the photo: only a cropped or shifted photo "
                          "has it there; Reset to centre in the Camera panel puts it back",
                          pp.x, pp.y),
                   false, ""});
  }
  return out;
}

void drawHandleWarnings(ImDrawList* list, const Canvas& canvas, const metrology::Shot& shot,
                        const std::vector<HandleWarning>& warnings) {
  std::array<bool, kCornerCount + 1> drawn{};
  for (const HandleWarning& w : warnings) {
    const ImU32 ring = w.blocking ? IM_COL32(255, 70, 60, 255) : IM_COL32(255, 190, 40, 255);
    for (const int h : w.handles) {
      if (h < 0 || h > kCornerCount || drawn[h]) continue;
      const glm::dvec2 photoPx = h == kPrincipalPointHandle ? shot.principalPoint() : shot.cornersPx[h];
      if (!finite(photoPx)) continue;
      drawn[h] = true;
      const glm::dvec2 p = canvas.toWindow(photoPx);
      const ImVec2 at(float(p.x), float(p.y));
      list->AddCircle(at, 13.0f, IM_COL32(0, 0, 0, 200), 24, 4.0f);
      list->AddCircle(at, 13.0f, ring, 24, 2.5f);
      const ImVec2 labelAt(at.x + 10.0f, at.y + 4.0f);
      const ImVec2 size = ImGui::CalcTextSize(w.label.c_str());
      list->AddRectFilled({labelAt.x - 2, labelAt.y - 1}, {labelAt.x + size.x + 2, labelAt.y + size.y + 1},
                          IM_COL32(0, 0, 0, 170), 2.0f);
      list->AddText(labelAt, ring, w.label.c_str());
    }
    // The line's corners: a thin ring, so that the label says which one to move.
    for (const int h : w.related) {
      if (h < 0 || h >= kCornerCount || !finite(shot.cornersPx[h])) continue;
      const glm::dvec2 p = canvas.toWindow(shot.cornersPx[h]);
      list->AddCircle(ImVec2(float(p.x), float(p.y)), 11.0f, ring, 24, 1.0f);
    }
  }
}

}  // namespace pw::edit
