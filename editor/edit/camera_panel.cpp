// The editor's camera: the Camera panel (the photo's EXIF, the focal length in pixels
// or in mm with a sensor width and its presets, the principal point, the scale from
// the camera height or a reference length between two corners), the principal point's
// handle and the reference drawn on the canvas, the warnings on the handles, and the
// trace's "camera" field. Every edit is one undo step (a field: when it loses focus).
#include <imgui.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include "editor/edit/panel_style.h"
#include "editor/app/shell.h"
#include "editor/edit/edit_mode.h"
#include "editor/edit/handle_warnings.h"

namespace pw::edit {
namespace {

using namespace ui;  // panel_style.h

using metrology::kCornerCount;
using metrology::Shot;
using nlohmann::ordered_json;

const ImU32 kPrincipalColour = IM_COL32(240, 90, 255, 255);
const ImU32 kReferenceColour = IM_COL32(120, 255, 230, 255);
constexpr double kGrabRadiusPx = 12;

// Common sensors, long side by short side in mm (the active area; makers' figures
// vary by a few tenths).
struct SensorPreset {
  const char* name;
  double longMm, shortMm;
};
constexpr std::array<SensorPreset, 10> kSensors{{
    {"full frame 36 x 24", 36.0, 24.0},
    {"APS-C 23.5 x 15.6 (Nikon, Sony, Fujifilm)", 23.5, 15.6},
    {"APS-C 22.3 x 14.9 (Canon)", 22.3, 14.9},
    {"Four Thirds 17.3 x 13.0", 17.3, 13.0},
    {"1-inch 13.2 x 8.8", 13.2, 8.8},
    {"phone 1/1.3\" 9.8 x 7.4", 9.8, 7.4},
    {"phone 1/1.7\" 7.6 x 5.7", 7.6, 5.7},
    {"phone 1/2.3\" 6.17 x 4.55", 6.17, 4.55},
    {"phone 1/2.55\" 5.6 x 4.2", 5.6, 4.2},
    {"phone 1/3\" 4.8 x 3.6", 4.8, 3.6},
}};

ordered_json pair(const glm::dvec2& p) { return ordered_json::array({p.x, p.y}); }
ordered_json optional(const std::optional<double>& v) { return v ? ordered_json(*v) : ordered_json(nullptr); }

// The sensor's side across the photo: the long one for a landscape photo.
double acrossMm(const SensorPreset& s, const Shot& shot) {
  return shot.imageHeight > shot.imageWidth ? s.shortMm : s.longMm;
}

bool cornerCombo(const char* label, int* corner) {
  bool changed = false;
  ImGui::SetNextItemWidth(60.0f);
  if (ImGui::BeginCombo(label, metrology::cornerName(*corner))) {
    for (int k = 0; k < kCornerCount; ++k) {
      if (ImGui::Selectable(metrology::cornerName(k), k == *corner)) *corner = k, changed = true;
    }
    ImGui::EndCombo();
  }
  return changed;
}

}  // namespace

void EditMode::rememberWidget(const char* name) {
  const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
  widgetRects_.emplace_back(name, WindowRect{{min.x, min.y}, {max.x, max.y}});
}

void EditMode::drawCamera(app::Shell& shell) {
  widgetRects_.clear();
  if (!ImGui::CollapsingHeader("Camera", ImGuiTreeNodeFlags_DefaultOpen)) return;
  const Shot shot = doc_->shot();
  Shot after = shot;
  std::string label;
  // A number field of kFieldRanges (number_field.h): its range checked, its refusal shown under it.
  double v = 0;
  const auto number = [&](const char* name, double committed, const char* format, double photoSide = 1) {
    const bool edited = fields_.field(shell, name, committed, &v, format, photoSide);
    rememberWidget(name);
    fields_.drawRefusal(name);
    return edited;
  };

  // The photo's EXIF, as read (the orientation is applied to the photo shown).
  const modeling::ExifTags& exif = doc_->exif();
  const std::optional<modeling::ExifFocal>& exifFocal = doc_->exifFocal();
  if (exif.present) {
    const std::string camera = exif.make + (exif.make.empty() || exif.model.empty() ? "" : " ") + exif.model;
    // One line (wrapped): the camera, FocalLength, FocalLengthIn35mmFilm, the sensor.
    std::string line = "EXIF: " + (camera.empty() ? std::string("(no make or model)") : camera);
    char part[96];
    if (exif.focalLengthMm) std::snprintf(part, sizeof part, ", %.2f mm", *exif.focalLengthMm), line += part;
    if (exif.focalLength35mm) std::snprintf(part, sizeof part, " (35 mm eq. %.0f)", *exif.focalLength35mm), line += part;
    if (exifFocal && exifFocal->focalMm) {
      std::snprintf(part, sizeof part, ", sensor %.2f x %.2f mm", exifFocal->focalMm->sensorWidthMm,
                    exifFocal->sensorHeightMm.value_or(0.0));
      line += part;
    }
    if (exif.orientation != 1) line += ", Orientation " + std::to_string(exif.orientation) + " (applied)";
    wrapped(ImGui::GetStyleColorVec4(ImGuiCol_Text), line);
    if (exif.orientation != 1 && ImGui::IsItemHovered()) {
      ImGui::SetTooltip("Orientation %d: %s (applied to the photo)", exif.orientation,
                        modeling::orientationName(exif.orientation).c_str());
    }
    if (exifFocal && doc_->focalSource() != exifFocal->source) {
      if (ImGui::SmallButton("use the EXIF focal length")) {
        after.focalPx = exifFocal->focalPx;
        after.focalMm = exifFocal->focalMm;
        label = "focal length from EXIF";
      }
      rememberWidget("use EXIF");
    } else if (!exifFocal && exif.focalLengthMm && !shot.focalMm) {
      if (ImGui::SmallButton("use the EXIF FocalLength with a sensor")) {
        const double sensor = acrossMm(kSensors[0], shot);
        after.focalMm = metrology::FocalLengthMm{*exif.focalLengthMm, sensor};
        after.focalPx = after.focalMm->pixels(shot.imageWidth);
        label = "focal length from EXIF";
      }
    }
  }
  // The EXIF's focal length in use: said in one line, how it was read in its tooltip
  // (the EXIF line above gives the figures).
  const std::string source = doc_->focalSource();
  if (exifFocal && source == exifFocal->source) {
    wrapped(kNoteColour, "focal length from: the photo's EXIF");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", source.c_str());
  } else {
    wrapped(kNoteColour, "focal length from: " + source + (exif.present ? "" : " (no EXIF)"));
  }

  // The focal length: in pixels, or in mm with the sensor's width across the photo.
  int unit = shot.focalMm ? 1 : 0;
  const int unitWas = unit;
  // The unit on the focal length's own row (the Camera fields stay above the fold
  // at 1280x720 with the 3D preview open).
  ImGui::RadioButton("px", &unit, 0);
  ImGui::SameLine();
  ImGui::RadioButton("mm", &unit, 1);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("the focal length in mm, with the sensor's width across the photo");
  ImGui::SameLine();
  if (unit != unitWas) {
    if (unit == 1) {
      // Keeps the focal length in pixels: the EXIF's sensor when known, else full frame.
      const double sensor = exifFocal && exifFocal->focalMm ? exifFocal->focalMm->sensorWidthMm : acrossMm(kSensors[0], shot);
      after.focalMm = metrology::FocalLengthMm{shot.focalPx / shot.imageWidth * sensor, sensor};
      after.focalPx = after.focalMm->pixels(shot.imageWidth);
    } else {
      after.focalMm.reset();
    }
    label = "focal length unit";
  }
  if (shot.focalMm) {
    if (number("focal mm", shot.focalMm->focalMm, "%.2f")) {
      after.focalMm->focalMm = v;
      label = "focal length";
    }
    if (number("sensor width mm", shot.focalMm->sensorWidthMm, "%.2f")) {
      after.focalMm->sensorWidthMm = v;
      label = "sensor width";
    }
    ImGui::SameLine();  // the presets: an arrow beside the sensor's field
    if (ImGui::BeginCombo("##sensor", "sensor presets", ImGuiComboFlags_NoPreview)) {
      for (const SensorPreset& s : kSensors) {
        if (ImGui::Selectable(s.name, std::abs(acrossMm(s, shot) - shot.focalMm->sensorWidthMm) < 1e-9)) {
          after.focalMm->sensorWidthMm = acrossMm(s, shot);  // the lens stays: the focal length in mm is kept
          label = std::string("sensor ") + s.name;
        }
      }
      ImGui::EndCombo();
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("sensor presets");
    if (after.focalMm) after.focalPx = after.focalMm->pixels(shot.imageWidth);
  } else {
    if (number("focal px", shot.focalPx, "%.1f")) {
      after.focalPx = v;
      label = "focal length";
    }
  }
  // The scale: the camera height, a reference length between two corners, or both
  // (the height scales, the reference is checked).
  bool byHeight = shot.cameraHeightM.has_value();
  // Checked, the field beside it names it.
  if (ImGui::Checkbox(byHeight ? "##camera height" : "camera height", &byHeight)) {
    if (byHeight) {
      const double measured = live_.measurement ? live_.measurement->cameraHeightM : kDefaultCameraHeightM;
      after.cameraHeightM = std::isfinite(measured) && measured > 0 ? measured : kDefaultCameraHeightM;
      label = "camera height";
    } else if (shot.reference) {
      after.cameraHeightM.reset();
      label = "scale from the reference";
    } else {
      shell.showMessage("the scale needs the camera height or a reference length: set a reference first");
    }
  }
  rememberWidget("camera height");
  if (shot.cameraHeightM) ImGui::SameLine();
  if (shot.cameraHeightM && number("camera height m", *shot.cameraHeightM, "%.3f")) {
    after.cameraHeightM = v;
    label = "camera height";
  }
  bool byReference = shot.reference.has_value();
  if (ImGui::Checkbox("reference length", &byReference)) {
    if (byReference) {
      metrology::ReferenceLength r;  // P3-P4, the far wall's floor edge, as long as it measures now
      r.lengthM = live_.measurement ? glm::length(live_.measurement->cornersM[r.to] - live_.measurement->cornersM[r.from])
                                    : 1.0;
      if (!(std::isfinite(r.lengthM) && r.lengthM > 0)) r.lengthM = 1.0;
      after.reference = r;
      label = "reference length";
    } else if (shot.cameraHeightM) {
      after.reference.reset();
      label = "no reference length";
    } else {
      shell.showMessage("the scale needs the camera height or a reference length: set the camera height first");
    }
  }
  rememberWidget("reference length");
  if (shot.reference) {
    metrology::ReferenceLength r = *shot.reference;
    ImGui::TextUnformatted("from");
    ImGui::SameLine();
    bool changed = cornerCombo("##reference from", &r.from);
    ImGui::SameLine();
    ImGui::TextUnformatted("to");
    ImGui::SameLine();
    changed = cornerCombo("##reference to", &r.to) || changed;
    if (changed) {
      if (r.from == r.to) {
        shell.showMessage("the reference needs two different corners");
      } else {
        after.reference = r;
        label = "reference corners";
      }
    }
    ImGui::SameLine();
    if (ImGui::SmallButton(pickingReference_ ? "click two corners..." : "pick")) {
      pickingReference_ = !pickingReference_;
      referencePickFrom_ = -1;
    }
    rememberWidget("pick");
    if (number("reference m", r.lengthM, "%.3f")) {
      after.reference->lengthM = v;
      label = "reference length";
    }
    if (pickingReference_) {
      wrapped(kWarningColour, referencePickFrom_ < 0 ? "click the reference's first corner on the photo (Esc: stop)"
                                                     : std::string("from ") + metrology::cornerName(referencePickFrom_) +
                                                           ": click its second corner");
    }
    wrapped(kNoteColour, shot.cameraHeightM ? "the camera height gives the scale; the reference checks it"
                                            : "the reference gives the scale");
  }
  if (shot.imageWidth > 0 && shot.imageHeight > 0) {
    const double equivalentMm =
        shot.focalPx / std::hypot(double(shot.imageWidth), double(shot.imageHeight)) * std::hypot(36.0, 24.0);
    if (shot.focalMm) {
      ImGui::TextDisabled("= %.1f px; 35 mm equivalent %.1f mm", shot.focalPx, equivalentMm);
      if (ImGui::IsItemHovered()) {
        ImGui::SetTooltip("pixels by the sensor's side across the photo; the 35 mm equivalent by the diagonal");
      }
    } else {
      ImGui::TextDisabled("35 mm equivalent %.1f mm (by the diagonal)", equivalentMm);
    }
  }

  // The principal point: the centre unless moved (its handle on the canvas, or here).
  const glm::dvec2 pp = shot.principalPoint();
  if (number("principal u px", pp.x, "%.1f", shot.imageWidth)) {
    after.principalPointPx = glm::dvec2(v, pp.y);
    label = "principal point";
  }
  if (number("principal v px", pp.y, "%.1f", shot.imageHeight)) {
    after.principalPointPx = glm::dvec2(pp.x, v);
    label = "principal point";
  }
  const bool ppMoved = shot.principalPointMoved();
  ImGui::BeginDisabled(!ppMoved);
  if (ImGui::SmallButton("reset to centre")) {
    after.principalPointPx.reset();
    label = "principal point to the centre";
  }
  rememberWidget("reset to centre");
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::TextDisabled(ppMoved ? "(moved)" : "(the photo's centre) (?)");
  constexpr const char* kPrincipalHelp =
      "drag the magenta PP handle to move it; a cropped or shifted photo moves the principal point "
      "away from its centre, so move it only for such a photo";
  if (ppMoved) {
    wrapped(kWarningColour, kPrincipalHelp);  // moved: the warning stays in view
  } else if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("%s", kPrincipalHelp);
  }

  // The lens's radial distortion (OpenCV's k1, k2 over the focal-normalised radius):
  // unknown (measure then fits it to the corners when they show one), none, or given.
  if (shot.distortion) {
    if (number("distortion k1", shot.distortion->k1, "%.4f")) {
      after.distortion->k1 = v;
      label = "distortion";
    }
    if (number("distortion k2", shot.distortion->k2, "%.4f")) {
      after.distortion->k2 = v;
      label = "distortion";
    }
    if (ImGui::SmallButton("distortion unknown")) {
      after.distortion.reset();
      label = "distortion unknown";
    }
    rememberWidget("distortion unknown");
  } else {
    const bool estimated = live_.measurement && live_.measurement->distortionSource == metrology::DistortionSource::kCorners;
    char k1[32];
    std::snprintf(k1, sizeof k1, "%.4f", estimated ? live_.measurement->camera.distortion.k1 : 0.0);
    wrapped(kNoteColour, estimated ? std::string("lens distortion: not given; k1 ") + k1 + " fitted to the corners"
                                   : std::string("lens distortion: not given (the corners show none)"));
    if (ImGui::SmallButton("set distortion")) {
      after.distortion = estimated ? live_.measurement->camera.distortion : metrology::RadialDistortion{};
      label = "distortion";
    }
    rememberWidget("set distortion");
  }
  if (!label.empty()) applyEdit(shell, after, label);
}

bool EditMode::pickReference(app::Shell& shell, int corner) {
  if (!pickingReference_ || !doc_) return false;
  if (corner < 0) return false;  // not on a handle: an ordinary click (a pan, nothing)
  if (referencePickFrom_ < 0 || referencePickFrom_ == corner) {
    referencePickFrom_ = corner;
    return true;
  }
  Shot after = doc_->shot();
  metrology::ReferenceLength r = after.reference.value_or(metrology::ReferenceLength{});
  r.from = referencePickFrom_;
  r.to = corner;
  if (!after.reference) {  // as long as it measures now, so that the scale stays
    r.lengthM = live_.measurement ? glm::length(live_.measurement->cornersM[r.to] - live_.measurement->cornersM[r.from])
                                  : 1.0;
    if (!(std::isfinite(r.lengthM) && r.lengthM > 0)) r.lengthM = 1.0;
  }
  after.reference = r;
  pickingReference_ = false;
  referencePickFrom_ = -1;
  applyEdit(shell, after, "reference corners");
  shell.showMessage(std::string("reference ") + metrology::cornerName(r.from) + "-" + metrology::cornerName(r.to) +
                    ": type its length in the Camera panel");
  return true;
}

int EditMode::principalHandleAt(const glm::dvec2& windowPx) const {
  if (!doc_ || !showOverlay_) return -1;
  const glm::dvec2 at = canvas_.toWindow(doc_->shot().principalPoint());
  return glm::length(at - windowPx) <= kGrabRadiusPx ? kPrincipalPointHandle : -1;
}

void EditMode::drawCameraOverlay(ImDrawList* list) const {
  if (!doc_) return;
  const Shot& shot = doc_->shot();
  const auto im = [](const glm::dvec2& p) { return ImVec2(float(p.x), float(p.y)); };
  // The reference: a line between its corners with the length given.
  if (shot.reference) {
    const glm::dvec2 a = canvas_.toWindow(shot.cornersPx[shot.reference->from]);
    const glm::dvec2 b = canvas_.toWindow(shot.cornersPx[shot.reference->to]);
    list->AddLine(im(a), im(b), IM_COL32(0, 0, 0, 200), 4.0f);
    list->AddLine(im(a), im(b), kReferenceColour, 2.0f);
    char text[48];
    std::snprintf(text, sizeof text, "%.3f m", shot.reference->lengthM);
    const glm::dvec2 mid = 0.5 * (a + b) + glm::dvec2(6, 4);
    list->AddText(im(mid + glm::dvec2(1, 1)), IM_COL32(0, 0, 0, 220), text);
    list->AddText(im(mid), kReferenceColour, text);
  }
  if (pickingReference_ && referencePickFrom_ >= 0) {
    const glm::dvec2 a = canvas_.toWindow(shot.cornersPx[referencePickFrom_]);
    list->AddLine(im(a), im(cursorPx_), kReferenceColour, 1.0f);
  }
  // The principal point: a crosshair in a circle, apart from the round corner handles.
  const glm::dvec2 pp = canvas_.toWindow(shot.principalPoint());
  if (std::isfinite(pp.x) && std::isfinite(pp.y)) {
    const ImU32 col = shot.principalPointPx ? kPrincipalColour : (kPrincipalColour & 0x00ffffff) | (170u << 24);
    const bool dragged = drag_ && drag_->corner == kPrincipalPointHandle;
    list->AddCircle(im(pp), 8.0f, IM_COL32(0, 0, 0, 200), 20, 3.5f);
    list->AddCircle(im(pp), 8.0f, col, 20, dragged ? 2.5f : 1.5f);
    for (const glm::dvec2 d : {glm::dvec2(1, 0), glm::dvec2(0, 1)}) {
      list->AddLine(im(pp - 13.0 * d), im(pp - 3.0 * d), col, 1.5f);
      list->AddLine(im(pp + 3.0 * d), im(pp + 13.0 * d), col, 1.5f);
    }
    list->AddText(im(pp + glm::dvec2(-24, 6)), IM_COL32(0, 0, 0, 220), "PP");  // below left: the horizon's label is above
    list->AddText(im(pp + glm::dvec2(-25, 5)), col, "PP");
  }
  drawHandleWarnings(list, canvas_, shot, live_.handleWarnings);
}

void EditMode::addCameraTrace(app::TraceRow& row) const {
  if (!doc_) {
    row.add("camera", ordered_json(nullptr));
    row.add("handle_warnings", ordered_json::array());
    return;
  }
  const Shot& shot = doc_->shot();
  ordered_json camera{{"focal_px", shot.focalPx},
                      {"focal_source", doc_->focalSource()},
                      {"focal_mm", shot.focalMm ? ordered_json(shot.focalMm->focalMm) : ordered_json(nullptr)},
                      {"sensor_width_mm", shot.focalMm ? ordered_json(shot.focalMm->sensorWidthMm) : ordered_json(nullptr)},
                      {"principal_px", pair(shot.principalPoint())},
                      {"principal_default", !shot.principalPointMoved()},
                      {"camera_height_m", optional(shot.cameraHeightM)}};
  camera["reference"] = shot.reference ? ordered_json{{"from", metrology::cornerName(shot.reference->from)},
                                                       {"to", metrology::cornerName(shot.reference->to)},
                                                       {"length_m", shot.reference->lengthM}}
                                       : ordered_json(nullptr);
  camera["distortion"] =
      shot.distortion ? ordered_json{{"k1", shot.distortion->k1}, {"k2", shot.distortion->k2}} : ordered_json(nullptr);
  const modeling::ExifTags& exif = doc_->exif();
  camera["exif"] = exif.present ? ordered_json{{"make", exif.make},
                                                {"model", exif.model},
                                                {"orientation", exif.orientation},
                                                {"focal_length_mm", optional(exif.focalLengthMm)},
                                                {"focal_length_35mm", optional(exif.focalLength35mm)}}
                                : ordered_json(nullptr);
  ordered_json widgets = ordered_json::object();
  for (const auto& [name, rect] : widgetRects_) {
    widgets[name] = ordered_json::array({rect.min.x, rect.min.y, rect.size().x, rect.size().y});
  }
  camera["widgets"] = widgets;
  camera["refused"] = fields_.refused() ? ordered_json(*fields_.refused()) : ordered_json(nullptr);
  row.add("camera", camera);
  ordered_json warnings = ordered_json::array();
  for (const HandleWarning& w : live_.handleWarnings) {
    ordered_json handles = ordered_json::array();
    for (int h : w.handles) handles.push_back(h == kPrincipalPointHandle ? "PP" : metrology::cornerName(h));
    warnings.push_back({{"handles", handles}, {"label", w.label}, {"blocking", w.blocking}, {"text", w.text}});
  }
  row.add("handle_warnings", warnings);
}

}  // namespace pw::edit
