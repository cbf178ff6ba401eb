// photowalk measure: true dimensions of a corridor from one photo (issue 3).
#include <cmath>
#include <cstdio>
#include <string>

#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "base/atomic_file.h"
#include "editor/cli/command.h"
#include "modeling/shot_file.h"
#include "metrology/input_sigma.h"
#include "metrology/measure.h"
#include "metrology/object_measure.h"
#include "metrology/sheet.h"

namespace pw::editor {
namespace {

constexpr const char* kUsage =
    "usage: photowalk measure SHOT.json [--method general|seed] [--sigma-px S] [--sigma-height-m S]\n"
    "                         [--focal-px F] [--sigma-focal R] [--assume-defaults] [--sheet OUT.png]\n"
    "                         [--point NAME=U,V[@SURFACE] ...] [--distance A,B ...] [--height A,B ...]\n\n"
    "Measures the corridor's true width, height and length from the shot's photo, focal\n"
    "length, camera height (or reference length) and eight corners, and prints one JSON\n"
    "object: width_m, height_m, length_m, sigma_m, sigma_sources, text, vanishing_point_px,\n"
    "camera {height_m, focal_px, yaw_deg, pitch_deg, roll_deg, position_m,\n"
    "world_from_camera}, reprojection_rms_px, corners_m (model frame) and more. The focal\n"
    "length is --focal-px's, else the shot's, else the photo's EXIF (FocalLength with\n"
    "FocalPlaneXResolution, or FocalLengthIn35mmFilm); camera.focal_source says which.\n"
    "A shot's distortion {k1, k2} (OpenCV's radial model) is taken out of the corners\n"
    "first; without one, a distortion the corners' residual shows clearly is estimated\n"
    "(camera.distortion, with its source).\n\n"
    "sigma_m carries every input, each by where it came from (sigma_sources gives each\n"
    "one's sigma and share of the variance, text the dimension as \"2.6 m \u00b1 0.3 (mostly:\n"
    "the assumed focal length)\"): the corners (--sigma-px), the focal length (given:\n"
    "--sigma-focal; EXIF mm: 1%; EXIF 35 mm equivalent: 3%; vanishing points: 21%;\n"
    "assumed: 32%), the camera height (given: --sigma-height-m; assumed: 0.28 m), the\n"
    "principal point (not given: 0.5% of the long side) and the distortion (not given:\n"
    "k1 0.01).\n\n"
    "  --method general   camera with full rotation, box fitted to all eight corners (default)\n"
    "  --method seed      the seed paper's one-point-perspective construction\n"
    "  --sigma-px S       standard deviation of each corner, pixels (default 1)\n"
    "  --sigma-height-m S standard deviation of the given camera height, metres (default 0)\n"
    "  --focal-px F       focal length in pixels, instead of the shot's or the EXIF's\n"
    "  --sigma-focal R    relative standard deviation of a given focal length (0.02: 2%;\n"
    "                     default 0)\n"
    "  --assume-defaults  what the editor assumes for a new photo: without a focal length\n"
    "                     (none given, no EXIF) a 28 mm-equivalent lens (0.8 of the long\n"
    "                     side, \u00b1 32%); without a camera height or reference length\n"
    "                     1.6 m \u00b1 0.28; said in the JSON's assumptions and on stderr\n"
    "  --sheet OUT.png    also draw a measurement sheet: the photo with the corners, the\n"
    "                     receding edges to the vanishing point, the horizon and each\n"
    "                     dimension written on its edge\n\n"
    "Objects in the photo (a door, a picture, a person): points given in the photo's pixels\n"
    "are placed in the corridor's frame (floor y = 0, metres) and measured, each with its\n"
    "\u00b1 (the corners', the camera's and the points' own: --sigma-point-px). The JSON\n"
    "gains points {NAME: {px, on, m, sigma_m, from_camera_m, from_far_wall_m}} and objects\n"
    "[{quantity, from, to, value_m, sigma_m, text, sigma_sources}].\n"
    "  --point NAME=U,V[@SURFACE]  a point and the surface it lies on: floor (the default),\n"
    "                     ceiling, wall:left, wall:right, wall:far, or above:OTHER, on the\n"
    "                     vertical through the point OTHER given before it (a head above\n"
    "                     the feet, a door's top above its sill, a lamp below the ceiling)\n"
    "  --distance A,B     the distance between two points\n"
    "  --height A,B       how far B is above A\n"
    "  --sigma-point-px S standard deviation of each point's u and v, pixels (default 1)\n";

// --point NAME=U,V[@SURFACE]
Result<metrology::ImagePoint> parsePoint(const std::string& text) {
  const std::string form = "--point takes NAME=U,V[@SURFACE] (SURFACE: floor, ceiling, wall:left, wall:right, "
                           "wall:far or above:NAME), not '" + text + "'";
  const size_t equals = text.find('=');
  if (equals == std::string::npos || equals == 0) return makeError(form);
  metrology::ImagePoint point;
  point.name = text.substr(0, equals);
  std::string rest = text.substr(equals + 1), surface = "floor";
  if (const size_t at = rest.find('@'); at != std::string::npos) {
    surface = rest.substr(at + 1);
    rest = rest.substr(0, at);
  }
  const size_t comma = rest.find(',');
  if (comma == std::string::npos) return makeError(form);
  auto u = parseNumber(rest.substr(0, comma), "--point " + point.name + " u");
  if (!u) return u.error();
  auto v = parseNumber(rest.substr(comma + 1), "--point " + point.name + " v");
  if (!v) return v.error();
  point.px = {*u, *v};
  auto on = metrology::surfaceFromName(surface, &point.on.above);
  if (!on) return makeError(form);
  point.on.surface = *on;
  return point;
}

// --distance A,B and --height A,B
Result<metrology::ObjectMeasure> parseObjectMeasure(const std::string& text, metrology::ObjectQuantity quantity) {
  const size_t comma = text.find(',');
  const std::string option = std::string("--") + metrology::quantityName(quantity);
  if (comma == std::string::npos || comma == 0 || comma + 1 == text.size()) {
    return makeError(option + " takes two point names, A,B, not '" + text + "'");
  }
  return metrology::ObjectMeasure{quantity, text.substr(0, comma), text.substr(comma + 1), ""};
}

// The points and objects as measure's JSON has them.
void addObjects(nlohmann::ordered_json& doc, const std::vector<metrology::ImagePoint>& asked,
                const metrology::PointMeasurement& measured) {
  using nlohmann::ordered_json;
  ordered_json points = ordered_json::object();
  for (size_t i = 0; i < measured.points.size(); ++i) {
    const metrology::LocatedPoint& p = measured.points[i];
    const glm::dvec3& s = measured.pointSigmaM[i];
    std::string on = metrology::surfaceName(asked[i].on.surface);
    if (asked[i].on.surface == metrology::PointSurface::kAbove) on += ":" + asked[i].on.above;
    points[p.name] = ordered_json{{"px", {asked[i].px.x, asked[i].px.y}},
                                  {"on", on},
                                  {"m", {p.m.x, p.m.y, p.m.z}},
                                  {"sigma_m", {s.x, s.y, s.z}},
                                  {"from_camera_m", p.fromCameraM},
                                  {"from_far_wall_m", p.fromFarWallM}};
  }
  ordered_json objects = ordered_json::array();
  for (const metrology::ObjectResult& r : measured.results) {
    ordered_json sources = ordered_json::object();
    const std::pair<std::string, double>* top = nullptr;
    for (const auto& source : r.sigmaSources) {
      sources[source.first] = source.second;
      if (!top || source.second > top->second) top = &source;
    }
    std::string text = metrology::dimensionText(r.valueM, r.sigmaM);
    if (top) text += " (mostly: " + top->first + ")";
    objects.push_back(ordered_json{{"quantity", metrology::quantityName(r.asked.quantity)},
                                   {"name", r.asked.name},
                                   {"from", r.asked.from},
                                   {"to", r.asked.to},
                                   {"value_m", r.valueM},
                                   {"sigma_m", r.sigmaM},
                                   {"text", text},
                                   {"sigma_sources", sources}});
  }
  doc["points"] = points;
  doc["objects"] = objects;
}

Result<metrology::MeasureOptions> parseMeasureOptions(Args& args) {
  metrology::MeasureOptions options;
  if (auto method = args.value("--method")) {
    if (*method == "general") options.method = metrology::Method::kGeneral;
    else if (*method == "seed") options.method = metrology::Method::kSeed;
    else return makeError("--method must be general or seed, not '" + *method + "'");
  }
  if (auto sigma = args.value("--sigma-px")) {
    auto v = parseNumber(*sigma, "--sigma-px");
    if (!v) return v.error();
    if (*v < 0) return makeError("--sigma-px must be >= 0");
    options.cornerSigmaPx = *v;
  }
  if (auto sigma = args.value("--sigma-height-m")) {
    auto v = parseNumber(*sigma, "--sigma-height-m");
    if (!v) return v.error();
    if (*v < 0) return makeError("--sigma-height-m must be >= 0");
    options.cameraHeightSigmaM = *v;
  }
  return options;
}

// The stated relative sigma of a given focal length (--sigma-focal).
Result<double> parseFocalSigma(const std::optional<std::string>& text) {
  if (!text) return 0.0;
  auto v = parseNumber(*text, "--sigma-focal");
  if (!v) return v.error();
  if (!(*v >= 0) || *v > 1) return makeError("--sigma-focal is relative: a number from 0 to 1 (0.02 is 2%)");
  return *v;
}

int runMeasure(Args& args) {
  auto options = parseMeasureOptions(args);
  const std::optional<std::string> sheetPath = args.value("--sheet");
  const std::optional<std::string> focalText = args.value("--focal-px");
  const std::optional<std::string> focalSigmaText = args.value("--sigma-focal");
  const bool assumeDefaults = args.flag("--assume-defaults");
  const std::vector<std::string> pointTexts = args.values("--point");
  const std::vector<std::string> distanceTexts = args.values("--distance");
  const std::vector<std::string> heightTexts = args.values("--height");
  const std::optional<std::string> pointSigmaText = args.value("--sigma-point-px");
  const std::vector<std::string> positionals = args.positionals();
  if (auto finished = args.finish(); !finished) return fail(finished.message());
  if (!options) return fail(options.message());
  if (positionals.size() != 1) return fail("measure takes one shot file; see photowalk measure --help");
  const std::string& shotPath = positionals[0];

  std::optional<double> focalPx;
  if (focalText) {
    auto f = parseNumber(*focalText, "--focal-px");
    if (!f) return fail(f.message());
    if (!(*f > 0)) return fail("--focal-px must be positive");
    focalPx = *f;
  }

  auto focalSigma = parseFocalSigma(focalSigmaText);
  if (!focalSigma) return fail(focalSigma.message());
  std::vector<metrology::ImagePoint> points;
  for (const std::string& text : pointTexts) {
    auto point = parsePoint(text);
    if (!point) return fail(point.message());
    points.push_back(*point);
  }
  std::vector<metrology::ObjectMeasure> objects;
  for (const auto& [texts, quantity] : {std::pair{&distanceTexts, metrology::ObjectQuantity::kDistance},
                                        std::pair{&heightTexts, metrology::ObjectQuantity::kHeight}}) {
    for (const std::string& text : *texts) {
      auto asked = parseObjectMeasure(text, quantity);
      if (!asked) return fail(asked.message());
      objects.push_back(*asked);
    }
  }
  double pointSigmaPx = 1.0;
  if (pointSigmaText) {
    auto v = parseNumber(*pointSigmaText, "--sigma-point-px");
    if (!v) return fail(v.message());
    if (!(*v >= 0)) return fail("--sigma-point-px must be >= 0");
    pointSigmaPx = *v;
  }

  auto loaded = modeling::loadShot(shotPath, focalPx, assumeDefaults);
  if (!loaded) return fail(loaded.message());
  for (const std::string& warning : loaded->warnings) printWarning(warning);
  // The shot file's own points and measurements first, then the command line's.
  points.insert(points.begin(), loaded->shot.points.begin(), loaded->shot.points.end());
  objects.insert(objects.begin(), loaded->shot.measurements.begin(), loaded->shot.measurements.end());
  if (sheetPath) {
    if (auto image = checkImageExtension(*sheetPath, "--sheet"); !image) return fail(image.message());
    if (auto distinct = checkNotAnInput(*sheetPath, "--sheet",
                                        {{"the shot", shotPath}, {"the shot's photo", loaded->shot.imagePath}});
        !distinct) {
      return fail(distinct.message());
    }
  }
  if (!objects.empty() && points.empty()) return fail("--distance and --height measure between points given by --point");
  std::vector<std::string> assumptions;
  metrology::InputOrigins origins;
  origins.focal = metrology::focalOriginOf(loaded->focalSource);
  origins.givenFocalSigmaRelative = *focalSigma;
  if (origins.focal == metrology::FocalOrigin::kAssumed) {
    assumptions.push_back("focal length " + std::to_string(static_cast<int>(std::lround(loaded->shot.focalPx))) +
                          " px: a 28 mm-equivalent lens, \u00b1 " +
                          std::to_string(static_cast<int>(std::lround(100 * metrology::kAssumedFocalSigmaRelative))) + "%");
  }
  if (assumeDefaults && !loaded->shot.cameraHeightM && !loaded->shot.reference) {
    loaded->shot.cameraHeightM = metrology::kAssumedCameraHeightM;
    origins.cameraHeightAssumed = true;
    char line[96];
    std::snprintf(line, sizeof line, "camera height %.1f m \u00b1 %.2f: a standing person's",
                  metrology::kAssumedCameraHeightM, metrology::kAssumedCameraHeightSigmaM);
    assumptions.push_back(line);
  }
  for (const std::string& a : assumptions) std::fprintf(stderr, "measure: assumed %s\n", a.c_str());
  const metrology::MeasureOptions withSigmas = metrology::withInputSigmas(*options, loaded->shot, origins);
  auto measurement = metrology::measureCorridor(loaded->shot, withSigmas);
  if (!measurement) return fail(shotPath + ": " + measurement.message());
  std::vector<std::string> warnings;
  if (auto large = metrology::implausibleSize(loaded->shot, *measurement)) {
    warnings.push_back(*large);
    printWarning(shotPath + ": " + *large);
  }
  auto text = modeling::measurementJson(*measurement, loaded->focalSource, assumptions, warnings);
  if (!text) return fail(shotPath + ": " + text.message());
  std::vector<metrology::SheetPoint> sheetPoints;
  std::vector<metrology::SheetObject> sheetObjects;
  if (!points.empty()) {
    auto measured = metrology::measurePoints(loaded->shot, withSigmas, *measurement, points, objects, pointSigmaPx);
    if (!measured) return fail(shotPath + ": " + measured.message());
    auto doc = nlohmann::ordered_json::parse(*text);
    addObjects(doc, points, *measured);
    text = doc.dump(1);
    for (const metrology::ImagePoint& p : points) sheetPoints.push_back({p.name, p.px});
    const auto pixelOf = [&](const std::string& name) {
      for (const metrology::ImagePoint& p : points)
        if (p.name == name) return p.px;
      return glm::dvec2(0.0);
    };
    for (const metrology::ObjectResult& r : measured->results) {
      const std::string name = r.asked.quantity == metrology::ObjectQuantity::kHeight ? "H " : "";
      sheetObjects.push_back({pixelOf(r.asked.from), pixelOf(r.asked.to),
                              name + metrology::dimensionText(r.valueM, r.sigmaM, "+/-")});
    }
  }

  if (sheetPath) {
    auto sheet = metrology::drawMeasurementSheet(loaded->image, loaded->shot, *measurement, sheetPoints, sheetObjects);
    if (!sheet) return fail(shotPath + ": " + sheet.message());
    Status written = writeViaTempFile(*sheetPath, [&](const std::filesystem::path& temp) -> Status {
      bool ok = false;
      try {
        ok = cv::imwrite(temp.string(), *sheet);
      } catch (const cv::Exception&) {
        ok = false;
      }
      if (!ok) return makeError(*sheetPath + ": cannot write the sheet (use a .png or .jpg name)");
      return {};
    });
    if (!written) return fail(written.message());
  }
  std::printf("%s\n", text->c_str());
  return kExitOk;
}

}  // namespace

PW_COMMAND(measure, "measure", "true width, height and length of a corridor from one photo", kUsage, runMeasure);

}  // namespace pw::editor
