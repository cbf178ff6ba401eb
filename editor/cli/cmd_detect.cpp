// photowalk detect: the corridor's vanishing points and eight corners, found
// automatically in one photo and written as a shot file (issue 7).
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "base/atomic_file.h"
#include "base/input_file.h"
#include "editor/cli/command.h"
#include "editor/edit/detection_report.h"
#include "modeling/exif.h"
#include "modeling/shot_file.h"
#include "metrology/detect/detect.h"
#include "metrology/detect/overlay.h"

namespace pw::editor {
namespace {
namespace fs = std::filesystem;
using nlohmann::json;
using metrology::detect::CorridorDetection;

constexpr const char* kUsage =
    "usage: photowalk detect PHOTO -o SHOT.json [--focal-px F] [--principal-point U,V]\n"
    "                        [--camera-height H] [--near-at-marked] [--distortion K1[,K2]]\n"
    "                        [--overlay OUT.png]\n"
    "       photowalk detect --hint ROUGH.json -o SHOT.json [--hint-reach PX] [--distortion K1[,K2]]\n"
    "                        [--overlay OUT.png]\n\n"
    "Finds the corridor in the photo: its vanishing points (the Manhattan frame), the\n"
    "four receding floor and ceiling edges, the far wall's corners P1..P4 and the near\n"
    "corners P5..P8, each refined to sub-pixel precision on the image's edges, and\n"
    "writes a shot file ready for measure, build and the editor, with a \"detection\"\n"
    "object giving each vanishing point's and each corner's confidence (0..1). A lens\n"
    "that bends the photo's straight lines is fitted to them (the plumb-line method) and\n"
    "written as the shot's distortion {k1, k2}; detection then runs on the photo\n"
    "undistorted and the corners are the photo's own pixels.\n\n"
    "  -o, --output SHOT.json  the shot file to write (the image path in it is relative)\n"
    "  --focal-px F            focal length in pixels; without it, the photo's EXIF gives\n"
    "                          it (FocalLength with FocalPlaneXResolution, or\n"
    "                          FocalLengthIn35mmFilm), else it is estimated from a second\n"
    "                          finite vanishing point, or a 28 mm-equivalent default is\n"
    "                          assumed (with a warning); the shot's focal_source says which\n"
    "  --principal-point U,V   in pixels (default: the image centre)\n"
    "  --camera-height H       camera height above the floor, metres (measure needs it,\n"
    "                          or a reference length added in the editor)\n"
    "  --near-at-marked        put P5..P8 on a band or frame marking a cross-section\n"
    "                          across the corridor, when one is found; by default they\n"
    "                          go to the nearest depth where all four stay inside the\n"
    "                          photo (the shot's detection.near_depth says which:\n"
    "                          image_edge or marked_cross_section; --near-at-image-edge,\n"
    "                          now the default, is still accepted)\n"
    "  --distortion K1[,K2]    the lens's radial distortion when it is known (a calibrated\n"
    "                          camera; OpenCV's k1, k2, normalised by the focal length):\n"
    "                          the photo is read through it, no lens is fitted, and the\n"
    "                          shot keeps it; 0 says the lens has none. With --hint it\n"
    "                          takes the rough shot's distortion's place\n"
    "  --overlay OUT.png       also draw what was found on the photo (corners ringed by\n"
    "                          confidence: green >= 0.7, amber >= 0.4, red below)\n"
    "  --hint ROUGH.json       a shot whose corners a person placed roughly (within 10-20\n"
    "                          px): they come back fitted to the photo's edges and\n"
    "                          vanishing points, each with its confidence; the shot's\n"
    "                          other fields (camera, reference, ...) are kept. The photo,\n"
    "                          focal length, principal point and lens distortion are\n"
    "                          the shot's (a shot without a distortion has the lens\n"
    "                          fitted to the photo's straight lines, as without --hint)\n"
    "  --hint-reach PX         how far from where it was put a side is looked for (25)\n\n"
    "Exit status: 0 written, and detect is sure of it; 3 written, but unsure: a best\n"
    "guess for a person to check in the editor (a warning line on stderr says why);\n"
    "1 bad input (one line on stderr); 2 no corridor's box found in the photo: the\n"
    "vanishing points it did find are printed and, with -o, written to SHOT.json without\n"
    "corners (\"detection\": {\"found\": false, ...}; the editor opens it and places a box\n"
    "along them; measure and build refuse it), or nothing is written when it found none.\n";

Result<glm::dvec2> parsePoint(const std::string& text, const char* option) {
  const size_t comma = text.find(',');
  if (comma == std::string::npos) return makeError(std::string(option) + " wants U,V in pixels, e.g. 399.5,299.5");
  auto u = parseNumber(std::string_view(text).substr(0, comma), option);
  auto v = parseNumber(std::string_view(text).substr(comma + 1), option);
  if (!u || !v) return makeError(std::string(option) + " wants U,V in pixels, e.g. 399.5,299.5, not '" + text + "'");
  return glm::dvec2(*u, *v);
}

// --distortion K1[,K2]: finite, within the range shot files take (-2..2).
Result<metrology::RadialDistortion> parseDistortion(const std::string& text) {
  const size_t comma = text.find(',');
  auto k1 = parseNumber(std::string_view(text).substr(0, comma), "--distortion");
  if (!k1) return k1.error();
  metrology::RadialDistortion lens{*k1, 0.0};
  if (comma != std::string::npos) {
    auto k2 = parseNumber(std::string_view(text).substr(comma + 1), "--distortion");
    if (!k2) return k2.error();
    lens.k2 = *k2;
  }
  if (!(std::abs(lens.k1) <= metrology::kMaxDistortionCoefficient && std::abs(lens.k2) <= metrology::kMaxDistortionCoefficient)) {
    return makeError("--distortion " + text + ": k1 and k2 must lie within -2..2 (OpenCV's model, normalised by the focal length)");
  }
  return lens;
}

std::string homogeneousText(const metrology::detect::VanishingPoint& vp) {
  char text[96];
  if (vp.isFinite()) {
    std::snprintf(text, sizeof text, "(%.1f, %.1f)", vp.pixel().x, vp.pixel().y);
  } else {
    std::snprintf(text, sizeof text, "at infinity towards (%.3f, %.3f)", vp.point.x, vp.point.y);
  }
  return text;
}

Status writeOverlay(const std::string& path, const cv::Mat& photo, const CorridorDetection& detection) {
  const cv::Mat overlay = metrology::detect::drawDetection(photo, detection);
  return writeViaTempFile(path, [&](const fs::path& temp) -> Status {
    bool ok = false;
    try {
      ok = cv::imwrite(temp.string(), overlay);
    } catch (const cv::Exception&) {
      ok = false;
    }
    if (!ok) return makeError(path + ": cannot write the overlay (use a .png or .jpg name)");
    return {};
  });
}

int runDetect(Args& args) {
  const std::optional<std::string> output = args.value("--output", "-o");
  const std::optional<std::string> focal = args.value("--focal-px");
  const std::optional<std::string> principal = args.value("--principal-point");
  const std::optional<std::string> height = args.value("--camera-height");
  const std::optional<std::string> overlayPath = args.value("--overlay");
  const std::optional<std::string> hintPath = args.value("--hint");
  const std::optional<std::string> hintReach = args.value("--hint-reach");
  const std::optional<std::string> lensText = args.value("--distortion");
  metrology::detect::DetectOptions options;
  options.nearAtMarkedCrossSection = args.flag("--near-at-marked");
  if (args.flag("--near-at-image-edge")) options.nearAtMarkedCrossSection = false;
  const std::vector<std::string> positionals = args.positionals();
  if (auto finished = args.finish(); !finished) return fail(finished.message());
  if (hintPath ? positionals.size() > 1 : positionals.size() != 1) {
    return fail("detect takes one photo (or --hint SHOT.json); see photowalk detect --help");
  }
  if (!output) return fail("detect needs -o SHOT.json, the shot file to write");
  if (focal) {
    auto f = parseNumber(*focal, "--focal-px");
    if (!f) return fail(f.message());
    if (*f <= 0) return fail("--focal-px must be positive");
    options.focalPx = *f;
  }
  if (principal) {
    auto p = parsePoint(*principal, "--principal-point");
    if (!p) return fail(p.message());
    options.principalPointPx = *p;
  }
  std::optional<double> cameraHeightM;
  if (height) {
    auto h = parseNumber(*height, "--camera-height");
    if (!h) return fail(h.message());
    if (*h <= 0) return fail("--camera-height must be positive (metres)");
    cameraHeightM = *h;
  }
  if (hintReach) {
    auto r = parseNumber(*hintReach, "--hint-reach");
    if (!r) return fail(r.message());
    if (!(*r >= 2 && *r <= 200)) return fail("--hint-reach " + *hintReach + " px: expected 2-200 px");
    options.hintReachPx = *r;
  }

  std::optional<metrology::RadialDistortion> lensGiven;
  if (lensText) {
    auto lens = parseDistortion(*lensText);
    if (!lens) return fail(lens.message());
    lensGiven = *lens;
  }

  // A rough shot: its photo, camera and other fields; its corners the hint.
  metrology::Shot shot;
  json keptFields = json::object();
  if (hintPath) {
    auto hinted = modeling::readShotFile(*hintPath, &keptFields);
    if (!hinted) return fail(hinted.message());
    shot = std::move(*hinted);
    options.hintPx = shot.cornersPx;
    if (!options.focalPx && shot.focalPx > 0) options.focalPx = shot.focalPx;
    if (!options.principalPointPx && shot.principalPointPx) options.principalPointPx = shot.principalPointPx;
    if (!cameraHeightM) cameraHeightM = shot.cameraHeightM;
    options.lens = shot.distortion;
    keptFields.erase("detection");
  }
  if (lensGiven) {
    options.lens = lensGiven;
    shot.distortion = lensGiven;
  }
  const std::string photoPath = positionals.empty() ? shot.imagePath : positionals[0];
  std::error_code ec;
  if (!fs::is_regular_file(photoPath, ec)) return fail(photoPath + ": no such file");
  std::vector<NamedInput> inputs{{"the photo", photoPath}};
  if (hintPath) inputs.push_back({"the --hint shot", *hintPath});
  if (auto distinct = checkNotAnInput(*output, "-o", inputs); !distinct) return fail(distinct.message());
  if (overlayPath) {
    if (auto distinct = checkNotAnInput(*overlayPath, "--overlay", inputs); !distinct) return fail(distinct.message());
  }
  // The photo as shown (its EXIF orientation applied, as every reader of the shot
  // applies it), and the EXIF focal length when none is given.
  auto read = modeling::readPhoto(photoPath);
  if (!read) return fail(read.message());
  const cv::Mat& photo = read->bgr;
  for (const std::string& warning : read->warnings) printWarning(warning);
  for (const std::string& note : read->notes) printNote(note);
  std::optional<modeling::ExifFocal> exifFocal;
  if (!options.focalPx && read->focal) {
    exifFocal = read->focal;
    options.focalPx = exifFocal->focalPx;
  }
  if (options.lens && !options.lens->isNone() && !options.focalPx) {
    return fail("--distortion is normalised by the focal length: give it too (--focal-px F), as the photo's EXIF does not");
  }
  if (hintPath && shot.imageWidth > 0 && (shot.imageWidth != photo.cols || shot.imageHeight != photo.rows)) {
    return fail(*hintPath + ": its image_size is " + std::to_string(shot.imageWidth) + "x" +
                std::to_string(shot.imageHeight) + " but " + photoPath + " is " + std::to_string(photo.cols) + "x" +
                std::to_string(photo.rows));
  }

  auto detection = metrology::detect::detectCorridor(photo, options);
  if (!detection) return fail(photoPath + ": " + detection.message());
  for (const std::string& warning : detection->warnings) printWarning(warning);

  const std::string focalSource = exifFocal ? exifFocal->source
                                  : hintPath && !focal ? std::string("shot")
                                                       : metrology::detect::focalSourceName(detection->focalSource);
  shot.imagePath = photoPath;
  shot.imageWidth = photo.cols;
  shot.imageHeight = photo.rows;
  shot.focalPx = detection->focalPx;
  if (exifFocal && exifFocal->focalMm) {
    shot.focalMm = exifFocal->focalMm;  // kept in the EXIF's millimetres
  } else if (shot.focalMm && std::abs(shot.focalMm->pixels(shot.imageWidth) - shot.focalPx) > 1e-6 * shot.focalPx) {
    shot.focalMm.reset();  // a focal length other than the shot's millimetres: written in pixels
  }
  shot.principalPointPx = detection->principalPointPx;
  shot.cameraHeightM = cameraHeightM;
  keptFields["focal_source"] = focalSource;
  keptFields["detection"] = edit::detectionReport(*detection, options.lens.has_value(), exifFocal.has_value());

  if (!detection->found) {
    std::fprintf(stderr, "%s\n", escapeControls("no corridor found in " + photoPath + ": " + detection->notFoundReason).c_str());
    if (!detection->hasVanishingPoints) return kExitNotFound;
    std::printf("vanishing points (focal %.1f px, %s): corridor %s, horizontal %s, vertical %s\n", detection->focalPx,
                focalSource.c_str(), homogeneousText(detection->corridor).c_str(),
                homogeneousText(detection->horizontal).c_str(), homogeneousText(detection->vertical).c_str());
    if (Status written = modeling::writeVanishingPointsFile(*output, shot, keptFields); !written) {
      return fail(written.message());
    }
    std::printf("wrote %s: the vanishing points, no corners (place them in the editor: photowalk edit %s)\n",
                output->c_str(), output->c_str());
    return kExitNotFound;
  }

  if (!detection->distortion.isNone()) shot.distortion = detection->distortion;
  for (int k = 0; k < metrology::kCornerCount; ++k) shot.cornersPx[k] = detection->corners[k].px;
  if (Status written = modeling::writeShotFile(*output, shot, keptFields); !written) return fail(written.message());
  if (overlayPath) {
    if (Status drawn = writeOverlay(*overlayPath, photo, *detection); !drawn) return fail(drawn.message());
  }
  const glm::dvec2 vp = detection->corridor.pixel();
  std::printf("corridor vanishing point (%.2f, %.2f), confidence %.2f; focal %.1f px (%s)\n", vp.x, vp.y,
              detection->corridor.confidence, detection->focalPx, focalSource.c_str());
  if (options.lens && !options.lens->isNone()) {
    std::printf("lens distortion %s (%s); the corners are the photo's\n", metrology::distortionText(*options.lens).c_str(),
                lensGiven ? "given" : "the shot's");
  } else if (!detection->distortion.isNone()) {
    std::printf("lens distortion k1 %.4f (from %d straight lines); the corners are the photo's\n",
                detection->distortion.k1, detection->plumbLineCount);
  }
  for (int k = 0; k < metrology::kCornerCount; ++k) {
    const auto& c = detection->corners[k];
    if (options.hintPx) {
      std::printf("  %s (%8.2f, %8.2f)  confidence %.2f  moved %.1f px\n", metrology::cornerName(k), c.px.x, c.px.y,
                  c.confidence, glm::length(c.px - (*options.hintPx)[k]));
    } else {
      std::printf("  %s (%8.2f, %8.2f)  confidence %.2f\n", metrology::cornerName(k), c.px.x, c.px.y, c.confidence);
    }
  }
  const char* nearText = detection->nearDepth == metrology::detect::NearDepth::kMarkedCrossSection
                             ? "marked cross-section"
                         : detection->nearDepth == metrology::detect::NearDepth::kGiven
                             ? "depth they were given"
                             : "nearest depth inside the photo";
  std::printf("wrote %s (P5..P8 at the %s)\n", output->c_str(), nearText);
  if (!cameraHeightM && !shot.reference) {
    printNote("no --camera-height: add camera_height_m (or a reference) to " + *output + " before measure");
  }
  if (!detection->confident) {
    std::string why;
    for (const std::string& doubt : detection->doubts) why += (why.empty() ? "" : "; ") + doubt;
    printWarning("unsure of this corridor, check it in the editor (photowalk edit " + *output + "): " + why);
    return kExitUnsure;
  }
  return kExitOk;
}

}  // namespace

PW_COMMAND(detect, "detect", "find the corridor's vanishing points and corners in a photo; write a shot", kUsage,
           runDetect);

}  // namespace pw::editor
