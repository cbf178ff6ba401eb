// Shot files (JSON): what `measure`, `build` and `detect` read and the editor saves.
// See the README for the format. Unknown fields are ignored (the shared corridor
// scenes carry ground truth there, which photowalk never reads).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <opencv2/core/mat.hpp>

#include "base/result.h"
#include "metrology/measure.h"
#include "metrology/shot.h"

namespace pw::modeling {

// Parses the shot file and checks every number is present, finite and sensible.
// Does not open the image; `shot.imagePath` is resolved against the file's folder.
// A shot without a focal length comes back with focalPx 0 and no focalMm (loadShot
// takes it from the photo's EXIF).
// `otherFields` (may be null) receives the fields photowalk does not read (a JSON
// object), so that a shot written back keeps them.
// `allowNoScale`: a shot without camera_height_m and reference is read (the caller
// assumes a height; measure --assume-defaults), else refused.
Result<metrology::Shot> readShotFile(const std::filesystem::path& path, nlohmann::json* otherFields = nullptr,
                                     bool allowNoScale = false);

// Reads the shot file and its image (BGR, 8 bit), filling imageWidth/imageHeight and
// checking the corners against the image size. The focal length is `focalPx` when
// given (the command line's), else the shot's, else the photo's EXIF (exif.h's
// exifFocal: FocalLength with FocalPlaneXResolution, or FocalLengthIn35mmFilm); with
// none of them it is an error, unless `assumeFocal`: then a 28 mm-equivalent lens
// (input_sigma.h's kAssumedFocalOverLongSide), focalSource "assumed: ...", and a shot
// without a camera height or reference length is read too (readShotFile's allowNoScale).
struct LoadedShot {
  metrology::Shot shot;
  cv::Mat image;
  nlohmann::json otherFields = nlohmann::json::object();  // as readShotFile gives them
  // Where the focal length came from: "given", the shot's own `focal_source` (or
  // "shot" when it has none), or the EXIF's line ("EXIF FocalLength 4.20 mm with ...").
  std::string focalSource;
  // What the image decoder warned of in a photo it still read whole (image_decode.h),
  // for the caller to show as warnings.
  std::vector<std::string> warnings;
};
// `allowNoScale`: a shot without a camera height or reference length is read too, the
// focal length still required (the editor, which assumes a height and says so).
Result<LoadedShot> loadShot(const std::filesystem::path& path, std::optional<double> focalPx = std::nullopt,
                            bool assumeFocal = false, bool allowNoScale = false);

// Writes a shot file atomically: `otherFields` (a JSON object, e.g. LoadedShot's) and
// the shot's own fields, which replace any of the same name. The image path is
// written relative to the shot file's folder where possible; the focal length in the
// units it was read in (focal_mm with sensor_width_mm, or focal_px).
Status writeShotFile(const std::filesystem::path& path, const metrology::Shot& shot,
                     const nlohmann::json& otherFields = nlohmann::json::object());

// What `detect` writes when it finds a photo's vanishing points but no corridor's box:
// the shot's fields without corners_px, beside `otherFields` (its "detection" object,
// with "found": false). readShotFile refuses it, naming the editor as the way on; the
// editor opens its photo.
Status writeVanishingPointsFile(const std::filesystem::path& path, const metrology::Shot& shot,
                                const nlohmann::json& otherFields);
// Whether a parsed shot file is such a file (no corners_px; detection.found false).
bool isVanishingPointsOnly(const nlohmann::json& doc);

// The measurement as one JSON object (what `photowalk measure` prints): width_m,
// height_m, length_m, sigma_m {...}, vanishing_point_px, camera {height_m, focal_px,
// yaw_deg, pitch_deg, roll_deg, position_m, world_from_camera, sigma}, horizon,
// reprojection_rms_px, corners_m, reprojected_px, reference (when given); the camera's
// focal_source when `focalSource` is not empty (LoadedShot's), its distortion {k1, k2,
// source} when it has one; sigma_sources [{source, name, sigma_m {width_m, height_m,
// length_m}, share {...: the source's part of the variance}}], sigma_mostly {width_m:
// the source with the largest share, ...}, text {width_m: "2.6 m ± 0.3 (mostly: the
// assumed focal length)", ...}, `assumptions` (what was assumed for a missing input)
// and `warnings` (what to check before trusting it: metrology::implausibleSize) when
// not empty. Fails rather than print a NaN or infinity.
Result<std::string> measurementJson(const metrology::Measurement& measurement, const std::string& focalSource = "",
                                    const std::vector<std::string>& assumptions = {},
                                    const std::vector<std::string>& warnings = {});

}  // namespace pw::modeling
