// The editor's measure tool (issue 25, part 2): M, then two clicks on the photo measure
// an object in it, in the corridor's frame (metrology/object_measure.h). Each point lies
// on the surface of the box the photo shows where it is clicked (floor, ceiling, a side
// wall, the far wall: surfaceAt), so that
//   - two clicks give the distance between them (a door's width at its sill on the
//     floor, a picture's width on its wall);
//   - with Shift held at the second click, the second point is on the vertical through
//     the first (drawn while measuring): its height above it (a person's head above
//     their feet, a door's top above its sill, a window's top above its sill on a wall).
// While the second point is being placed the value and its ± follow the cursor. Each
// measurement goes into the shot (its points "A1", "B1", ... and the measurement), one
// undo step, listed in the panel's Measurements with a delete button, drawn on the photo
// and written in the trace's "objects".
#include <imgui.h>

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

#include "editor/app/shell.h"
#include "editor/edit/edit_mode.h"
#include "editor/edit/panel_style.h"
#include "metrology/input_sigma.h"

namespace pw::edit {
namespace {

using metrology::ImagePoint;
using metrology::ObjectMeasure;
using metrology::ObjectQuantity;
using metrology::PointSurface;
using metrology::Shot;
using nlohmann::ordered_json;

const ImU32 kMeasureColour = IM_COL32(255, 210, 60, 255);
const ImU32 kShadow = IM_COL32(0, 0, 0, 210);
constexpr double kPointSigmaPx = 1.0;  // a click's placement, as measure's --sigma-point-px default

ImVec2 im(const glm::dvec2& p) { return {float(p.x), float(p.y)}; }

// The first n with no point named A<n> or B<n>.
int freeIndex(const Shot& shot) {
  for (int n = 1;; ++n) {
    const std::string a = "A" + std::to_string(n), b = "B" + std::to_string(n);
    if (std::none_of(shot.points.begin(), shot.points.end(), [&](const ImagePoint& p) { return p.name == a || p.name == b; })) {
      return n;
    }
  }
}

// The surface of the corridor's box the photo shows at `px`: the far wall inside its
// four corners, else the floor, the ceiling or a side wall, each the quad between the far
// wall and the near section carried on outwards from the vanishing point to the photo's
// edges. Pixels of objects in front of the surfaces are taken as the surface behind.
PointSurface surfaceAt(const Shot& shot, glm::dvec2 px) {
  const auto& c = shot.cornersPx;
  const auto inside = [&](std::array<glm::dvec2, 4> q) {
    double sign = 0;
    for (int i = 0; i < 4; ++i) {
      const glm::dvec2 a = q[i], b = q[(i + 1) % 4];
      const double cross = (b.x - a.x) * (px.y - a.y) - (b.y - a.y) * (px.x - a.x);
      if (cross == 0) continue;
      if (sign == 0) sign = cross;
      else if ((cross > 0) != (sign > 0)) return false;
    }
    return true;
  };
  using metrology::P1, metrology::P2, metrology::P3, metrology::P4, metrology::P5, metrology::P6, metrology::P7,
      metrology::P8;
  if (inside({c[P1], c[P2], c[P4], c[P3]})) return PointSurface::kFarWall;
  // The near corners carried far out along their boundaries (from the far corners).
  const auto out = [&](int nearCorner, int farCorner) { return c[farCorner] + 1000.0 * (c[nearCorner] - c[farCorner]); };
  if (inside({c[P3], c[P4], out(P6, P4), out(P5, P3)})) return PointSurface::kFloor;
  if (inside({c[P1], c[P2], out(P8, P2), out(P7, P1)})) return PointSurface::kCeiling;
  if (inside({c[P1], c[P3], out(P5, P3), out(P7, P1)})) return PointSurface::kLeftWall;
  if (inside({c[P2], c[P4], out(P6, P4), out(P8, P2)})) return PointSurface::kRightWall;
  return PointSurface::kFloor;
}

const ImagePoint* pointNamed(const Shot& shot, const std::string& name) {
  for (const ImagePoint& p : shot.points)
    if (p.name == name) return &p;
  return nullptr;
}

// A click snaps within this many screen pixels (as a dragged corner does): to the
// strongest corner there (two edges meeting: a door's or a picture's corner, a foot on
// the floor's line), placed to a tenth of a pixel; else to the nearest edge.
constexpr double kMeasureSnapScreenPx = 8;

std::optional<glm::dvec2> snapToPhoto(const cv::Mat& photo, glm::dvec2 px, double reachPx) {
  if (photo.empty()) return std::nullopt;
  const int r = static_cast<int>(std::ceil(reachPx)) + 4;
  const cv::Rect roi = cv::Rect(static_cast<int>(std::floor(px.x)) - r, static_cast<int>(std::floor(px.y)) - r, 2 * r + 1, 2 * r + 1) &
                       cv::Rect(0, 0, photo.cols, photo.rows);
  if (roi.width < 8 || roi.height < 8) return std::nullopt;
  cv::Mat grey;
  cv::cvtColor(photo(roi), grey, cv::COLOR_BGR2GRAY);
  const glm::dvec2 origin(roi.x, roi.y);
  std::vector<cv::Point2f> corners;
  cv::goodFeaturesToTrack(grey, corners, 8, 0.05, 2.0);
  std::optional<glm::dvec2> best;
  double bestDistance = reachPx;
  for (const cv::Point2f& c : corners) {
    const glm::dvec2 at = origin + glm::dvec2(c.x, c.y);
    if (glm::length(at - px) <= bestDistance) best = at, bestDistance = glm::length(at - px);
  }
  if (best) {
    std::vector<cv::Point2f> refined{cv::Point2f(float(best->x - origin.x), float(best->y - origin.y))};
    cv::cornerSubPix(grey, refined, cv::Size(3, 3), cv::Size(-1, -1),
                     cv::TermCriteria(cv::TermCriteria::EPS + cv::TermCriteria::COUNT, 20, 0.01));
    const glm::dvec2 at = origin + glm::dvec2(refined[0].x, refined[0].y);
    return glm::length(at - *best) <= 2.0 ? at : *best;
  }
  cv::Mat edges;
  cv::Canny(grey, edges, 40, 120);
  for (int y = 0; y < edges.rows; ++y) {
    for (int x = 0; x < edges.cols; ++x) {
      if (!edges.at<uchar>(y, x)) continue;
      const glm::dvec2 at = origin + glm::dvec2(x, y);
      if (glm::length(at - px) <= bestDistance) best = at, bestDistance = glm::length(at - px);
    }
  }
  return best;
}

void labelAt(ImDrawList* list, glm::dvec2 at, const std::string& text) { ui::labelOnPlate(list, im(at), text, kMeasureColour); }

}  // namespace

// The shot with the measurement from `from` to `to` (image pixels) added: floor points,
// or the second above the first for a height.
Shot EditMode::withObjectMeasure(const Shot& shot, glm::dvec2 from, glm::dvec2 to, bool height) const {
  Shot after = shot;
  const int n = freeIndex(shot);
  const std::string a = "A" + std::to_string(n), b = "B" + std::to_string(n);
  after.points.push_back({a, from, {surfaceAt(shot, from), ""}});
  after.points.push_back({b, to, height ? metrology::PointOn{PointSurface::kAbove, a} : metrology::PointOn{surfaceAt(shot, to), ""}});
  after.measurements.push_back({height ? ObjectQuantity::kHeight : ObjectQuantity::kDistance, a, b, ""});
  return after;
}

// The image of the vertical through the point at `px` (on the surface the photo shows
// there): that point and the one a metre above it, or nullopt when the corners do not
// measure or its ray misses the surface.
std::optional<std::pair<glm::dvec2, glm::dvec2>> EditMode::verticalThrough(glm::dvec2 px) const {
  if (!live_.measurement) return std::nullopt;
  auto located = metrology::locatePoints(*live_.measurement, {{"foot", px, {surfaceAt(doc_->shot(), px), ""}}});
  if (!located || located->empty()) return std::nullopt;
  const glm::dvec3 foot = located->front().m;
  const glm::dvec3 a = metrology::projectWithMeasurement(*live_.measurement, foot);
  const glm::dvec3 b = metrology::projectWithMeasurement(*live_.measurement, foot + glm::dvec3(0, 1, 0));
  const glm::dvec2 pa(a.x, a.y), pb(b.x, b.y);
  if (!(std::isfinite(pa.x) && std::isfinite(pa.y) && std::isfinite(pb.x) && std::isfinite(pb.y)) || glm::length(pb - pa) < 1e-6) {
    return std::nullopt;
  }
  return std::pair{pa, pb};
}

// The measurements of `shot` (its points' and the ones asked), with their ±, or why not.
Result<metrology::PointMeasurement> EditMode::measureObjects(const Shot& shot) const {
  if (!live_.measurement) return makeError(live_.error.empty() ? "the corners cannot be measured" : live_.error);
  const metrology::MeasureOptions options = metrology::withInputSigmas({}, shot, doc_->inputOrigins());
  return metrology::measurePoints(shot, options, *live_.measurement, shot.points, shot.measurements, kPointSigmaPx);
}

void EditMode::remeasureObjects() {
  objects_.reset();
  objectsError_.clear();
  if (!doc_ || doc_->shot().measurements.empty()) return;
  auto measured = measureObjects(doc_->shot());
  if (measured) objects_ = std::move(*measured);
  else objectsError_ = measured.message();
}

void EditMode::setMeasuring(app::Shell& shell, bool on) {
  measuring_ = on && doc_.has_value();
  measureFrom_.reset();
  if (measuring_) {
    pickingReference_ = false;
    shell.showMessage("measure: click a point (on the floor, a wall or the ceiling), then the second (Shift: a height above the first); Esc: stop");
  }
}

// Where a point at `px` (photo pixels) goes: snapped to the photo's corner or edge within
// reach, unless Alt is held.
glm::dvec2 EditMode::measureSnap(glm::dvec2 px) const {
  if (!doc_ || altHeld()) return px;
  const double reach = std::clamp(kMeasureSnapScreenPx / canvas_.scale(), 1.0, 25.0);
  return snapToPhoto(doc_->photo(), px, reach).value_or(px);
}

bool EditMode::measureClick(app::Shell& shell) {
  if (!measuring_ || !doc_) return false;
  const glm::dvec2 at = measureSnap(canvas_.toPhoto(cursorPx_));
  if (!measureFrom_) {
    if (!live_.measurement) {
      shell.showMessage("measure: the corners do not measure yet: " + live_.error);
      return true;
    }
    auto located = metrology::locatePoints(*live_.measurement, {{"a", at, {surfaceAt(doc_->shot(), at), ""}}});
    if (!located) {
      shell.showMessage("measure: " + located.message());
      return true;
    }
    measureFrom_ = at;
    return true;
  }
  const std::optional<glm::dvec2> to = measuringNow().target;
  if (!to) return true;
  const bool height = shiftHeld();
  const Shot after = withObjectMeasure(doc_->shot(), *measureFrom_, *to, height);
  auto measured = measureObjects(after);
  if (!measured) {
    shell.showMessage("measure: " + measured.message());
    return true;
  }
  const ObjectMeasure& added = after.measurements.back();
  applyEdit(shell, after, std::string("measure ") + metrology::quantityName(added.quantity) + " " + added.from + "-" + added.to);
  measureFrom_.reset();
  return true;
}

void EditMode::deleteObjectMeasure(app::Shell& shell, size_t index) {
  if (!doc_ || index >= doc_->shot().measurements.size()) return;
  Shot after = doc_->shot();
  const ObjectMeasure gone = after.measurements[index];
  after.measurements.erase(after.measurements.begin() + static_cast<long>(index));
  // Its points go too (the second first: it may stand above the first), unless another
  // measurement or a point left standing above one still names them.
  for (const std::string& name : {gone.to, gone.from}) {
    const bool named =
        std::any_of(after.measurements.begin(), after.measurements.end(),
                    [&](const ObjectMeasure& m) { return m.from == name || m.to == name; }) ||
        std::any_of(after.points.begin(), after.points.end(), [&](const ImagePoint& p) {
          return p.on.surface == PointSurface::kAbove && p.on.above == name;
        });
    if (!named) std::erase_if(after.points, [&](const ImagePoint& p) { return p.name == name; });
  }
  applyEdit(shell, after, std::string("delete ") + metrology::quantityName(gone.quantity) + " " + gone.from + "-" + gone.to);
}

void EditMode::drawMeasureOverlay(ImDrawList* list, const MeasuringNow& now) const {
  if (!doc_) return;
  const Shot& shot = doc_->shot();
  // The measurements kept: a line between their points, the value and ± at its middle.
  for (size_t i = 0; i < shot.measurements.size(); ++i) {
    const ObjectMeasure& m = shot.measurements[i];
    const ImagePoint* a = pointNamed(shot, m.from);
    const ImagePoint* b = pointNamed(shot, m.to);
    if (!a || !b) continue;
    const glm::dvec2 wa = canvas_.toWindow(a->px), wb = canvas_.toWindow(b->px);
    list->AddLine(im(wa), im(wb), kShadow, 4.0f);
    list->AddLine(im(wa), im(wb), kMeasureColour, 2.0f);
    for (const glm::dvec2& p : {wa, wb}) list->AddCircleFilled(im(p), 3.5f, kMeasureColour);
    std::string text = (m.name.empty() ? std::to_string(i + 1) : m.name) + ": ";
    if (objects_ && i < objects_->results.size()) {
      text += metrology::dimensionText(objects_->results[i].valueM, objects_->results[i].sigmaM);
    } else {
      text += "?";
    }
    labelAt(list, 0.5 * (wa + wb) + glm::dvec2(8, 6), text);
  }
  if (!measuring_ || !measureFrom_) return;
  // Being measured: for a height, the vertical through the first point; the line to
  // where the second would go, with its value.
  const glm::dvec2 wa = canvas_.toWindow(*measureFrom_);
  list->AddCircleFilled(im(wa), 4.0f, kMeasureColour);
  if (now.vertical) {
    const glm::dvec2 p = canvas_.toWindow(now.vertical->first), q = canvas_.toWindow(now.vertical->second);
    const glm::dvec2 dir = glm::normalize(q - p);
    list->AddLine(im(p - 2000.0 * dir), im(p + 2000.0 * dir), (kMeasureColour & 0x00ffffff) | (110u << 24), 1.0f);
  }
  if (!now.target) return;
  const glm::dvec2 wb = canvas_.toWindow(*now.target);
  list->AddLine(im(wa), im(wb), kShadow, 3.0f);
  list->AddLine(im(wa), im(wb), kMeasureColour, 1.5f);
  labelAt(list, wb + glm::dvec2(12, 8), now.text);
}

// Once a frame (the overlay is drawn in up to four pieces around the loupe): the second
// point as the cursor places it (snapped), the vertical for a height, the value.
EditMode::MeasuringNow EditMode::measuringNow() const {
  MeasuringNow now;
  if (!doc_ || !measuring_ || !measureFrom_) return now;
  const bool height = shiftHeld();
  const glm::dvec2 cursor = measureSnap(canvas_.toPhoto(cursorPx_));
  if (height) {
    // On the vertical through the first point: the cursor's nearest point on its image.
    now.vertical = verticalThrough(*measureFrom_);
    if (!now.vertical) return now;
    const glm::dvec2 dir = glm::normalize(now.vertical->second - now.vertical->first);
    now.target = now.vertical->first + glm::dot(cursor - now.vertical->first, dir) * dir;
  } else {
    now.target = cursor;
  }
  auto measured = measureObjects(withObjectMeasure(doc_->shot(), *measureFrom_, *now.target, height));
  now.text = measured ? std::string(height ? "height " : "distance ") +
                            metrology::dimensionText(measured->results.back().valueM, measured->results.back().sigmaM)
                      : std::string("not on a surface");
  return now;
}

void EditMode::drawMeasurements(app::Shell& shell) {
  const Shot& shot = doc_->shot();
  if (!ImGui::CollapsingHeader("Measurements (M)", ImGuiTreeNodeFlags_DefaultOpen)) return;
  if (ImGui::SmallButton(measuring_ ? "measuring: click two points (Esc)" : "measure (M)")) setMeasuring(shell, !measuring_);
  rememberWidget("measure");
  if (shot.measurements.empty()) {
    ImGui::TextDisabled("none: M, then two clicks (Shift at the second: a height above the first)");
    return;
  }
  if (!objectsError_.empty()) ui::wrapped(ui::kErrorColour, "cannot measure them: " + objectsError_);
  nameBuffers_.resize(shot.measurements.size());
  for (size_t i = 0; i < shot.measurements.size(); ++i) {
    const ObjectMeasure& m = shot.measurements[i];
    ImGui::PushID(static_cast<int>(i));
    if (ImGui::SmallButton("x")) deleteObjectMeasure(shell, i);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("delete it (Ctrl+Z brings it back)");
    ImGui::SameLine();
    // Its name, typed in place: kept on Enter or when the field is left (one undo step).
    const std::optional<std::string> typed =
        ui::nameField("##name", m.name, nameBuffers_[i], renaming_, static_cast<int>(i), 110.0f);
    rememberWidget(("name " + std::to_string(i + 1)).c_str());
    if (typed) {
      Shot after = shot;
      after.measurements[i].name = *typed;
      applyEdit(shell, after, "name measurement " + std::to_string(i + 1));
    }
    ImGui::SameLine();
    std::string line = std::string(metrology::quantityName(m.quantity)) + " " + m.from + "-" + m.to + "  ";
    if (objects_ && i < objects_->results.size()) {
      const metrology::ObjectResult& r = objects_->results[i];
      line += metrology::dimensionText(r.valueM, r.sigmaM);
    }
    ImGui::TextUnformatted(line.c_str());
    ImGui::PopID();
  }
}

void EditMode::addObjectsTrace(app::TraceRow& row) const {
  ordered_json objects = ordered_json::array();
  if (doc_) {
    const Shot& shot = doc_->shot();
    for (size_t i = 0; i < shot.measurements.size(); ++i) {
      const ObjectMeasure& m = shot.measurements[i];
      ordered_json o{{"quantity", metrology::quantityName(m.quantity)}, {"name", m.name}, {"from", m.from}, {"to", m.to}};
      const bool have = objects_ && i < objects_->results.size();
      o["value_m"] = have ? ordered_json(objects_->results[i].valueM) : ordered_json(nullptr);
      o["sigma_m"] = have ? ordered_json(objects_->results[i].sigmaM) : ordered_json(nullptr);
      objects.push_back(o);
    }
  }
  row.add("objects", objects);
  row.add("measuring", ordered_json{{"active", measuring_},
                                    {"from_px", measureFrom_ ? ordered_json::array({measureFrom_->x, measureFrom_->y})
                                                             : ordered_json(nullptr)}});
}

}  // namespace pw::edit
