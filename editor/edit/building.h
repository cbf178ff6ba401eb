// What the editor edits in building mode: a layout file (modeling/layout.h) with its
// shots. The layout has its own undo history (one step per plan edit: a drag, a turn, a
// field); each shot is a Document (document.h) with its own unsaved state and undo
// history, kept while another shot is edited. No window, no GPU: tested headless
// (tests/edit/building_test.cpp).
//
//   auto b = Building::open("house.json");    // the layout and every shot it names
//   b->apply(placeCorridor(b->layout(), 1, pose), "move wing");
//   b->undo();  b->save();                    // the shots with changes, then the layout
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "base/result.h"
#include "editor/edit/document.h"
#include "editor/edit/live_measurement.h"
#include "editor/edit/plan.h"
#include "modeling/layout.h"
#include "modeling/pipeline.h"

namespace pw::edit {

// The whole building's model from shots already measured (one per corridor of
// `layout`, in its order), titled `title`: what Building::buildModel makes (W walks
// it) and building mode's 3D preview builds on its worker thread. Any thread.
// Errors: modeling::buildModel's.
Result<modeling::BuiltModel> buildBuildingModel(const modeling::Layout& layout,
                                                const std::vector<modeling::MeasuredShot>& shots,
                                                const modeling::ModelOptions& options, const std::string& title);

// True for a JSON file with a "corridors" array (a layout, not a shot file).
bool isLayoutFile(const std::filesystem::path& path);

class Building {
 public:
  // Reads the layout and opens every shot it names. A shot that cannot be opened is
  // a line in shotError(), not an error: the plan shows the others. Errors: the layout
  // file cannot be read (readLayoutFile's message).
  static Result<Building> open(const std::filesystem::path& path);

  const std::filesystem::path& path() const { return path_; }
  const modeling::Layout& layout() const { return layout_; }
  // Unsaved changes in the layout (the shots' own: Document::dirty).
  bool layoutDirty() const { return !saved_ || !sameLayout(*saved_, layout_); }
  // Any unsaved change, the layout's or a shot's.
  bool dirty() const;
  // The files save() would write for unsaved changes: each shot with them (`lentShot`,
  // the lent shot as it is now, counts for the lent one), then the layout.
  std::vector<std::filesystem::path> unsavedFiles(const Document* lentShot) const;

  // The shots, by the path the layout names them with (LayoutEntry::shot). A shot
  // lent to the shot editor (lend) is not here until it is given back.
  Document* shot(const std::filesystem::path& shotPath);
  const std::string& shotError(const std::filesystem::path& shotPath) const;
  // Hands the shot's Document over to be edited elsewhere, and takes it back (what
  // was edited is then what the plan shows and save() writes).
  std::optional<Document> lend(const std::filesystem::path& shotPath);
  void giveBack(const std::filesystem::path& shotPath, Document doc);
  const std::optional<std::filesystem::path>& lent() const { return lent_; }

  // Measures each shot again where its corners changed. `lentShot`: the lent shot as
  // it is now (it changes the corridor's size in the plan).
  void remeasure(const Document* lentShot);
  // Per corridor of layout(), its measured box; a shot that cannot be measured keeps
  // its last box (none yet: 2 x 5 x 2.5 m), and measured(i) is false.
  std::vector<metrology::Dimensions> boxes() const { return boxesFor(layout_); }
  // The same for another layout (one the plan may become), by its shot paths.
  std::vector<metrology::Dimensions> boxesFor(const modeling::Layout& layout) const;
  bool measured(int corridor) const;
  // Why corridor i's shot cannot be opened or measured (empty when it can).
  std::string problem(int corridor) const;
  // Each corridor's shot as modeling::buildModel takes it, or why one cannot be.
  Result<std::vector<modeling::MeasuredShot>> measuredShots(const Document* lentShot) const;
  // The whole building's model from the shots as they are (saved or not), as
  // `photowalk build --layout` makes it from the files: what W walks (and what a
  // preview of the building would draw). Errors: a shot that cannot be measured, a
  // layout that cannot be built (planBuilding's message).
  Result<modeling::BuiltModel> buildModel(const Document* lentShot) const;

  // Plan edits, as the shot's: apply is one step; setLive then commitLive (a drag).
  void apply(const modeling::Layout& after, std::string label);
  void setLive(const modeling::Layout& live) { layout_ = live; }
  void commitLive(const modeling::Layout& before, std::string label);
  bool undo();
  bool redo();
  bool canUndo() const { return next_ > 0; }
  bool canRedo() const { return next_ < steps_.size(); }

  // Adds a shot file or a photo (Document::open: a photo gets detected corners and is
  // saved beside it as STEM.shot.json) as a new corridor, placed beside the others,
  // one undo step; a shot already in the layout is shared (the same Document). Returns
  // the new corridor's index. Errors: Document::open's.
  Result<int> addShot(const std::filesystem::path& path, const OpenOptions& options = {});

  // Writes every shot with unsaved changes (lentShot too, when given), then the layout,
  // each atomically. The first failure stops and is returned.
  Status save(Document* lentShot);

 private:
  struct Slot {
    std::optional<Document> doc;
    std::string error;  // why the shot cannot be opened or measured
    std::optional<metrology::Shot> measuredShot;
    std::optional<metrology::Measurement> measurement;
    std::optional<metrology::Dimensions> box;  // the last box measured
  };
  struct Step {
    modeling::Layout before, after;
    std::string label;
  };
  void push(Step step);
  const Slot* slotOf(int corridor) const;

  std::filesystem::path path_;
  modeling::Layout layout_;
  std::optional<modeling::Layout> saved_;
  std::map<std::filesystem::path, Slot> shots_;
  std::optional<std::filesystem::path> lent_;
  std::vector<Step> steps_;
  size_t next_ = 0;
};

}  // namespace pw::edit
