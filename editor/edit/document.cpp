#include "editor/edit/document.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>

#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "base/input_file.h"
#include "editor/edit/autosave.h"
#include "editor/edit/detection_report.h"
#include "metrology/detect/detect.h"
#include "modeling/image_decode.h"
#include "modeling/shot_file.h"

namespace pw::edit {
namespace fs = std::filesystem;
using metrology::kCornerCount;
using metrology::Shot;

void History::push(Step step) {
  steps_.resize(next_);
  steps_.push_back(std::move(step));
  next_ = steps_.size();
}

const History::Step* History::undo() {
  if (!canUndo()) return nullptr;
  return &steps_[--next_];
}

const History::Step* History::redo() {
  if (!canRedo()) return nullptr;
  return &steps_[next_++];
}

std::array<glm::dvec2, kCornerCount> defaultCorners(int w, int h) {
  const double x0 = 0.1 * w, x1 = 0.9 * w, y0 = 0.1 * h, y1 = 0.9 * h;  // near cross-section
  const double fx0 = 0.4 * w, fx1 = 0.6 * w, fy0 = 0.4 * h, fy1 = 0.6 * h;  // far wall
  std::array<glm::dvec2, kCornerCount> c{};
  c[metrology::P1] = {fx0, fy0};
  c[metrology::P2] = {fx1, fy0};
  c[metrology::P3] = {fx0, fy1};
  c[metrology::P4] = {fx1, fy1};
  c[metrology::P5] = {x0, y1};
  c[metrology::P6] = {x1, y1};
  c[metrology::P7] = {x0, y0};
  c[metrology::P8] = {x1, y0};
  return c;
}

namespace {

// The photo of a shot file that `detect` wrote without corners (vanishing points only).
std::optional<fs::path> vanishingPointsOnlyPhoto(const fs::path& path) {
  auto text = readInputFile(path, kShotInput);  // a regular file of at most 16 MiB
  if (!text) return std::nullopt;
  const nlohmann::json doc = nlohmann::json::parse(*text, nullptr, /*allow_exceptions=*/false);
  if (!modeling::isVanishingPointsOnly(doc) || !doc.contains("image") || !doc["image"].is_string()) return std::nullopt;
  const fs::path image = doc["image"].get<std::string>();
  return image.is_absolute() ? image : path.parent_path() / image;
}

bool isShotFile(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char ch) { return std::tolower(ch); });
  return ext == ".json";
}

std::string fixed(double value, int decimals) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

// A corner read back from a shot file is where detection put it within this (JSON keeps
// doubles exactly: the file's corners_px and the report's px are the same numbers).
constexpr double kSameCornerPx = 1e-6;

}  // namespace

