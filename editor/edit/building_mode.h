// Building mode: `photowalk edit LAYOUT.json`. A mode of the app shell beside the shot
// editor (edit_mode.h) and the walk (model_walk.h): the plan of the building seen from
// above (plan.h), where corridors are moved and turned by dragging and snap to each
// other's far and side walls (which writes the layout's attach entries), the list of
// shots (one is lent to the shot editor at a time, with its own undo history and
// unsaved state: building.h), numeric placement, adding a shot or photo, a walk of the
// whole building, and Save of the layout and its shots. README "Building mode" lists
// the mouse and keys and the trace's "building" and "plan_to_window" fields.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <GLFW/glfw3.h>

#include "editor/app/app_mode.h"
#include "editor/edit/building.h"
#include "editor/edit/building_preview.h"
#include "editor/edit/canvas.h"
#include "editor/edit/number_field.h"
#include "editor/edit/plan.h"

namespace pw::edit {

class EditMode;
class ModelWalk;

class BuildingMode : public app::AppMode {
 public:
  static constexpr const char* kName = "building";

  // `editor` edits the shot lent to it, `walk` walks the building (both borrowed).
  BuildingMode(EditMode& editor, ModelWalk& walk, std::optional<std::filesystem::path> layout);

  // Opens a layout file (what the file browser or a drop would call): the plan shows
  // it; a failure is a message in the window. Unsaved changes of a building open
  // before are dropped: ask first (dirty()).
  void openLayout(app::Shell& shell, const std::filesystem::path& path);
  // A layout opened from the shot editor or dropped on the plan: when the building or
  // the editor's shot has unsaved changes, asks first (Save all / Discard / Cancel, in
  // this mode), then opens it and shows the plan.
  void openFromEditor(app::Shell& shell, const std::filesystem::path& path);
  // The shot editor's close (EditMode::setCloseAsker): when the building has unsaved
  // changes (the shot lent to the editor's or any other), the question is asked here,
  // about them and the editor's own shot, this mode becoming the active one. True: it
  // asks (the window stays).
  bool askBeforeEditorCloses(app::Shell& shell);
  bool hasBuilding() const { return building_.has_value(); }
  bool dirty() const;

  std::string_view name() const override { return kName; }
  Status open(app::Shell& shell) override;
  bool onCloseRequest(app::Shell& shell) override;  // asks first when dirty()
  void onEnter(app::Shell& shell) override;
  void onLeave(app::Shell& shell) override;
  void onInput(app::Shell& shell, const app::InputEvent& event) override;
  Status onReplayEvent(app::Shell& shell, const app::ModeEvent& event) override;  // preview-wait
  void update(app::Shell& shell, double stepS) override;
  void traceRow(app::TraceRow& row) const override;
  void drawUi(app::Shell& shell) override;
  app::FrameContent frame(app::Shell& shell) override;

 private:
  struct Drag {
    enum class Kind { kMove, kTurn } kind = Kind::kMove;
    std::string name;  // the corridor (attaching may list it elsewhere)
    modeling::Layout before;
    int indexBefore = -1;
    PlanPose poseBefore;
    glm::dvec2 pressPlan{0.0};
    glm::dvec2 pressWindowPx{0.0};
    bool moved = false;
    std::optional<Snap> snap;
  };

  void layOut(app::Shell& shell);
  void updatePreview(app::Shell& shell);  // swaps a finished model in; asks for the building as it is
  void onKey(app::Shell& shell, const app::KeyEvent& event);
  void onButton(const app::MouseButtonEvent& event);
  void onCursor(const glm::dvec2& positionPx);
  void onDrop(app::Shell& shell, const app::DropEvent& event);
  void zoomAbout(const glm::dvec2& anchorPx, double steps);
  void fit();
  bool overPlan(const glm::dvec2& windowPx) const;
  bool held(int key) const { return key >= 0 && key <= GLFW_KEY_LAST && keys_[key]; }
  bool shiftHeld() const { return held(GLFW_KEY_LEFT_SHIFT) || held(GLFW_KEY_RIGHT_SHIFT); }
  bool ctrlHeld() const { return held(GLFW_KEY_LEFT_CONTROL) || held(GLFW_KEY_RIGHT_CONTROL); }
  bool altHeld() const { return held(GLFW_KEY_LEFT_ALT) || held(GLFW_KEY_RIGHT_ALT); }

