// photowalk measure: true dimensions of a corridor from one photo (issue 3).
#include <cmath>
#include <cstdio>
#include <string>

#include <opencv2/imgcodecs.hpp>

#include "base/atomic_file.h"
#include "editor/cli/command.h"
#include "modeling/shot_file.h"
#include "metrology/input_sigma.h"
#include "metrology/measure.h"
#include "metrology/sheet.h"

namespace pw::editor {
namespace {

constexpr const char* kUsage =
    "usage: photowalk measure SHOT.json [--method general|seed] [--sigma-px S] [--sigma-height-m S]\n"
    "                         [--focal-px F] [--sigma-focal R] [--assume-defaults] [--sheet OUT.png]\n\n"
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
    "                     dimension written on its edge\n";

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

  auto loaded = modeling::loadShot(shotPath, focalPx, assumeDefaults);
  if (!loaded) return fail(loaded.message());
  if (sheetPath) {
    if (auto image = checkImageExtension(*sheetPath, "--sheet"); !image) return fail(image.message());
    if (auto distinct = checkNotAnInput(*sheetPath, "--sheet",
                                        {{"the shot", shotPath}, {"the shot's photo", loaded->shot.imagePath}});
        !distinct) {
      return fail(distinct.message());
    }
  }
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
  auto text = modeling::measurementJson(*measurement, loaded->focalSource, assumptions);
  if (!text) return fail(shotPath + ": " + text.message());

  if (sheetPath) {
    auto sheet = metrology::drawMeasurementSheet(loaded->image, loaded->shot, *measurement);
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
