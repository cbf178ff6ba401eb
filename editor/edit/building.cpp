#include "editor/edit/building.h"

#include <algorithm>
#include <cctype>

#include <nlohmann/json.hpp>

#include "base/atomic_file.h"

namespace pw::edit {
namespace fs = std::filesystem;
using modeling::Layout;

namespace {

// Drawn for a shot that has never measured, so that it can still be placed.
constexpr metrology::Dimensions kUnmeasuredBox{2.0, 2.5, 5.0};
constexpr double kAddGapM = 2.0;  // a corridor added stands this far right of the others

const std::string kNoProblem;

}  // namespace

Result<modeling::BuiltModel> buildBuildingModel(const Layout& layout, const std::vector<modeling::MeasuredShot>& shots,
                                                const modeling::ModelOptions& options, const std::string& title) {
  auto model = modeling::buildModel(layout, shots, options);
  if (!model) return model.error();
  model->scene.title = title;
  return model;
}

bool isLayoutFile(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext != ".json") return false;
  auto text = readFile(path);
  if (!text) return false;
  const nlohmann::json doc = nlohmann::json::parse(*text, nullptr, false);
  return doc.is_object() && doc.contains("corridors") && doc["corridors"].is_array();
}

Result<Building> Building::open(const fs::path& path) {
  auto layout = modeling::readLayoutFile(path);
  if (!layout) return layout.error();
  Building b;
  b.path_ = path;
  b.layout_ = std::move(*layout);
  b.saved_ = b.layout_;
  for (const modeling::LayoutEntry& entry : b.layout_.corridors) {
    if (b.shots_.count(entry.shot)) continue;
    Slot& slot = b.shots_[entry.shot];
    auto doc = Document::open(entry.shot);
    if (doc) slot.doc = std::move(*doc);
    else slot.error = doc.message();
  }
  b.remeasure(nullptr);
  return b;
}

bool Building::dirty() const {
  if (layoutDirty()) return true;
  return std::any_of(shots_.begin(), shots_.end(), [](const auto& s) { return s.second.doc && s.second.doc->dirty(); });
}

std::vector<fs::path> Building::unsavedFiles(const Document* lentShot) const {
  std::vector<fs::path> files;
  for (const auto& [shotPath, slot] : shots_) {
    const Document* doc = slot.doc ? &*slot.doc : (lent_ == shotPath ? lentShot : nullptr);
    if (doc && doc->dirty()) files.push_back(shotPath);
  }
  if (layoutDirty()) files.push_back(path_);
  return files;
}

Document* Building::shot(const fs::path& shotPath) {
  auto it = shots_.find(shotPath);
  return it != shots_.end() && it->second.doc ? &*it->second.doc : nullptr;
}

const std::string& Building::shotError(const fs::path& shotPath) const {
  auto it = shots_.find(shotPath);
  return it != shots_.end() ? it->second.error : kNoProblem;
}

std::optional<Document> Building::lend(const fs::path& shotPath) {
  auto it = shots_.find(shotPath);
  if (it == shots_.end() || !it->second.doc || lent_) return std::nullopt;
  std::optional<Document> doc = std::move(it->second.doc);
  it->second.doc.reset();
  lent_ = shotPath;
  return doc;
}

void Building::giveBack(const fs::path& shotPath, Document doc) {
  shots_[shotPath].doc = std::move(doc);
  if (lent_ == shotPath) lent_.reset();
}

void Building::remeasure(const Document* lentShot) {
  for (auto& [shotPath, slot] : shots_) {
    const Document* doc = slot.doc ? &*slot.doc : (lent_ == shotPath ? lentShot : nullptr);
    if (!doc) continue;
    if (slot.measuredShot && *slot.measuredShot == doc->shot()) continue;
    slot.measuredShot = doc->shot();
    LiveMeasurement live = measureLive(doc->shot(), doc->inputOrigins());
    slot.measurement = live.measurement;
    if (live.measurement) {
      slot.box = live.measurement->size;
      slot.error.clear();
    } else {
      slot.error = shotPath.filename().string() + ": cannot be measured: " + live.error;
    }
  }
}

const Building::Slot* Building::slotOf(int corridor) const {
  if (corridor < 0 || size_t(corridor) >= layout_.corridors.size()) return nullptr;
  auto it = shots_.find(layout_.corridors[corridor].shot);
  return it != shots_.end() ? &it->second : nullptr;
}

std::vector<metrology::Dimensions> Building::boxesFor(const Layout& layout) const {
  std::vector<metrology::Dimensions> boxes;
  for (const modeling::LayoutEntry& entry : layout.corridors) {
    auto it = shots_.find(entry.shot);
    boxes.push_back(it != shots_.end() && it->second.box ? *it->second.box : kUnmeasuredBox);
  }
  return boxes;
}

