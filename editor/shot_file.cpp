#include "editor/shot_file.h"

#include <cmath>

#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "base/atomic_file.h"

namespace pw::editor {
namespace fs = std::filesystem;
using nlohmann::json;
using metrology::kCornerCount;

namespace {

int cornerIndex(const std::string& name) {
  for (int i = 0; i < kCornerCount; ++i) {
    if (name == metrology::cornerName(i)) return i;
  }
  return -1;
}

// Reads a finite number at `key`; `where` prefixes the error.
Result<double> number(const json& object, const char* key, const std::string& where) {
  auto it = object.find(key);
  if (it == object.end()) return makeError(where + ": missing field \"" + key + "\"");
  if (!it->is_number()) return makeError(where + ": field \"" + key + "\" must be a number, not " + it->dump());
  const double v = it->get<double>();
  if (!std::isfinite(v)) return makeError(where + ": field \"" + key + "\" is not a finite number");
  return v;
}

Result<glm::dvec2> point(const json& value, const std::string& what, const std::string& where) {
  if (!value.is_array() || value.size() != 2 || !value[0].is_number() || !value[1].is_number()) {
    return makeError(where + ": " + what + " must be [u, v] in pixels, not " + value.dump());
  }
  const glm::dvec2 p(value[0].get<double>(), value[1].get<double>());
  if (!std::isfinite(p.x) || !std::isfinite(p.y)) return makeError(where + ": " + what + " is not finite");
  return p;
}

}  // namespace

Result<metrology::Shot> readShotFile(const fs::path& path) {
  const std::string where = path.string();
  auto text = readFile(path);
  if (!text) return text.error();
  json doc = json::parse(*text, nullptr, /*allow_exceptions=*/false);
  if (doc.is_discarded()) return makeError(where + ": not valid JSON");
  if (!doc.is_object()) return makeError(where + ": a shot file is a JSON object");

  metrology::Shot shot;
  auto image = doc.find("image");
  if (image == doc.end() || !image->is_string() || image->get<std::string>().empty()) {
    return makeError(where + ": missing field \"image\" (the photo's path, relative to the shot file)");
  }
  fs::path imagePath = image->get<std::string>();
  if (imagePath.is_relative()) imagePath = path.parent_path() / imagePath;
  shot.imagePath = imagePath.lexically_normal().string();

  if (doc.contains("focal_px")) {
    auto f = number(doc, "focal_px", where);
    if (!f) return f.error();
    if (*f <= 0) return makeError(where + ": focal_px must be positive");
    shot.focalPx = *f;
  } else if (doc.contains("focal_mm") || doc.contains("sensor_width_mm")) {
    auto mm = number(doc, "focal_mm", where);
    if (!mm) return mm.error();
    auto sensor = number(doc, "sensor_width_mm", where);
    if (!sensor) return sensor.error();
    if (*mm <= 0 || *sensor <= 0) return makeError(where + ": focal_mm and sensor_width_mm must be positive");
    shot.focalOverSensorWidth = *mm / *sensor;
  } else {
    return makeError(where + ": missing field \"focal_px\" (or \"focal_mm\" with \"sensor_width_mm\")");
  }

  if (doc.contains("principal_point")) {
    auto pp = point(doc["principal_point"], "principal_point", where);
    if (!pp) return pp.error();
    shot.principalPointPx = *pp;
  }
  if (doc.contains("camera_height_m")) {
    auto h = number(doc, "camera_height_m", where);
    if (!h) return h.error();
    if (*h <= 0) return makeError(where + ": camera_height_m must be positive");
    shot.cameraHeightM = *h;
  }

  auto corners = doc.find("corners_px");
  if (corners == doc.end() || !corners->is_object()) {
    return makeError(where + ": missing field \"corners_px\" ({\"P1\": [u, v], ... \"P8\": [u, v]})");
  }
  for (int i = 0; i < kCornerCount; ++i) {
    auto c = corners->find(metrology::cornerName(i));
    if (c == corners->end()) return makeError(where + ": corners_px has no " + metrology::cornerName(i));
    auto p = point(*c, std::string("corner ") + metrology::cornerName(i), where);
    if (!p) return p.error();
    shot.cornersPx[i] = *p;
  }

  if (doc.contains("reference")) {
    const json& ref = doc["reference"];
    if (!ref.is_object()) return makeError(where + ": reference must be {\"from\": \"P3\", \"to\": \"P4\", \"length_m\": L}");
    metrology::ReferenceLength reference;
    const std::string from = ref.value("from", ""), to = ref.value("to", "");
    reference.from = cornerIndex(from);
    reference.to = cornerIndex(to);
    if (reference.from < 0 || reference.to < 0 || reference.from == reference.to) {
      return makeError(where + ": reference needs two different corners \"from\" and \"to\" among P1..P8");
    }
    auto length = number(ref, "length_m", where + ": reference");
    if (!length) return length.error();
    if (*length <= 0) return makeError(where + ": reference length_m must be positive");
    reference.lengthM = *length;
    shot.reference = reference;
  }
  if (!shot.cameraHeightM && !shot.reference) {
    return makeError(where + ": give camera_height_m or a reference length; without one the scale is unknown");
  }
  return shot;
}

Result<LoadedShot> loadShot(const fs::path& path) {
  auto shot = readShotFile(path);
  if (!shot) return shot.error();
  LoadedShot loaded{std::move(*shot), {}};
  metrology::Shot& s = loaded.shot;
  std::error_code ec;
  if (!fs::exists(s.imagePath, ec)) return makeError(path.string() + ": image " + s.imagePath + " does not exist");
  if (fs::file_size(s.imagePath, ec) == 0) return makeError(path.string() + ": image " + s.imagePath + " is empty");
  try {
    loaded.image = cv::imread(s.imagePath, cv::IMREAD_COLOR);
  } catch (const cv::Exception&) {
    loaded.image.release();
  }
  if (loaded.image.empty()) return makeError(path.string() + ": image " + s.imagePath + " is not a readable PNG/JPEG");
  s.imageWidth = loaded.image.cols;
  s.imageHeight = loaded.image.rows;
  if (s.focalOverSensorWidth) s.focalPx = *s.focalOverSensorWidth * s.imageWidth;
  for (int i = 0; i < kCornerCount; ++i) {
    const glm::dvec2 p = s.cornersPx[i];
    if (p.x < -s.imageWidth || p.x > 2.0 * s.imageWidth || p.y < -s.imageHeight || p.y > 2.0 * s.imageHeight) {
      return makeError(path.string() + ": corner " + metrology::cornerName(i) + " lies far outside the " +
                       std::to_string(s.imageWidth) + "x" + std::to_string(s.imageHeight) + " image");
    }
  }
  return loaded;
}

Status writeShotFile(const fs::path& path, const metrology::Shot& shot) {
  json doc;
  fs::path image = shot.imagePath;
  std::error_code ec;
  const fs::path base = path.parent_path().empty() ? fs::path(".") : path.parent_path();
  fs::path relative = fs::relative(fs::absolute(image, ec), fs::absolute(base, ec), ec);
  doc["image"] = (!ec && !relative.empty()) ? relative.generic_string() : image.generic_string();
  if (shot.imageWidth > 0) doc["image_size"] = {shot.imageWidth, shot.imageHeight};
  doc["focal_px"] = shot.focalPx;
  if (shot.principalPointPx) doc["principal_point"] = {shot.principalPointPx->x, shot.principalPointPx->y};
  if (shot.cameraHeightM) doc["camera_height_m"] = *shot.cameraHeightM;
  json corners = json::object();
  for (int i = 0; i < kCornerCount; ++i) corners[metrology::cornerName(i)] = {shot.cornersPx[i].x, shot.cornersPx[i].y};
  doc["corners_px"] = corners;
  if (shot.reference) {
    doc["reference"] = {{"from", metrology::cornerName(shot.reference->from)},
                        {"to", metrology::cornerName(shot.reference->to)},
                        {"length_m", shot.reference->lengthM}};
  }
  return writeFileAtomic(path, doc.dump(1) + "\n");
}

}  // namespace pw::editor