Result<Document> Document::open(const fs::path& path, const OpenOptions& options) {
  Document doc;
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) return makeError(path.string() + ": no such file");
  if (isShotFile(path)) {
    // detect's file for a photo with vanishing points but no box: open its photo, to be
    // saved here once the corners are placed.
    if (auto photo = vanishingPointsOnlyPhoto(path)) {
      OpenOptions photoOptions = options;
      photoOptions.photoShotPath = path;
      return open(*photo, photoOptions);
    }
    // (A shot without a camera height or reference, as `detect` writes one without
    // --camera-height, opens with the height assumed, as a photo does, and says so.)
    auto loaded = modeling::loadShot(path, std::nullopt, /*assumeFocal=*/false, /*allowNoScale=*/true);
    if (!loaded) return loaded.error();
    doc.path_ = path;
    doc.shot_ = std::move(loaded->shot);
    doc.scaleFromFile_ = doc.shot_.cameraHeightM || doc.shot_.reference;
    if (!doc.scaleFromFile_) doc.shot_.cameraHeightM = kDefaultCameraHeightM;
    doc.photo_ = std::move(loaded->image);
    doc.notes_ = std::move(loaded->warnings);
    doc.otherFields_ = std::move(loaded->otherFields);
    // Detection's report, as `detect` writes it (and the editor, for a photo it opened).
    if (const auto report = readDetectionReport(doc.otherFields_)) doc.takeDetection(*report);
    doc.saved_ = doc.shot_;
    // The photo's EXIF, to show beside the shot's own camera (loadShot's photo is
    // oriented as shown, so the stored size is the shown one turned back).
    doc.exif_ = modeling::readExif(doc.shot_.imagePath);
    const bool swap = modeling::orientationSwapsAxes(doc.exif_.orientation);
    doc.exifFocal_ = modeling::exifFocal(doc.exif_, swap ? doc.photo_.rows : doc.photo_.cols,
                                         swap ? doc.photo_.cols : doc.photo_.rows);
    doc.fromFile_ = true;
    doc.openedFocalPx_ = doc.shot_.focalPx;
    doc.openedFocalMm_ = doc.shot_.focalMm;
    const auto source = doc.otherFields_.find("focal_source");
    doc.openedFocalSource_ =
        source != doc.otherFields_.end() && source->is_string() ? source->get<std::string>() : "the shot file";
    doc.opened_ = doc.shot_;
    return doc;
  }

  auto photo = modeling::readPhoto(path);
  if (!photo) {
    // (A file that is neither: say that a shot file opens too.)
    const bool unreadable = photo.message().find(modeling::kUnreadableImage) != std::string::npos;
    return makeError(photo.message() + (unreadable ? "; nor a shot file (*.json)" : ""));
  }
  doc.photo_ = std::move(photo->bgr);
  doc.exif_ = std::move(photo->exif);
  doc.exifFocal_ = std::move(photo->focal);
  for (const std::string& warning : photo->warnings) doc.notes_.push_back(warning);
  for (const std::string& note : photo->notes) doc.notes_.push_back(note);
  doc.path_ = options.photoShotPath.empty() ? path.parent_path() / (path.stem().string() + ".shot.json")
                                            : options.photoShotPath;
  Shot& shot = doc.shot_;
  shot.imagePath = path.string();
  shot.imageWidth = doc.photo_.cols;
  shot.imageHeight = doc.photo_.rows;
  shot.cameraHeightM = kDefaultCameraHeightM;

  metrology::detect::DetectOptions detectOptions;
  if (doc.exifFocal_) {
    shot.focalPx = doc.exifFocal_->focalPx;
    shot.focalMm = doc.exifFocal_->focalMm;  // saved as focal_mm with sensor_width_mm when the sensor is known
    detectOptions.focalPx = shot.focalPx;
    doc.openedFocalSource_ = doc.exifFocal_->source;
    // (How: the Camera panel's "focal length from" line.)
    doc.notes_.push_back("focal length " + fixed(shot.focalPx, 1) + " px from the photo's EXIF");
  }
  auto detection = metrology::detect::detectCorridor(doc.photo_, detectOptions);
  if (detection && detection->found) {
    shot.focalPx = detection->focalPx;
    if (!doc.exifFocal_) {
      doc.openedFocalSource_ = detection->focalSource == metrology::detect::FocalSource::kVanishingPoints
                                   ? "detection: from the vanishing points"
                                   : "default: a 28 mm-equivalent lens";
    }
    for (int k = 0; k < kCornerCount; ++k) shot.cornersPx[k] = detection->corners[k].px;
    // The report, saved with the shot, read as a shot file's is: opening the saved file
    // again shows the same.
    doc.otherFields_["detection"] = detectionReport(*detection, /*lensGiven=*/false, doc.exifFocal_.has_value());
    if (const auto report = readDetectionReport(doc.otherFields_)) doc.takeDetection(*report);
    if (!detection->distortion.isNone()) {
      shot.distortion = detection->distortion;
      doc.notes_.push_back("lens distortion k1 " + fixed(detection->distortion.k1, 3) + " found from " +
                           std::to_string(detection->plumbLineCount) + " straight lines: the edges are drawn curved, as "
                           "the lens shows them");
    }
    for (const std::string& warning : detection->warnings) doc.notes_.push_back("detection: " + warning);
  } else {
    const std::string reason = detection ? detection->notFoundReason : detection.message();
    const int longSide = std::max(shot.imageWidth, shot.imageHeight);
    const auto along = detection ? metrology::detect::boxAlongVanishingPoints(*detection, doc.photo_.size())
                                 : std::nullopt;
    shot.cornersPx = along ? *along : defaultCorners(shot.imageWidth, shot.imageHeight);
    doc.notes_.push_back("no corridor found (" + reason + ")");
    doc.placeholder_ = along ? "a starting box along the photo's vanishing points" : "a default box from the image size";
    if (along && !doc.exifFocal_) shot.focalPx = detection->focalPx;
    if (!doc.exifFocal_ && !(along && detection->focalSource == metrology::detect::FocalSource::kVanishingPoints)) {
      shot.focalPx = metrology::detect::kDefaultFocalOverLongSide * longSide;
      doc.openedFocalSource_ = "default: a 28 mm-equivalent lens";
    }
  }
  doc.openedFocalPx_ = shot.focalPx;
  doc.openedFocalMm_ = shot.focalMm;
  doc.opened_ = doc.shot_;
  return doc;
}

