#include "editor/edit/autosave.h"

#include "modeling/shot_file.h"

namespace pw::edit {
namespace fs = std::filesystem;
using metrology::Shot;

fs::path autosavePath(const fs::path& savePath) {
  return savePath.parent_path() / ("." + savePath.filename().string() + ".autosave");
}

Status Autosave::step(const Document* doc, double stepS) {
  sinceS_ += stepS;
  if (sinceS_ < kIntervalS) return {};
  sinceS_ = 0;
  if (!doc) return {};
  if (!doc->hasUnsavedEdits()) {
    if (writtenFor_) remove(*writtenFor_);
    return {};
  }
  if (writtenShot_ && writtenFor_ == doc->path() && *writtenShot_ == doc->shot()) return {};
  if (Status saved = doc->saveCopy(autosavePath(doc->path())); !saved) {
    const bool first = !failing_;
    failing_ = true;
    if (first) return makeError("autosave failed: " + saved.message());
    return {};
  }
  failing_ = false;
  if (writtenFor_ && *writtenFor_ != doc->path()) remove(*writtenFor_);  // the document moved (Save As)
  writtenShot_ = doc->shot();
  writtenFor_ = doc->path();
  return {};
}

void Autosave::remove(const fs::path& savePath) {
  std::error_code ec;
  fs::remove(autosavePath(savePath), ec);
  if (writtenFor_ == savePath) reset();
}

void Autosave::reset() {
  writtenShot_.reset();
  writtenFor_.reset();
  sinceS_ = 0;
}

Result<std::optional<Shot>> recoverableShot(const Document& doc) {
  const fs::path side = autosavePath(doc.path());
  std::error_code ec;
  if (!fs::exists(side, ec)) return std::optional<Shot>();
  auto read = modeling::readShotFile(side);
  if (!read) return makeError("the autosave " + side.string() + " cannot be read: " + read.message());
  const Shot& shot = doc.shot();
  if (!fs::equivalent(read->imagePath, shot.imagePath, ec) || ec) {
    return makeError("the autosave " + side.string() + " is of another photo (" + read->imagePath + "); left as it is");
  }
  Shot recovered = shot;
  recovered.focalPx = read->focalPx;
  recovered.focalMm = read->focalMm;
  if (recovered.focalMm) recovered.focalPx = recovered.focalMm->pixels(recovered.imageWidth);
  recovered.principalPointPx = read->principalPointPx;
  recovered.cameraHeightM = read->cameraHeightM;
  recovered.reference = read->reference;
  recovered.cornersPx = read->cornersPx;
  if (recovered == shot) return std::optional<Shot>();
  return std::optional<Shot>(recovered);
}

}  // namespace pw::edit
