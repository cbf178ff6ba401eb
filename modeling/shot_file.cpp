#include "modeling/shot_file.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "base/atomic_file.h"
#include "base/input_file.h"
#include "metrology/input_sigma.h"
#include "modeling/exif.h"
#include "modeling/image_decode.h"

namespace pw::modeling {
namespace fs = std::filesystem;
using nlohmann::json;
using nlohmann::ordered_json;
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

// The focal length of a loaded shot (its photo decoded, oriented as shown): the one
// given, else the shot's, else the photo's EXIF; and where it came from.
Status fillFocal(const fs::path& path, std::optional<double> givenPx, bool assumeFocal, LoadedShot& loaded) {
  metrology::Shot& s = loaded.shot;
  const bool inShot = s.focalPx > 0 || s.focalMm.has_value();
  if (givenPx) {
    s.focalPx = *givenPx;
    s.focalMm.reset();
    loaded.focalSource = "given";
    return {};
  }
  if (inShot) {
    const auto source = loaded.otherFields.find("focal_source");
    loaded.focalSource = source != loaded.otherFields.end() && source->is_string() ? source->get<std::string>() : "shot";
    return {};
  }
  // The decoded photo is oriented as shown; the EXIF's sizes are the stored image's.
  const ExifTags tags = readExif(s.imagePath);
  const bool swap = orientationSwapsAxes(tags.orientation);
  std::vector<std::string> notes;
  const std::optional<ExifFocal> exif = exifFocal(tags, swap ? loaded.image.rows : loaded.image.cols,
                                                  swap ? loaded.image.cols : loaded.image.rows, &notes);
  if (!exif && assumeFocal) {
    s.focalPx = metrology::kAssumedFocalOverLongSide * std::max(loaded.image.cols, loaded.image.rows);
    s.focalMm.reset();
    loaded.focalSource = "assumed: a 28 mm-equivalent lens (0.8 of the long side)";
    return {};
  }
  if (!exif) {
    return makeError(path.string() + ": missing field \"focal_px\" (or \"focal_mm\" with \"sensor_width_mm\"), and the photo " +
                     s.imagePath + " has no EXIF focal length" + (notes.empty() ? "" : " (" + notes.front() + ")"));
  }
  s.focalPx = exif->focalPx;
  s.focalMm = exif->focalMm;
  loaded.focalSource = exif->source;
  return {};
}

// A shot file's own points and measurements (README "Measuring objects"):
//   "points": [{"name": "feet", "px": [u, v], "on": "floor"}, ...],
//   "measurements": [{"height": ["feet", "head"]}, {"distance": ["a", "b"]}, ...]
Status readShotObjects(const json& fields, const std::string& where, std::vector<metrology::ImagePoint>& points,
                       std::vector<metrology::ObjectMeasure>& objects) {
  if (fields.contains("points")) {
    const json& list = fields["points"];
    const std::string form = "points is [{\"name\": NAME, \"px\": [u, v], \"on\": SURFACE}, ...]";
    if (!list.is_array()) return makeError(where + ": " + form);
    for (size_t i = 0; i < list.size(); ++i) {
      const json& p = list[i];
      const std::string at = where + ": points[" + std::to_string(i) + "]";
      if (!p.is_object() || !p.contains("name") || !p["name"].is_string() || !p.contains("px") || !p["px"].is_array() ||
          p["px"].size() != 2 || !p["px"][0].is_number() || !p["px"][1].is_number()) {
        return makeError(at + ": " + form);
      }
      metrology::ImagePoint point;
      point.name = p["name"].get<std::string>();
      point.px = {p["px"][0].get<double>(), p["px"][1].get<double>()};
      const std::string on = p.contains("on") && p["on"].is_string() ? p["on"].get<std::string>() : "floor";
      auto surface = metrology::surfaceFromName(on, &point.on.above);
      if (!surface) return makeError(at + ": \"on\" is floor, ceiling, wall:left, wall:right, wall:far or above:NAME");
      point.on.surface = *surface;
      points.push_back(point);
    }
  }
  if (fields.contains("measurements")) {
    const json& list = fields["measurements"];
    const std::string form = "measurements is [{\"distance\": [A, B]} or {\"height\": [A, B]}, with \"name\": TEXT if wished, ...]";
    if (!list.is_array()) return makeError(where + ": " + form);
    for (size_t i = 0; i < list.size(); ++i) {
      const json& m = list[i];
      bool read = false;
      for (auto quantity : {metrology::ObjectQuantity::kDistance, metrology::ObjectQuantity::kHeight}) {
        const char* key = metrology::quantityName(quantity);
        if (!m.is_object() || !m.contains(key)) continue;
        const json& ends = m[key];
        if (!ends.is_array() || ends.size() != 2 || !ends[0].is_string() || !ends[1].is_string()) break;
        objects.push_back({quantity, ends[0].get<std::string>(), ends[1].get<std::string>(), ""});
        if (m.contains("name")) {
          if (!m["name"].is_string()) break;
          objects.back().name = m["name"].get<std::string>();
        }
        read = true;
      }
      if (!read) return makeError(where + ": measurements[" + std::to_string(i) + "]: " + form);
    }
  }
  return {};
}

// A shot file's objects to stand up (README "Standing objects up"):
//   "cutouts": [{"name": "person", "outline_px": [[u, v], [u, v], [u, v], ...], "shape": "flat"|"box"}, ...]
Status readCutouts(const json& fields, const std::string& where, std::vector<metrology::Cutout>& cutouts) {
  if (!fields.contains("cutouts")) return {};
  const json& list = fields["cutouts"];
  const std::string form = "cutouts is [{\"name\": NAME, \"outline_px\": [[u, v], [u, v], [u, v], ...]}, ...]";
  if (!list.is_array()) return makeError(where + ": " + form);
  for (size_t i = 0; i < list.size(); ++i) {
    const json& c = list[i];
    const std::string at = where + ": cutouts[" + std::to_string(i) + "]";
    if (!c.is_object() || !c.contains("name") || !c["name"].is_string() || !c.contains("outline_px") ||
        !c["outline_px"].is_array()) {
      return makeError(at + ": " + form);
    }
    metrology::Cutout cutout;
    cutout.name = c["name"].get<std::string>();
    if (cutout.name.empty()) return makeError(at + ": its name is empty");
    for (const json& p : c["outline_px"]) {
      if (!p.is_array() || p.size() != 2 || !p[0].is_number() || !p[1].is_number()) return makeError(at + ": " + form);
      const glm::dvec2 px(p[0].get<double>(), p[1].get<double>());
      if (!std::isfinite(px.x) || !std::isfinite(px.y)) return makeError(at + ": an outline point is not a number");
      cutout.outlinePx.push_back(px);
    }
    if (cutout.outlinePx.size() < 3) return makeError(at + ": its outline needs 3 points or more (a rectangle: 4)");
    if (c.contains("shape")) {
      const json& shape = c["shape"];
      if (shape == "box") {
        cutout.shape = metrology::CutoutShape::kBox;
      } else if (shape == "opening") {
        cutout.shape = metrology::CutoutShape::kOpening;
      } else if (shape == "hanging") {
        cutout.shape = metrology::CutoutShape::kHanging;
      } else if (shape != "flat") {
        return makeError(at + ": its shape is \"flat\" (a cut-out facing the camera), \"box\" (a box on the floor), "
                              "\"hanging\" (a cut-out hanging from the ceiling) or \"opening\" (a doorway in a side wall, "
                              "with a room behind it)");
      }
    }
    for (const metrology::Cutout& earlier : cutouts) {
      if (earlier.name == cutout.name) return makeError(at + ": the name \"" + cutout.name + "\" is used twice");
    }
    cutouts.push_back(std::move(cutout));
  }
  return {};
}

}  // namespace

