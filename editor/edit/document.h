// What the editor edits: one shot (metrology/shot.h) with its photo, where it is saved,
// what opening it found out, and its undo history. No window, no GPU: tested headless
// (tests/edit/document_test.cpp).
//
//   auto doc = Document::open("corridor.png", {});   // corners detected, or a default box
//   Shot s = doc->shot();  s.cornersPx[P5] += glm::dvec2(3, 0);
//   doc->apply(s, "move P5");                         // one undo step
//   doc->undo();  doc->redo();  doc->save();          // writeShotFile, atomically
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <opencv2/core/mat.hpp>

#include "base/result.h"
#include "metrology/input_sigma.h"
#include "metrology/shot.h"
#include "modeling/exif.h"

namespace pw::edit {

struct DetectionReport;

// Undo and redo as whole shots: a shot is a few hundred bytes, so each step keeps the
// state before and after, and undoing everything then redoing everything restores
// the very same numbers (hence byte-identical files).
class History {
 public:
  struct Step {
    metrology::Shot before, after;
    std::string label;  // "move P5", "focal length"
  };
  // Records a step; the steps that were undone are dropped (no redo past a new edit).
  void push(Step step);
  // The step to undo (its `before` is the state to restore), or none; moves back.
  const Step* undo();
  // The step to redo (its `after` is the state to restore), or none; moves forward.
  const Step* redo();
  bool canUndo() const { return next_ > 0; }
  bool canRedo() const { return next_ < steps_.size(); }
  size_t size() const { return steps_.size(); }

 private:
  std::vector<Step> steps_;
  size_t next_ = 0;  // steps_[0, next_) are done
};

// The editor's defaults for a photo without a shot file.
inline constexpr double kDefaultCameraHeightM = 1.6;

struct OpenOptions {
  // Where Save writes a shot for a photo opened alone; empty: beside the photo, as
  // STEM.shot.json. (A shot file is saved where it was read.)
  std::filesystem::path photoShotPath;
};

class Document {
 public:
  // Opens a shot file (*.json: modeling::loadShot) or a photo (PNG/JPEG). A photo gets
  // its corners from automatic detection (metrology/detect), with the confidences;
  // where none is found, a default box from the image size; the camera height is then
  // kDefaultCameraHeightM until set, as it is for a shot file with neither a camera height
  // nor a reference length (detect's without --camera-height). notes() says what was
  // assumed. Errors: a file
  // that cannot be read, a shot file with errors (one line naming the problem).
  static Result<Document> open(const std::filesystem::path& path, const OpenOptions& options = {});

  const metrology::Shot& shot() const { return shot_; }
  // The shot as its model sees it: without the points and measurements on objects (they
  // change no surface), so that measuring rebuilds no preview and keeps W's model.
  metrology::Shot modelShot() const {
    metrology::Shot s = shot_;
    s.points.clear();
    s.measurements.clear();
    return s;
  }
  const cv::Mat& photo() const { return photo_; }  // BGR, 8 bit
  const std::filesystem::path& path() const { return path_; }  // where save() writes
  // Unsaved changes: the shot differs from the file at path() (always, for a photo
  // never saved).
  bool dirty() const { return !saved_ || *saved_ != shot_; }
  // Changes a person would lose by closing now: the shot differs from the file saved,
  // or, for a photo never saved, from what opening it gave (detection's corners,
  // which opening it again gives back). What autosave keeps and closing asks about.
  bool hasUnsavedEdits() const { return (saved_ ? *saved_ : opened_) != shot_; }
  // One line each: what opening found, and what is assumed now ("corners detected
  // automatically, ...", "camera height assumed 1.60 m: ..."): an assumption's note
  // goes once its value is set and comes back when it is set back to the assumed one.
  std::vector<std::string> notes() const;
  // Where no corridor was found, the box opening put there is a placeholder until one
  // of its corners is moved: it measures nothing a person should be shown, walk in or
  // export (the editor says so instead).
  bool isPlaceholderBox() const;
  // Where detection found a box but was unsure of it (detect's exit 3), the box is a
  // suggestion until one of its corners is moved or the corners are fitted (E): the
  // editor shows its dimensions as a suggestion's, not a result, with the doubts.
  bool isSuggestedBox() const;
  // Per corner, the detection's confidence (0..1), while the corner is where detection
  // put it; unset for corners from a file, a default box, or moved since.
  std::optional<double> detectionConfidence(int corner) const;
  // The photo's EXIF tags (read for a shot file's photo too; present = false without
  // any) and the focal length they give for the photo as shown, if any.
  const modeling::ExifTags& exif() const { return exif_; }
  const std::optional<modeling::ExifFocal>& exifFocal() const { return exifFocal_; }
  // Where the shot's focal length comes from, in words: the EXIF source line while the
  // focal length is the EXIF's, "detection: vanishing points", "default: ...", the shot
  // file's own focal_source (or "the shot file") while unchanged, else "set in the
  // editor". Save writes it as the shot file's "focal_source" (unless it is the file's).
  std::string focalSource() const;
  // Where the focal length and the camera height came from, for the measurement's ±
  // (metrology/input_sigma.h): the camera height is assumed while a photo opened
  // without a shot file, or a shot file without a height or reference, keeps
  // kDefaultCameraHeightM.
  metrology::InputOrigins inputOrigins() const;