std::vector<std::string> Document::notes() const {
  std::vector<std::string> notes = notes_;
  if (isPlaceholderBox()) {
    notes.push_back(*placeholder_ + ", not the corridor's: no dimensions until its corners are on the corridor's corners");
  }
  if (focalSource().rfind("default:", 0) == 0) {
    notes.push_back("focal length assumed " + fixed(shot_.focalPx, 0) +
                    " px (a 28 mm-equivalent lens): set it below");
  }
  if (inputOrigins().cameraHeightAssumed) {
    notes.push_back("camera height assumed " + fixed(kDefaultCameraHeightM, 2) + " m: set it below");
  }
  return notes;
}

bool Document::isPlaceholderBox() const { return placeholder_ && shot_.cornersPx == opened_.cornersPx; }

bool Document::isSuggestedBox() const { return suggested_ && shot_.cornersPx == opened_.cornersPx; }

void Document::takeDetection(const DetectionReport& report) {
  double lowest = 1, highest = 0;
  int asDetected = 0;
  for (int k = 0; k < kCornerCount; ++k) {
    if (!(glm::length(shot_.cornersPx[k] - report.px[k]) <= kSameCornerPx)) continue;
    detectedPx_[k] = shot_.cornersPx[k];
    confidence_[k] = report.confidence[k];
    lowest = std::min(lowest, report.confidence[k]);
    highest = std::max(highest, report.confidence[k]);
    ++asDetected;
  }
  if (asDetected < kCornerCount) return;
  notes_.push_back("corners detected (confidence " + fixed(lowest, 2) + " to " + fixed(highest, 2) +
                   "): check each, the lowest first");
  for (const std::string& doubt : report.doubts) notes_.push_back("detection unsure: " + doubt);
  suggested_ = !report.confident;
}

std::optional<double> Document::detectionConfidence(int corner) const {
  if (corner < 0 || corner >= kCornerCount || !confidence_[corner]) return std::nullopt;
  if (shot_.cornersPx[corner] != detectedPx_[corner]) return std::nullopt;
  return confidence_[corner];
}