// The fields readShotFile reads and writeShotFile writes.
constexpr const char* kShotFields[] = {"image",           "image_size",      "focal_px",  "focal_mm",
                                       "sensor_width_mm", "principal_point", "camera_height_m", "corners_px",
                                       "reference",       "distortion",      "points",          "measurements",
                                       "cutouts"};

Result<metrology::Shot> readShotFile(const fs::path& path, json* otherFields, bool allowNoScale) {
  const std::string where = path.string();
  auto text = readInputFile(path, kShotInput);
  if (!text) return text.error();
  json doc;
  try {
    doc = json::parse(*text);
  } catch (const json::exception& e) {
    // e.what() is "[json.exception.parse_error.101] parse error at line 1, column 9: ...".
    std::string what = e.what();
    if (const size_t close = what.find("] "); close != std::string::npos) what = what.substr(close + 2);
    return makeError(where + ": not valid JSON: " + what);
  }
  if (!doc.is_object()) return makeError(where + ": a shot file is a JSON object");

  metrology::Shot shot;
  auto image = doc.find("image");
  if (image == doc.end() || !image->is_string() || image->get<std::string>().empty()) {
    return makeError(where + ": missing field \"image\" (the photo's path, relative to the shot file)");
  }
  if (image->get<std::string>().find('\0') != std::string::npos) {
    return makeError(where + ": field \"image\" holds a NUL character; no file has such a name");
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
    shot.focalMm = metrology::FocalLengthMm{*mm, *sensor};
  }  // else: none (loadShot takes it from the photo's EXIF or the command line)

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
  if (corners == doc.end() && isVanishingPointsOnly(doc)) {
    return makeError(where + ": no corners: detect found no corridor's box in this photo, only its vanishing points; "
                     "place the corners in the editor (photowalk edit " + path.string() + ")");
  }
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
    auto name = [&](const char* key) {
      auto it = ref.find(key);
      return (it != ref.end() && it->is_string()) ? it->get<std::string>() : std::string();
    };
    const std::string from = name("from"), to = name("to");
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
  if (doc.contains("distortion")) {
    const json& lens = doc["distortion"];
    const std::string form = "distortion must be {\"k1\": K1, \"k2\": K2} (OpenCV's radial model, focal-normalised)";
    if (!lens.is_object()) return makeError(where + ": " + form + ", not " + lens.dump());
    metrology::RadialDistortion d;
    for (const auto& [key, value] : lens.items()) {
      if (key != "k1" && key != "k2") return makeError(where + ": " + form + "; \"" + key + "\" is not one of them");
    }
    if (lens.contains("k1")) {
      auto k1 = number(lens, "k1", where + ": distortion");
      if (!k1) return k1.error();
      d.k1 = *k1;
    }
    if (lens.contains("k2")) {
      auto k2 = number(lens, "k2", where + ": distortion");
      if (!k2) return k2.error();
      d.k2 = *k2;
    }
    if (std::abs(d.k1) > metrology::kMaxDistortionCoefficient || std::abs(d.k2) > metrology::kMaxDistortionCoefficient) {
      return makeError(where + ": distortion k1 and k2 must lie within -2..2 (focal-normalised), not " +
                       metrology::distortionText(d));
    }
    shot.distortion = d;
  }
  if (Status read = readShotObjects(doc, where, shot.points, shot.measurements); !read) return makeError(read.message());
  if (Status read = readCutouts(doc, where, shot.cutouts); !read) return makeError(read.message());
  if (doc.contains("image_size")) {
    const json& size = doc["image_size"];
    if (!size.is_array() || size.size() != 2 || !size[0].is_number_integer() || !size[1].is_number_integer() ||
        size[0].get<int64_t>() <= 0 || size[1].get<int64_t>() <= 0 || size[0].get<int64_t>() > 1000000 ||
        size[1].get<int64_t>() > 1000000) {
      return makeError(where + ": image_size must be [width, height] in pixels, not " + size.dump());
    }
    shot.imageWidth = size[0].get<int>();
    shot.imageHeight = size[1].get<int>();
  }
  if (!shot.cameraHeightM && !shot.reference && !allowNoScale) {
    return makeError(where + ": give camera_height_m or a reference length; without one the scale is unknown");
  }
  if (otherFields) {
    *otherFields = doc;
    for (const char* key : kShotFields) otherFields->erase(key);
  }
  return shot;
}