  // Fits the eight corners, from where they are now, to the photo's edges and
  // vanishing points (metrology/detect's hint: each side looked for within
  // `reachPx`), as one undo step "fit corners"; the fitted corners then show their
  // confidence. The message says how it went (how far the corners moved, or why the
  // photo does not bear the box out, the corners then staying where they were).
  struct FitResult {
    bool moved = false;
    bool confident = false;
    std::string message;
  };
  FitResult fitCorners(double reachPx = 25);

  // Makes `after` the shot, as one undo step from the current one; nothing when equal.
  void apply(const metrology::Shot& after, std::string label);
  // An edit in progress (a drag): setLive changes the shot without a step; commitLive
  // then records one step from `before` (the shot when the edit began) to the current
  // shot, nothing when they are equal.
  void setLive(const metrology::Shot& live) { shot_ = live; }
  void commitLive(const metrology::Shot& before, std::string label);
  bool undo();
  bool redo();
  const History& history() const { return history_; }

  // Writes the shot to path() atomically (modeling::writeShotFile; the focal length in
  // the units it came in); the document is then clean.
  Status save();
  // Save As: writes the shot to `path` atomically, as save() does (the image path made
  // relative to its folder; fields photowalk does not read kept); the document then
  // lives there, clean. Errors: the file cannot be written (the document stays as it was).
  Status saveAs(const std::filesystem::path& path);
  // Writes the shot to `path` without changing the document's path or state.
  Status saveCopy(const std::filesystem::path& path) const;

 private:
  void removeAutosave() const;  // the side file of path(), once saved
  // Detection's report (a shot file's, or the one made for a photo opened alone): each
  // corner's confidence while the shot's corner is where detection put it, and, where all
  // eight are, the note on them, the doubts, and a box detection was unsure of a suggestion.
  void takeDetection(const DetectionReport& report);

  std::filesystem::path path_;
  metrology::Shot shot_;
  nlohmann::json otherFields_ = nlohmann::json::object();  // the shot file's fields photowalk does not read, kept
  std::optional<metrology::Shot> saved_;
  metrology::Shot opened_;  // the shot as opening gave it
  cv::Mat photo_;
  std::vector<std::string> notes_;  // what opening found (the assumptions' notes are made by notes())
  std::optional<std::string> placeholder_;  // which placeholder box opening put there, if it did
  bool suggested_ = false;                  // detection found the box opening put there, unsure of it
  std::array<std::optional<double>, metrology::kCornerCount> confidence_{};
  std::array<glm::dvec2, metrology::kCornerCount> detectedPx_{};
  modeling::ExifTags exif_;
  std::optional<modeling::ExifFocal> exifFocal_;
  // The focal length when opened and where it came from (focalSource()); fromFile_:
  // the shot file said it (its own focal_source, if any, stays in otherFields_).
  double openedFocalPx_ = 0;
  std::optional<metrology::FocalLengthMm> openedFocalMm_;
  std::string openedFocalSource_;
  bool fromFile_ = false;
  // The shot file gave a camera height or a reference length (else the height is
  // assumed, kDefaultCameraHeightM, as for a photo opened alone).
  bool scaleFromFile_ = false;
  nlohmann::json fieldsToWrite() const;
  History history_;
};

// A default box for a photo where no corridor was found: the far wall a centred
// rectangle a fifth of the image, the near corners a tenth in from its edges.
std::array<glm::dvec2, metrology::kCornerCount> defaultCorners(int imageWidth, int imageHeight);

}  // namespace pw::edit