bool Building::measured(int corridor) const {
  const Slot* slot = slotOf(corridor);
  return slot && slot->measurement.has_value();
}

std::string Building::problem(int corridor) const {
  const Slot* slot = slotOf(corridor);
  if (!slot) return "no shot";
  return slot->error;
}

Result<std::vector<modeling::MeasuredShot>> Building::measuredShots(const Document* lentShot) const {
  std::vector<modeling::MeasuredShot> shots;
  for (size_t i = 0; i < layout_.corridors.size(); ++i) {
    const modeling::LayoutEntry& entry = layout_.corridors[i];
    const Slot* slot = slotOf(int(i));
    const Document* doc = slot && slot->doc ? &*slot->doc : (lent_ == entry.shot ? lentShot : nullptr);
    if (!slot || !doc) return makeError("corridor \"" + entry.name + "\": " + (slot ? slot->error : "no shot"));
    if (!slot->measurement || !slot->measuredShot || *slot->measuredShot != doc->shot()) {
      return makeError("corridor \"" + entry.name + "\": " +
                       (slot->error.empty() ? std::string("not measured yet") : slot->error));
    }
    modeling::MeasuredShot measured;
    measured.loaded.shot = doc->shot();
    measured.loaded.image = doc->photo();  // shared, not copied
    measured.measurement = *slot->measurement;
    shots.push_back(std::move(measured));
  }
  return shots;
}

Result<modeling::BuiltModel> Building::buildModel(const Document* lentShot) const {
  auto shots = measuredShots(lentShot);
  if (!shots) return shots.error();
  return buildBuildingModel(layout_, *shots, modeling::ModelOptions{}, path_.stem().string());
}

void Building::push(Step step) {
  steps_.resize(next_);
  steps_.push_back(std::move(step));
  next_ = steps_.size();
}

void Building::apply(const Layout& after, std::string label) {
  if (sameLayout(after, layout_)) return;
  push({layout_, after, std::move(label)});
  layout_ = after;
}

void Building::commitLive(const Layout& before, std::string label) {
  if (sameLayout(before, layout_)) return;
  push({before, layout_, std::move(label)});
}

bool Building::undo() {
  if (!canUndo()) return false;
  layout_ = steps_[--next_].before;
  return true;
}

bool Building::redo() {
  if (!canRedo()) return false;
  layout_ = steps_[next_++].after;
  return true;
}

Result<int> Building::addShot(const fs::path& path, const OpenOptions& options) {
  fs::path shotPath;
  if (isLayoutFile(path)) return makeError(path.string() + ": a layout, not a shot or a photo");
  std::optional<Document> opened;
  if (auto doc = Document::open(path, options); doc) {
    shotPath = doc->path();
    opened = std::move(*doc);
  } else {
    return doc.error();
  }
  if (!shots_.count(shotPath)) {
    shots_[shotPath].doc = std::move(opened);
    remeasure(nullptr);
  }
  modeling::LayoutEntry entry;
  entry.shot = shotPath;
  std::string stem = path.stem().string();
  if (stem.empty()) stem = "corridor";
  entry.name = stem;
  const auto taken = [&](const std::string& name) {
    return std::any_of(layout_.corridors.begin(), layout_.corridors.end(),
                       [&](const modeling::LayoutEntry& e) { return e.name == name; });
  };
  for (int k = 2; taken(entry.name); ++k) entry.name = stem + "_" + std::to_string(k);
  // Beside the others: right of everything, near end on z = 0.
  const std::vector<metrology::Dimensions> sizes = boxes();
  const std::vector<glm::dmat4> world = placeCorridors(layout_, sizes);
  double right = 0;
  bool any = false;
  for (size_t i = 0; i < world.size(); ++i) {
    for (const glm::dvec2& corner : footprintCorners(world[i], sizes[i])) {
      right = any ? std::max(right, corner.x) : corner.x;
      any = true;
    }
  }
  Layout after = layout_;
  after.corridors.push_back(entry);
  const Slot& slot = shots_[shotPath];
  const metrology::Dimensions box = slot.box ? *slot.box : kUnmeasuredBox;
  after.corridors.back().position = {any ? right + kAddGapM + box.widthM / 2 : 0.0, 0.0, 0.0};
  apply(after, "add " + entry.name);
  return int(layout_.corridors.size()) - 1;
}

Status Building::save(Document* lentShot) {
  for (auto& [shotPath, slot] : shots_) {
    if (slot.doc && slot.doc->dirty()) PW_TRY(slot.doc->save());
  }
  if (lentShot && lentShot->dirty()) PW_TRY(lentShot->save());
  PW_TRY(modeling::writeLayoutFile(path_, layout_));
  saved_ = layout_;
  return {};
}

}  // namespace pw::edit