  // The plan as it is now: each corridor's box and world transform.
  int selectedIndex() const;
  std::optional<glm::dvec2> turnHandle(int corridor) const;  // window pixels, for the selected one
  double snapDistanceM() const;

  // Edits (each one undo step) and commands.
  void dragTo(const glm::dvec2& cursorPx);
  void endDrag(bool keep);
  void turnSelected(double deltaDeg);
  void removeSelected(app::Shell& shell);
  void applyLayout(const modeling::Layout& after, const std::string& label);
  void undo(app::Shell& shell);
  void redo(app::Shell& shell);
  void save(app::Shell& shell);
  void walk(app::Shell& shell);
  void editShot(app::Shell& shell, int corridor);
  void addShot(app::Shell& shell, const std::filesystem::path& path);
  // The shot lent to the editor, when the editor still has it.
  Document* lentShot();
  const Document* lentShot() const;
  void reconcileLent(app::Shell& shell);

  // building_question.cpp: the Save all / Discard / Cancel question before unsaved
  // changes (the layout's, its shots', the editor's shot) would be lost.
  struct Question {
    std::optional<std::filesystem::path> open;  // the layout to open then; unset: closing
    bool backToEditor = false;                  // asked from the shot editor: Cancel goes back
  };
  void ask(app::Shell& shell, std::optional<std::filesystem::path> open);
  void answer(app::Shell& shell, int answer);  // 0 save all, 1 discard, 2 cancel
  bool onQuestionKey(app::Shell& shell, const app::KeyEvent& event);  // true: the question is up
  std::vector<std::filesystem::path> unsavedFiles() const;
  const Document* foreignShot() const;  // the editor's shot when it is not the building's
  void drawQuestion(app::Shell& shell);
  bool questionButton(const char* label, const std::string& name);
  void traceQuestion(app::TraceRow& row) const;

  // building_panel.cpp: the side panel and the plan's drawing.
  void drawPanel(app::Shell& shell);
  void drawCorridorList(app::Shell& shell);
  void drawPlacement(app::Shell& shell);
  void drawAddShot(app::Shell& shell);
  void drawPlan();

  EditMode& editor_;
  ModelWalk& walk_;
  std::optional<std::filesystem::path> file_;
  std::optional<Building> building_;
  std::string openError_;
  std::string planError_;  // why the layout as it is cannot be built (planBuilding), or empty
  std::vector<std::string> planWarnings_;  // corridors that run through each other (planBuilding's overlaps)
  // The plan as last computed (update, and after each edit).
  std::vector<metrology::Dimensions> boxes_;
  std::vector<glm::dmat4> world_;

  glm::ivec2 windowSize_{0};
  double panelWidthPx_ = 0;
  double panelHeightPx_ = 0;  // the side panel, above the 3D preview
  WindowRect planArea_;
  BuildingPreview preview_;     // the whole building in 3D, under the panel
  bool previewCurrent_ = false;  // it shows the building as it is now
  PlanTransform view_;
  bool viewTouched_ = false;  // zoomed or panned: a resize keeps the view
  std::vector<WindowRect> uiRects_;

  std::string selected_;  // the selected corridor's name, or empty
  std::optional<Drag> drag_;
  std::optional<glm::dvec2> panFrom_;
  int panButton_ = -1;
  glm::dvec2 cursorPx_{-1.0};
  std::array<bool, GLFW_KEY_LAST + 1> keys_{};
  std::string addPath_;  // the panel's "add a shot or photo" field
  std::optional<Question> question_;
  std::vector<std::pair<std::string, WindowRect>> questionButtons_;  // as last drawn, for the trace
  NumberFields fields_;  // the placement's number fields (number_field.h)
};

}  // namespace pw::edit