Document::FitResult Document::fitCorners(double reachPx) {
  metrology::detect::DetectOptions options;
  options.focalPx = shot_.focalPx;
  options.principalPointPx = shot_.principalPoint();
  options.hintPx = shot_.cornersPx;
  options.hintReachPx = reachPx;
  options.lens = shot_.distortion;
  auto detection = metrology::detect::detectCorridor(photo_, options);
  FitResult result;
  if (!detection) {
    result.message = "cannot fit the corners: " + detection.message();
    return result;
  }
  if (!detection->found) {
    result.message = "cannot fit the corners: " + detection->notFoundReason;
    return result;
  }
  const auto joined = [](const std::vector<std::string>& lines) {
    std::string text;
    for (const std::string& line : lines) text += (text.empty() ? "" : "; ") + line;
    return text;
  };
  Shot after = shot_;
  // A lens found from the photo's lines where the shot had none: the fitted corners
  // are where that lens shows them, so the shot takes it.
  const bool lensFound = !shot_.distortion && !detection->distortion.isNone();
  if (lensFound) after.distortion = detection->distortion;
  double largest = 0;
  for (int k = 0; k < kCornerCount; ++k) {
    after.cornersPx[k] = detection->corners[k].px;
    largest = std::max(largest, glm::length(after.cornersPx[k] - shot_.cornersPx[k]));
  }
  if (after == shot_) {
    result.message = "the corners stay where they are: " + joined(detection->doubts);
    return result;
  }
  apply(after, "fit corners");
  for (int k = 0; k < kCornerCount; ++k) {
    detectedPx_[k] = after.cornersPx[k];
    confidence_[k] = detection->corners[k].confidence;
  }
  result.moved = true;
  result.confident = detection->confident;
  result.message = "corners fitted to the photo's edges (moved up to " + fixed(largest, 1) + " px)" +
                   (lensFound ? "; lens distortion " + metrology::distortionText(detection->distortion) +
                                    " found from the photo's straight lines"
                              : "") +
                   (detection->warnings.empty() ? "" : "; " + joined(detection->warnings)) +
                   (detection->confident ? "" : "; unsure: " + joined(detection->doubts));
  return result;
}

void Document::apply(const Shot& after, std::string label) {
  if (after == shot_) return;
  history_.push({shot_, after, std::move(label)});
  shot_ = after;
}

void Document::commitLive(const Shot& before, std::string label) {
  if (before == shot_) return;
  history_.push({before, shot_, std::move(label)});
}

bool Document::undo() {
  const History::Step* step = history_.undo();
  if (!step) return false;
  shot_ = step->before;
  return true;
}

bool Document::redo() {
  const History::Step* step = history_.redo();
  if (!step) return false;
  shot_ = step->after;
  return true;
}

namespace {

// The same focal length: in mm with the same sensor when both are in mm, else the same
// pixels (a unit switched to px keeps them).
bool sameFocal(double px, const std::optional<metrology::FocalLengthMm>& mm, double otherPx,
               const std::optional<metrology::FocalLengthMm>& otherMm) {
  if (mm && otherMm) return mm->focalMm == otherMm->focalMm && mm->sensorWidthMm == otherMm->sensorWidthMm;
  return std::abs(px - otherPx) <= 1e-9 * std::abs(otherPx);
}

}  // namespace

std::string Document::focalSource() const {
  if (exifFocal_ && sameFocal(shot_.focalPx, shot_.focalMm, exifFocal_->focalPx, exifFocal_->focalMm)) {
    return exifFocal_->source;
  }
  if (sameFocal(shot_.focalPx, shot_.focalMm, openedFocalPx_, openedFocalMm_)) return openedFocalSource_;
  return "set in the editor";
}

metrology::InputOrigins Document::inputOrigins() const {
  metrology::InputOrigins origins;
  origins.focal = metrology::focalOriginOf(focalSource());
  origins.cameraHeightAssumed = !scaleFromFile_ && shot_.cameraHeightM && *shot_.cameraHeightM == kDefaultCameraHeightM;
  return origins;
}

nlohmann::json Document::fieldsToWrite() const {
  nlohmann::json fields = otherFields_;
  const bool asInTheFile = fromFile_ && sameFocal(shot_.focalPx, shot_.focalMm, openedFocalPx_, openedFocalMm_);
  if (!asInTheFile) fields["focal_source"] = focalSource();
  return fields;
}

Status Document::save() {
  PW_TRY(modeling::writeShotFile(path_, shot_, fieldsToWrite()));
  saved_ = shot_;
  removeAutosave();
  return {};
}

void Document::removeAutosave() const {
  // Saved: an autosave's side file (autosave.h) would offer an older state back.
  std::error_code ignored;
  fs::remove(autosavePath(path_), ignored);
}

Status Document::saveAs(const fs::path& path) {
  PW_TRY(modeling::writeShotFile(path, shot_, fieldsToWrite()));
  path_ = path;
  saved_ = shot_;
  removeAutosave();
  return {};
}

Status Document::saveCopy(const fs::path& path) const { return modeling::writeShotFile(path, shot_, fieldsToWrite()); }

}  // namespace pw::edit