Result<LoadedShot> loadShot(const fs::path& path, std::optional<double> focalPx, bool assumeFocal, bool allowNoScale) {
  json otherFields;
  auto shot = readShotFile(path, &otherFields, assumeFocal || allowNoScale);
  if (!shot) return shot.error();
  LoadedShot loaded{std::move(*shot), {}, std::move(otherFields), {}};
  metrology::Shot& s = loaded.shot;
  std::error_code ec;
  if (!fs::exists(s.imagePath, ec)) return makeError(path.string() + ": image " + s.imagePath + " does not exist");
  if (auto checked = checkInputFile(s.imagePath, kPhotoInput); !checked) {
    return makeError(path.string() + ": image: " + checked.message());
  }
  if (fs::file_size(s.imagePath, ec) == 0) return makeError(path.string() + ": image " + s.imagePath + " is empty");
  auto decoded = decodeImage(s.imagePath, cv::IMREAD_COLOR);
  if (!decoded) return makeError(path.string() + ": image " + s.imagePath + ": " + decoded.message());
  loaded.image = std::move(decoded->image);
  if (decoded->decoderWarning) loaded.warnings.push_back(*decoded->decoderWarning);
  if (s.imageWidth > 0 && (s.imageWidth != loaded.image.cols || s.imageHeight != loaded.image.rows)) {
    return makeError(path.string() + ": image_size " + std::to_string(s.imageWidth) + "x" + std::to_string(s.imageHeight) +
                     " does not match the image " + s.imagePath + ", which is " + std::to_string(loaded.image.cols) + "x" +
                     std::to_string(loaded.image.rows) + "; the corners belong to another size");
  }
  s.imageWidth = loaded.image.cols;
  s.imageHeight = loaded.image.rows;
  PW_TRY(fillFocal(path, focalPx, assumeFocal, loaded));
  if (s.focalMm) s.focalPx = s.focalMm->pixels(s.imageWidth);
  for (int i = 0; i < kCornerCount; ++i) {
    const glm::dvec2 p = s.cornersPx[i];
    if (p.x < -s.imageWidth || p.x > 2.0 * s.imageWidth || p.y < -s.imageHeight || p.y > 2.0 * s.imageHeight) {
      return makeError(path.string() + ": corner " + metrology::cornerName(i) + " lies far outside the " +
                       std::to_string(s.imageWidth) + "x" + std::to_string(s.imageHeight) + " image");
    }
  }
  return loaded;
}

