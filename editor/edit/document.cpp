#include "editor/edit/document.h"

#include <algorithm>
#include <cctype>
#include <cstdio>

#include <opencv2/imgcodecs.hpp>

#include "metrology/detect/detect.h"
#include "modeling/shot_file.h"

namespace pw::edit {
namespace fs = std::filesystem;
using metrology::kCornerCount;
using metrology::Shot;

bool sameShot(const Shot& a, const Shot& b) {
  const auto sameMm = [](const std::optional<metrology::FocalLengthMm>& x, const std::optional<metrology::FocalLengthMm>& y) {
    if (x.has_value() != y.has_value()) return false;
    return !x || (x->focalMm == y->focalMm && x->sensorWidthMm == y->sensorWidthMm);
  };
  const auto sameReference = [](const std::optional<metrology::ReferenceLength>& x,
                                const std::optional<metrology::ReferenceLength>& y) {
    if (x.has_value() != y.has_value()) return false;
    return !x || (x->from == y->from && x->to == y->to && x->lengthM == y->lengthM);
  };
  return a.imagePath == b.imagePath && a.imageWidth == b.imageWidth && a.imageHeight == b.imageHeight &&
         a.focalPx == b.focalPx && sameMm(a.focalMm, b.focalMm) && a.principalPointPx == b.principalPointPx &&
         a.cameraHeightM == b.cameraHeightM && a.cornersPx == b.cornersPx && sameReference(a.reference, b.reference);
}

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

}  // namespace

Result<Document> Document::open(const fs::path& path, const OpenOptions& options) {
  Document doc;
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) return makeError(path.string() + ": no such file");
  if (isShotFile(path)) {
    auto loaded = modeling::loadShot(path);
    if (!loaded) return loaded.error();
    doc.path_ = path;
    doc.shot_ = std::move(loaded->shot);
    doc.photo_ = std::move(loaded->image);
    doc.otherFields_ = std::move(loaded->otherFields);
    doc.saved_ = doc.shot_;
    doc.opened_ = doc.shot_;
    return doc;
  }

  try {
    doc.photo_ = cv::imread(path.string(), cv::IMREAD_COLOR);
  } catch (const cv::Exception&) {
    doc.photo_.release();
  }
  if (doc.photo_.empty()) return makeError(path.string() + ": not a readable PNG/JPEG image (or a shot file, *.json)");
  doc.path_ = options.photoShotPath.empty() ? path.parent_path() / (path.stem().string() + ".shot.json")
                                            : options.photoShotPath;
  Shot& shot = doc.shot_;
  shot.imagePath = path.string();
  shot.imageWidth = doc.photo_.cols;
  shot.imageHeight = doc.photo_.rows;
  shot.cameraHeightM = kDefaultCameraHeightM;

  auto detection = metrology::detect::detectCorridor(doc.photo_, {});
  if (detection && detection->found) {
    shot.focalPx = detection->focalPx;
    double lowest = 1, highest = 0;
    for (int k = 0; k < kCornerCount; ++k) {
      shot.cornersPx[k] = detection->corners[k].px;
      doc.detectedPx_[k] = shot.cornersPx[k];
      doc.confidence_[k] = detection->corners[k].confidence;
      lowest = std::min(lowest, detection->corners[k].confidence);
      highest = std::max(highest, detection->corners[k].confidence);
    }
    doc.notes_.push_back("corners detected automatically (confidence " + fixed(lowest, 2) + " to " + fixed(highest, 2) +
                         "): check each one, the lowest first");
    for (const std::string& warning : detection->warnings) doc.notes_.push_back("detection: " + warning);
  } else {
    const std::string reason = detection ? detection->notFoundReason : detection.message();
    const int longSide = std::max(shot.imageWidth, shot.imageHeight);
    shot.focalPx = metrology::detect::kDefaultFocalOverLongSide * longSide;
    shot.cornersPx = defaultCorners(shot.imageWidth, shot.imageHeight);
    doc.notes_.push_back("no corridor found (" + reason + "): a default box from the image size; drag the corners onto "
                         "the corridor's");
    doc.notes_.push_back("focal length assumed " + fixed(shot.focalPx, 0) +
                         " px (a 28 mm-equivalent lens): set it in the Camera panel");
  }
  doc.notes_.push_back("camera height assumed " + fixed(kDefaultCameraHeightM, 2) + " m: set it in the Camera panel");
  doc.opened_ = doc.shot_;
  return doc;
}

std::optional<double> Document::detectionConfidence(int corner) const {
  if (corner < 0 || corner >= kCornerCount || !confidence_[corner]) return std::nullopt;
  if (shot_.cornersPx[corner] != detectedPx_[corner]) return std::nullopt;
  return confidence_[corner];
}

void Document::apply(const Shot& after, std::string label) {
  if (sameShot(after, shot_)) return;
  history_.push({shot_, after, std::move(label)});
  shot_ = after;
}

void Document::commitLive(const Shot& before, std::string label) {
  if (sameShot(before, shot_)) return;
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

Status Document::save() {
  PW_TRY(modeling::writeShotFile(path_, shot_, otherFields_));
  saved_ = shot_;
  return {};
}

Status Document::saveAs(const fs::path& path) {
  PW_TRY(modeling::writeShotFile(path, shot_, otherFields_));
  path_ = path;
  saved_ = shot_;
  return {};
}

Status Document::saveCopy(const fs::path& path) const { return modeling::writeShotFile(path, shot_, otherFields_); }

}  // namespace pw::edit
