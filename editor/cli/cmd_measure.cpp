// photowalk measure: true dimensions of a corridor from one photo (issue 3).
#include <cstdio>
#include <string>

#include <opencv2/imgcodecs.hpp>

#include "base/atomic_file.h"
#include "editor/cli/command.h"
#include "modeling/shot_file.h"
#include "metrology/measure.h"
#include "metrology/sheet.h"

namespace pw::editor {
namespace {

constexpr const char* kUsage =
    "usage: photowalk measure SHOT.json [--method general|seed] [--sigma-px S] [--sigma-height-m S]\n"
    "                         [--focal-px F] [--sheet OUT.png]\n\n"
    "Measures the corridor's true width, height and length from the shot's photo, focal\n"
    "length, camera height (or reference length) and eight corners, and prints one JSON\n"
    "object: width_m, height_m, length_m, sigma_m, vanishing_point_px, camera {height_m,\n"
    "focal_px, yaw_deg, pitch_deg, roll_deg, position_m, world_from_camera},\n"
    "reprojection_rms_px, corners_m (model frame) and more. The focal length is\n"
    "--focal-px's, else the shot's, else the photo's EXIF (FocalLength with\n"
    "FocalPlaneXResolution, or FocalLengthIn35mmFilm); camera.focal_source says which.\n"
    "A shot's distortion {k1, k2} (OpenCV's radial model) is taken out of the corners\n"
    "first; without one, a distortion the corners' residual shows clearly is estimated\n"
    "(camera.distortion, with its source).\n\n"
    "  --method general   camera with full rotation, box fitted to all eight corners (default)\n"
    "  --method seed      the seed paper's one-point-perspective construction\n"
    "  --sigma-px S       standard deviation of each corner, pixels (default 1)\n"
    "  --sigma-height-m S standard deviation of the camera height, metres (default 0)\n"
    "  --focal-px F       focal length in pixels, instead of the shot's or the EXIF's\n"
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

int runMeasure(Args& args) {
  auto options = parseMeasureOptions(args);
  const std::optional<std::string> sheetPath = args.value("--sheet");
  const std::optional<std::string> focalText = args.value("--focal-px");
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

  auto loaded = modeling::loadShot(shotPath, focalPx);
  if (!loaded) return fail(loaded.message());
  if (sheetPath) {
    if (auto image = checkImageExtension(*sheetPath, "--sheet"); !image) return fail(image.message());
    if (auto distinct = checkNotAnInput(*sheetPath, "--sheet",
                                        {{"the shot", shotPath}, {"the shot's photo", loaded->shot.imagePath}});
        !distinct) {
      return fail(distinct.message());
    }
  }
  auto measurement = metrology::measureCorridor(loaded->shot, *options);
  if (!measurement) return fail(shotPath + ": " + measurement.message());
  auto text = modeling::measurementJson(*measurement, loaded->focalSource);
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