bool isVanishingPointsOnly(const json& doc) {
  if (!doc.is_object() || doc.contains("corners_px")) return false;
  const auto detection = doc.find("detection");
  if (detection == doc.end() || !detection->is_object()) return false;
  const auto found = detection->find("found");
  return found != detection->end() && found->is_boolean() && !found->get<bool>();
}

namespace {

json shotJson(const fs::path& path, const metrology::Shot& shot, const json& otherFields, bool withCorners) {
  json doc = otherFields.is_object() ? otherFields : json::object();
  for (const char* key : kShotFields) doc.erase(key);
  fs::path image = shot.imagePath;
  std::error_code ec;
  const fs::path base = path.parent_path().empty() ? fs::path(".") : path.parent_path();
  fs::path relative = fs::relative(fs::absolute(image, ec), fs::absolute(base, ec), ec);
  doc["image"] = (!ec && !relative.empty()) ? relative.generic_string() : image.generic_string();
  if (shot.imageWidth > 0) doc["image_size"] = {shot.imageWidth, shot.imageHeight};
  if (shot.focalMm) {
    doc["focal_mm"] = shot.focalMm->focalMm;
    doc["sensor_width_mm"] = shot.focalMm->sensorWidthMm;
  } else if (shot.focalPx > 0) {
    doc["focal_px"] = shot.focalPx;
  }  // else none: as it was read (loadShot takes it from the photo's EXIF)
  if (shot.principalPointPx) doc["principal_point"] = {shot.principalPointPx->x, shot.principalPointPx->y};
  if (shot.cameraHeightM) doc["camera_height_m"] = *shot.cameraHeightM;
  if (withCorners) {
    json corners = json::object();
    for (int i = 0; i < kCornerCount; ++i) corners[metrology::cornerName(i)] = {shot.cornersPx[i].x, shot.cornersPx[i].y};
    doc["corners_px"] = corners;
  }
  if (shot.reference) {
    doc["reference"] = {{"from", metrology::cornerName(shot.reference->from)},
                        {"to", metrology::cornerName(shot.reference->to)},
                        {"length_m", shot.reference->lengthM}};
  }
  if (shot.distortion) doc["distortion"] = {{"k1", shot.distortion->k1}, {"k2", shot.distortion->k2}};
  if (!shot.points.empty()) {
    json points = json::array();
    for (const metrology::ImagePoint& p : shot.points) {
      const std::string on = metrology::surfaceName(p.on.surface) +
                             (p.on.surface == metrology::PointSurface::kAbove ? ":" + p.on.above : std::string());
      points.push_back({{"name", p.name}, {"px", {p.px.x, p.px.y}}, {"on", on}});
    }
    doc["points"] = points;
  }
  if (!shot.measurements.empty()) {
    json measurements = json::array();
    for (const metrology::ObjectMeasure& m : shot.measurements) {
      json entry = {{metrology::quantityName(m.quantity), {m.from, m.to}}};
      if (!m.name.empty()) entry["name"] = m.name;
      measurements.push_back(entry);
    }
    doc["measurements"] = measurements;
  }
  if (!shot.cutouts.empty()) {
    json cutouts = json::array();
    for (const metrology::Cutout& c : shot.cutouts) {
      json outline = json::array();
      for (const glm::dvec2& p : c.outlinePx) outline.push_back({p.x, p.y});
      json cutout = {{"name", c.name}, {"outline_px", outline}};
      if (c.shape == metrology::CutoutShape::kBox) cutout["shape"] = "box";
      if (c.shape == metrology::CutoutShape::kOpening) cutout["shape"] = "opening";
      if (c.shape == metrology::CutoutShape::kHanging) cutout["shape"] = "hanging";
      cutouts.push_back(std::move(cutout));
    }
    doc["cutouts"] = cutouts;
  }
  return doc;
}

}  // namespace

