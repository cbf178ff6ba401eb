#include "editor/edit/detection_report.h"

#include <cmath>

namespace pw::edit {
namespace {

using nlohmann::json;

json vanishingPointJson(const metrology::detect::VanishingPoint& vp) {
  json j;
  if (vp.isFinite()) j["px"] = {vp.pixel().x, vp.pixel().y};
  j["homogeneous"] = {vp.point.x, vp.point.y, vp.point.z};
  j["confidence"] = vp.confidence;
  j["inliers"] = vp.inlierCount;
  j["rms_angle_deg"] = vp.rmsAngleDeg;
  return j;
}

bool isFiniteNumber(const json& j) { return j.is_number() && std::isfinite(j.get<double>()); }

}  // namespace

json detectionReport(const metrology::detect::CorridorDetection& d, bool lensGiven, bool focalFromExif) {
  json j;
  j["method"] = "lsd+manhattan-ransac+angular-profile+subpixel-edges+layout-net";
  j["found"] = d.found;
  if (!d.found) j["reason"] = d.notFoundReason;
  j["focal_source"] = focalFromExif ? "exif" : metrology::detect::focalSourceName(d.focalSource);
  j["near_depth"] = metrology::detect::nearDepthName(d.nearDepth);
  j["segments"] = d.segmentCount;
  j["vanishing_points"] = {{"corridor", vanishingPointJson(d.corridor)},
                           {"horizontal", vanishingPointJson(d.horizontal)},
                           {"vertical", vanishingPointJson(d.vertical)}};
  if (d.found) {
    json corners = json::object();
    for (int k = 0; k < metrology::kCornerCount; ++k) {
      // (px: where detection put the corner, as corners_px has it when written.)
      corners[metrology::cornerName(k)] = {{"px", {d.corners[k].px.x, d.corners[k].px.y}},
                                           {"confidence", d.corners[k].confidence},
                                           {"sigma_px", d.corners[k].sigmaPx}};
    }
    j["corners"] = corners;
  }
  j["warnings"] = d.warnings;
  j["confident"] = d.confident;
  j["doubts"] = d.doubts;
  if (lensGiven) {
    j["distortion"] = {{"method", "given"}};
  } else if (!d.distortion.isNone()) {
    j["distortion"] = {{"method", "plumb-line"}, {"lines", d.plumbLineCount}};
  }
  return j;
}

std::optional<DetectionReport> readDetectionReport(const json& fields) {
  const auto found = fields.find("detection");
  if (found == fields.end() || !found->is_object()) return std::nullopt;
  const json& report = *found;
  const auto flag = [&](const char* name) { return report.contains(name) && report[name].is_boolean() && report[name].get<bool>(); };
  if (!flag("found") || !report.contains("corners") || !report["corners"].is_object()) return std::nullopt;
  DetectionReport out;
  out.confident = flag("confident");
  for (int k = 0; k < metrology::kCornerCount; ++k) {
    const auto corner = report["corners"].find(metrology::cornerName(k));
    if (corner == report["corners"].end() || !corner->is_object()) return std::nullopt;
    const json& c = *corner;
    if (!c.contains("px") || !c["px"].is_array() || c["px"].size() != 2 || !isFiniteNumber(c["px"][0]) ||
        !isFiniteNumber(c["px"][1]) || !c.contains("confidence") || !isFiniteNumber(c["confidence"])) {
      return std::nullopt;
    }
    out.px[k] = {c["px"][0].get<double>(), c["px"][1].get<double>()};
    out.confidence[k] = c["confidence"].get<double>();
  }
  if (report.contains("doubts") && report["doubts"].is_array()) {
    for (const json& doubt : report["doubts"])
      if (doubt.is_string()) out.doubts.push_back(doubt.get<std::string>());
  }
  return out;
}

}  // namespace pw::edit