Status writeShotFile(const fs::path& path, const metrology::Shot& shot, const json& otherFields) {
  return writeFileAtomic(path, shotJson(path, shot, otherFields, true).dump(1) + "\n");
}

Status writeVanishingPointsFile(const fs::path& path, const metrology::Shot& shot, const json& otherFields) {
  return writeFileAtomic(path, shotJson(path, shot, otherFields, false).dump(1) + "\n");
}

}  // namespace pw::modeling

namespace pw::modeling {

namespace {

// "+ 0.0" turns -0 into 0, which reads better.
ordered_json vec(const glm::dvec2& v) { return ordered_json::array({v.x + 0.0, v.y + 0.0}); }
ordered_json vec(const glm::dvec3& v) { return ordered_json::array({v.x + 0.0, v.y + 0.0, v.z + 0.0}); }

// A vanishing point as {"px": [u, v]} or, at infinity, {"direction": [du, dv]}.
ordered_json vanishingJson(const metrology::VanishingPoint& vp) {
  ordered_json out = vp.finite ? ordered_json{{"px", vec(vp.px)}} : ordered_json{{"direction", vec(vp.direction)}};
  out["residual_px"] = vp.residualPx;
  return out;
}

// True when every number in the document is finite (nlohmann would print NaN as null).
bool allFinite(const ordered_json& j) {
  if (j.is_number_float()) return std::isfinite(j.get<double>());
  if (j.is_array() || j.is_object()) {
    for (const auto& item : j) {
      if (!allFinite(item)) return false;
    }
  }
  return true;
}

}  // namespace

Result<std::string> measurementJson(const metrology::Measurement& m, const std::string& focalSource,
                                    const std::vector<std::string>& assumptions,
                                    const std::vector<std::string>& warnings) {
  using namespace metrology;
  ordered_json out;
  out["method"] = methodName(m.method);
  out["width_m"] = m.size.widthM;
  out["height_m"] = m.size.heightM;
  out["length_m"] = m.size.lengthM;
  out["sigma_m"] = {{"width_m", m.sigma.widthM}, {"height_m", m.sigma.heightM}, {"length_m", m.sigma.lengthM}};
  out["sigma_corner_px"] = m.cornerSigmaPx;
  {
    // Each source's own sigma and its share of the variance; the one with the most.
    const char* const keys[3] = {"width_m", "height_m", "length_m"};
    ordered_json sources = ordered_json::array();
    for (const SigmaSource& source : m.sigmaSources) {
      ordered_json entry = {{"source", source.key}, {"name", source.name}};
      ordered_json sigma = ordered_json::object(), share = ordered_json::object();
      for (int d = 0; d < 3; ++d) {
        const double s = dimensionOf(source.sigma, d), total = dimensionOf(m.sigma, d);
        sigma[keys[d]] = s;
        share[keys[d]] = total > 0 ? s * s / (total * total) : 0.0;
      }
      entry["sigma_m"] = sigma;
      entry["share"] = share;
      sources.push_back(entry);
    }
    out["sigma_sources"] = sources;
    ordered_json mostly = ordered_json::object(), text = ordered_json::object();
    for (int d = 0; d < 3; ++d) {
      const SigmaSource* top = dominantSigmaSource(m, d);
      mostly[keys[d]] = top ? top->key : "corners";
      text[keys[d]] = dimensionWithSource(m, d);
    }
    out["sigma_mostly"] = mostly;
    out["text"] = text;
  }
  if (!assumptions.empty()) out["assumptions"] = assumptions;
  if (!warnings.empty()) out["warnings"] = warnings;
  out["vanishing_point_px"] = vec(m.vanishing.corridor.px);
  out["vanishing_residual_px"] = m.vanishing.corridor.residualPx;
  out["horizontal_vanishing_point"] = vanishingJson(m.vanishing.horizontal);
  out["vertical_vanishing_point"] = vanishingJson(m.vanishing.vertical);
  out["horizon"] = vec(m.horizon);
  ordered_json rotation = ordered_json::array();
  for (int row = 0; row < 3; ++row) {
    rotation.push_back({m.pose.worldFromCamera[0][row], m.pose.worldFromCamera[1][row], m.pose.worldFromCamera[2][row]});
  }
  out["camera"] = {
      {"height_m", m.cameraHeightM},
      {"focal_px", m.camera.focalPx},
      {"principal_point_px", vec(m.camera.principalPointPx)},
      {"yaw_deg", m.pose.yawDeg},
      {"pitch_deg", m.pose.pitchDeg},
      {"roll_deg", m.pose.rollDeg},
      {"position_m", vec(m.pose.positionM)},
      {"world_from_camera", rotation},
      {"sigma", {{"yaw_deg", m.poseSigma.yawDeg},
                 {"pitch_deg", m.poseSigma.pitchDeg},
                 {"roll_deg", m.poseSigma.rollDeg},
                 {"position_m", vec(m.poseSigma.positionM)}}},
  };
  if (!focalSource.empty()) out["camera"]["focal_source"] = focalSource;
  if (m.distortionSource != DistortionSource::kNone) {
    out["camera"]["distortion"] = {{"k1", m.camera.distortion.k1},
                                   {"k2", m.camera.distortion.k2},
                                   {"source", distortionSourceName(m.distortionSource)}};
  }
  out["reprojection_rms_px"] = m.reprojectionRmsPx;
  ordered_json corners = ordered_json::object(), reprojected = ordered_json::object();
  for (int i = 0; i < kCornerCount; ++i) {
    corners[cornerName(i)] = vec(m.cornersM[i]);
    reprojected[cornerName(i)] = vec(m.reprojectedPx[i]);
  }
  out["corners_m"] = corners;
  out["reprojected_px"] = reprojected;
  if (m.reference) {
    out["reference"] = {{"from", cornerName(m.reference->from)},
                        {"to", cornerName(m.reference->to)},
                        {"given_m", m.reference->givenM},
                        {"measured_m", m.reference->measuredM},
                        {"error_percent", m.reference->errorPercent},
                        {"used_for_scale", m.reference->usedForScale}};
  }
  out["frame"] =
      "metres, right-handed, y up; floor y=0; near corners P5..P8 at z=0, far wall at z=-length; x from -width/2 to "
      "width/2; world_from_camera rows, camera looking along its -z with y up";
  if (!allFinite(out)) return makeError("the measurement holds a number that is not finite; the corners are degenerate");
  return out.dump(1);
}

}  // namespace pw::modeling
