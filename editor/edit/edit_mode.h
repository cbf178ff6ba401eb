// The editor as a mode of the app shell (editor/app): the photo on a canvas that pans
// and zooms (canvas.h), the eight corners as handles over it (overlay.h) with a loupe
// while one is dragged or nudged, a live measurement and camera panel (panels.cpp),
// undo and redo of every edit, Save, and a switch to the walkthrough of the current
// model and back (model_walk.h). README "The editor" lists the keys and the test
// interface (replay events, the trace's fields).
#pragma once

#include <array>
#include <chrono>
#include <filesystem>
#include <functional>
#include <future>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <GLFW/glfw3.h>

#include "editor/app/app_mode.h"
#include "editor/edit/canvas.h"
#include "editor/edit/document.h"
#include "editor/edit/edit_files.h"
#include "editor/edit/live_measurement.h"
#include "editor/edit/number_field.h"
#include "editor/edit/overlay.h"
#include "editor/edit/latest_worker.h"
#include "editor/edit/preview.h"
#include "metrology/detect/snap.h"
#include "metrology/object_measure.h"
#include "modeling/stand_up.h"

namespace pw::edit {

class ModelWalk;

struct EditModeOptions {
  std::optional<std::filesystem::path> file;  // a photo or a shot file to open; none: empty
  OpenOptions open;
  // Where the recent files list is kept; unset: defaultRecentFilesPath().
  std::optional<std::filesystem::path> recentFilesPath;
};

// `save-copy FILE`: the replay event that writes the shot as Ctrl+S would, to FILE
// (relative to the script), leaving the document's path and state as they are.
struct SaveCopyEvent {
  std::filesystem::path path;
};

// `preview-wait`: the replay event that waits until the 3D preview shows the full
// model of the corners as they are (tests capture it; a frame waits, so only there).
struct PreviewWaitEvent {};

// `boxes-wait`: the replay event that waits until the boxes drawn on the photo are those
// of the shot as it is (tests; a frame waits, so only there).
struct BoxesWaitEvent {};

class EditMode : public app::AppMode {
 public:
  // `walk` is the shell's walk mode for this editor (borrowed).
  EditMode(EditModeOptions options, ModelWalk& walk);

  // The editor's own replay events (save-copy), paths relative to `scriptDir`.
  static std::vector<app::ReplayVerb> replayVerbs(const std::filesystem::path& scriptDir);

  std::string_view name() const override { return "edit"; }
  Status open(app::Shell& shell) override;  // opens the file given; a failure is a message, not an error
  void onEnter(app::Shell& shell) override;
  void onLeave(app::Shell& shell) override;
  void onInput(app::Shell& shell, const app::InputEvent& event) override;
  Status onReplayEvent(app::Shell& shell, const app::ModeEvent& event) override;
  bool onCloseRequest(app::Shell& shell) override;  // asks first when there are unsaved edits
  void update(app::Shell& shell, double stepS) override;
  void traceRow(app::TraceRow& row) const override;
  double messagesMaxX() const override { return windowSize_.x - panelWidthPx_; }  // left of the panel
  void drawUi(app::Shell& shell) override;
  app::FrameContent frame(app::Shell& shell) override;

  // The trace's "document" field: {"path": ..., "dirty": ...} (also in walk rows).
  void addDocumentTrace(app::TraceRow& row) const;

  // Building mode (building_mode.h) lends the editor one shot at a time: the shot open
  // now (null: none), taken away (the editor is then empty), or shown (fitted, nothing
  // selected). `planMode` set: B and a panel button go to that mode (the plan).
  const Document* document() const { return doc_ ? &*doc_ : nullptr; }
  Document* document() { return doc_ ? &*doc_ : nullptr; }
  std::optional<Document> takeDocument(app::Shell& shell);
  void showDocument(app::Shell& shell, Document doc);
  void setPlanMode(std::string planMode) { planMode_ = std::move(planMode); }
  // Where a layout file opened here (dropped, or openFile) goes: building mode.
  void setLayoutOpener(std::function<void(app::Shell&, const std::filesystem::path&)> opener) {
    layoutOpener_ = std::move(opener);
  }
  // Asked first when the window closes (building mode: true when the shot open is one
  // of its building's and it asks about all the building's changes instead).
  void setCloseAsker(std::function<bool(app::Shell&)> asker) { closeAsker_ = std::move(asker); }

 private:
  struct Drag {
    int corner = -1;  // P1..P8, or kPrincipalPointHandle (handle_warnings.h)
    metrology::Shot before;  // the shot when the drag began: one undo step on release
    glm::dvec2 lastCursorPx{0.0};
  };

  void openFile(app::Shell& shell, const std::filesystem::path& path);
  void layOut(app::Shell& shell);  // the canvas's area from the window's size
  void onKey(app::Shell& shell, const app::KeyEvent& event);
  void onButton(app::Shell& shell, const app::MouseButtonEvent& event);
  void onCursor(const glm::dvec2& positionPx);
  void onDrop(app::Shell& shell, const app::DropEvent& event);
  bool overCanvas(const glm::dvec2& windowPx) const;
  bool held(int key) const { return key >= 0 && key <= GLFW_KEY_LAST && keys_[key]; }
  bool shiftHeld() const { return held(GLFW_KEY_LEFT_SHIFT) || held(GLFW_KEY_RIGHT_SHIFT); }
  bool ctrlHeld() const { return held(GLFW_KEY_LEFT_CONTROL) || held(GLFW_KEY_RIGHT_CONTROL); }
  bool altHeld() const { return held(GLFW_KEY_LEFT_ALT) || held(GLFW_KEY_RIGHT_ALT); }

  // Edits, each one undo step (a drag: one step when it ends).
  void endDrag(bool keep);
  void nudge(const glm::dvec2& deltaPx);
  void select(int corner);
  void undo(app::Shell& shell);
  void redo(app::Shell& shell);
  // E: the eight corners fitted to the photo's edges from where they are (Document::fitCorners).
  void fitCorners(app::Shell& shell);
  void save(app::Shell& shell);
  void walk(app::Shell& shell);
  void applyEdit(app::Shell& shell, const metrology::Shot& after, const std::string& label);

  void remeasure();  // when the shot changed since the last measurement
  std::optional<Loupe> loupe() const;

  // files_ui.cpp: Open (the browser, recent files, drops), Save As, Export, autosave
  // and recovery, and asking before unsaved edits are lost (Save / Discard / Cancel).
  static std::vector<app::ReplayVerb> filesReplayVerbs(const std::filesystem::path& scriptDir);
  bool onFilesReplayEvent(app::Shell& shell, const app::ModeEvent& event);  // true: one of its events
  void requestOpen(app::Shell& shell, const std::filesystem::path& path);  // asks first if edits would be lost
  void afterOpen(app::Shell& shell, const std::filesystem::path& opened);
  void leaveDocument();  // before another file replaces this one
  void afterSave(app::Shell& shell);
  void openBrowser(app::Shell& shell, BrowserPurpose purpose);
  void confirmBrowser(app::Shell& shell, const std::optional<std::filesystem::path>& chosen = std::nullopt);
  void saveAs(app::Shell& shell, const std::filesystem::path& path);
  void exportTo(app::Shell& shell, const std::filesystem::path& path);  // off the UI thread
  void finishExport(app::Shell& shell, bool wait);  // says how it went, once it is done
  void answerUnsaved(app::Shell& shell, int answer);  // 0 save, 1 discard, 2 cancel
  void answerRecovery(app::Shell& shell, bool recover);
  bool onFilesKey(app::Shell& shell, const app::KeyEvent& event);  // true: taken
  bool dialogOpen() const { return files_.browser || files_.unsaved || files_.recovered; }
  void updateFiles(app::Shell& shell, double stepS);
  void traceFiles(app::TraceRow& row) const;
  void drawFiles(app::Shell& shell);
  void drawBrowser(app::Shell& shell);
  void drawUnsaved(app::Shell& shell);
  void drawRecovery(app::Shell& shell);
  void drawOpenChoices(app::Shell& shell);  // the empty window's: open, recent files
  void drawExportButtons(app::Shell& shell);  // the panel's Export .wrl and .glb
  bool recordedButton(const char* label, const std::string& name);
  void recordItem(const std::string& name);  // the last item's rectangle, for the trace

  // panels.cpp: the side panel (document, measurement, warnings, camera, corners, keys).
  void drawPanel(app::Shell& shell);
  void drawMeasurement();
  // camera_panel.cpp: the camera (EXIF, focal length and sensor, principal point and
  // its handle, the scale from the camera height or a reference length).
  void drawCamera(app::Shell& shell);
  void drawCameraOverlay(ImDrawList* list) const;  // the principal point's handle, the reference, the warnings
  int principalHandleAt(const glm::dvec2& windowPx) const;  // kPrincipalPointHandle or -1
  bool pickReference(app::Shell& shell, int corner);  // a click while picking the reference's corners
  void addCameraTrace(app::TraceRow& row) const;      // the trace's "camera" and "handle_warnings"
  void rememberWidget(const char* name);              // the last item's rectangle, for the trace
  void drawCorners(app::Shell& shell);
  // measure_tool.cpp: M, two clicks: a distance on the floor or (Shift) a height, kept in
  // the shot (points, measurements), listed, deleted, drawn, traced ("objects").
  void setMeasuring(app::Shell& shell, bool on);
  bool measureClick(app::Shell& shell);  // a click while measuring (true: taken)
  void deleteObjectMeasure(app::Shell& shell, size_t index);
  metrology::Shot withObjectMeasure(const metrology::Shot& shot, glm::dvec2 from, glm::dvec2 to, bool height) const;
  glm::dvec2 measureSnap(glm::dvec2 px) const;
  std::optional<std::pair<glm::dvec2, glm::dvec2>> verticalThrough(glm::dvec2 floorPx) const;
  Result<metrology::PointMeasurement> measureObjects(const metrology::Shot& shot) const;
  void remeasureObjects();
  struct MeasuringNow {
    std::optional<std::pair<glm::dvec2, glm::dvec2>> vertical;  // for a height
    std::optional<glm::dvec2> target;                           // the second point
    std::string text;                                            // its value, or why none
  };
  MeasuringNow measuringNow() const;
  void drawMeasureOverlay(ImDrawList* list, const MeasuringNow& now) const;
  void drawMeasurements(app::Shell& shell);
  void addObjectsTrace(app::TraceRow& row) const;
  // stand_up_tool.cpp: U, a rectangle dragged (or a polygon clicked) around an object
  // stands it up in the model (the shot's cutouts), listed, renamed, deleted, drawn,
  // traced ("cutouts").
  // O: the same, an outline around a doorway or an opening in a side wall opens it with
  // a room behind (a cutout of shape "opening").
  void setOutlining(app::Shell& shell, bool on, metrology::CutoutShape shape = metrology::CutoutShape::kFlat);
  bool outlineButton(app::Shell& shell, bool down);  // a press or release while outlining (true: taken)
  bool outlineKey(app::Shell& shell, int key);        // Enter, Backspace, Esc on a polygon being clicked (true: taken)
  void standUpOutline(app::Shell& shell, const std::vector<glm::dvec2>& outline);
  void deleteCutout(app::Shell& shell, size_t index);
  void setCutoutShape(app::Shell& shell, size_t index, metrology::CutoutShape shape);
  std::optional<modeling::StandingObject> checkStandUp(app::Shell& shell, const metrology::Cutout& cutout);
  std::optional<modeling::SideRoom> checkOpening(app::Shell& shell, const metrology::Cutout& cutout);
  void drawCutoutOverlay(ImDrawList* list) const;
  void drawCutouts(app::Shell& shell);
  void addCutoutsTrace(app::TraceRow& row) const;
  void drawCanvasOverlay();
  void drawEmptyHint(app::Shell& shell);

  EditModeOptions options_;
  ModelWalk& walk_;
  std::optional<Document> doc_;
  std::string openError_;  // why the last file could not be opened
  engine::ImageHandle photo_;
  glm::ivec2 windowSize_{0};
  double panelWidthPx_ = 0;
  double panelHeightPx_ = 0;  // the side panel above the 3D preview's column
  Preview preview_;           // the 3D preview pane (preview.h), under the panel
  WindowRect previewToolbar_;
  Canvas canvas_;
  std::vector<WindowRect> uiRects_;  // ImGui windows over the canvas, as last drawn

  // The measurement of the shot as it is (or why it cannot be measured).
  std::optional<metrology::Shot> measuredShot_;
  LiveMeasurement live_;

  int selected_ = -1;
  std::optional<Drag> drag_;
  int lastMoved_ = -1;  // the corner dragged or nudged last: the warnings name it
  // Snapping a dragged corner onto its edge junction: the photo's snapper, made at the
  // first drag of a document; the junction the corner would go to on release (shown
  // while dragging; Alt keeps the corner where it is).
  struct SnapRequest {
    int corner = -1;
    std::array<glm::dvec2, metrology::kCornerCount> box{};
    glm::dvec2 at{0.0};
    double reachPx = 0;
    std::shared_ptr<const metrology::detect::CornerSnapper> snapper;
    bool sameAs(const SnapRequest& o) const { return corner == o.corner && box == o.box && at == o.at && reachPx == o.reachPx; }
  };
  struct SnapDone {
    SnapRequest request;
    std::optional<metrology::detect::CornerSnap> snap;
  };
  std::unique_ptr<LatestWorker<SnapRequest, SnapDone>> snapWorker_;
  std::optional<SnapDone> snapShown_;  // the latest answer, for the ring
  std::optional<SnapRequest> snapRequest();  // for the corner being dragged, where it is
  void updateSnap();
  std::optional<glm::dvec2> currentSnap() const;  // the ring's answer, when it is for where the corner is
  // The boxes of the shot's box cutouts, fitted to the photo on a worker whenever the
  // shot changes (GrabCut and the fit: about half a second on a large photo), drawn on
  // the photo while they are the shot's as it is. Each box: its front's corners
  // (bottom-left, bottom-right, top-right, top-left as the camera sees it), then the back's
  // behind each.
  struct BoxFitRequest {
    metrology::Shot shot;
    cv::Mat photo;
    metrology::Measurement measurement;
  };
  struct BoxFitDone {
    metrology::Shot shot;
    std::vector<std::pair<std::string, std::array<glm::dvec3, 8>>> boxes;
  };
  std::unique_ptr<LatestWorker<BoxFitRequest, BoxFitDone>> boxFitWorker_;
  std::optional<metrology::Shot> boxFitAsked_;
  std::optional<BoxFitDone> boxFitShown_;
  void updateBoxFits();
  // The shown box of the cutout named so, in photo pixels (nullopt: none for the shot as it is).
  std::optional<std::array<glm::dvec2, 8>> shownBoxPx(const std::string& name) const;
  // Why the cutout `name` could not stand up in the preview's full model of the shot as
  // it is (it is left painted), or nothing (it stood up, or no such model yet).
  std::optional<std::string> leftPainted(const std::string& name) const;
  std::optional<glm::dvec2> panFrom_;  // the cursor when a pan began or last moved
  int panButton_ = -1;
  glm::dvec2 cursorPx_{-1.0};
  long step_ = 0;
  long nudgeLoupeUntil_ = -1;  // the loupe shows until this step after a nudge
  std::array<bool, GLFW_KEY_LAST + 1> keys_{};
  EditFiles files_;
  bool showKeys_ = false;
  bool showOverlay_ = true;  // H hides the handles and guides, to see the photo under them
  // Picking the reference length's two corners on the canvas: the first one picked, or
  // -1 while waiting for it (camera_panel.cpp).
  bool pickingReference_ = false;
  int referencePickFrom_ = -1;
  // The measure tool: on (M), its first point once clicked (photo pixels), and the
  // shot's measurements as last measured (remeasure) or why they do not measure.
  bool measuring_ = false;
  std::optional<glm::dvec2> measureFrom_;
  std::optional<metrology::PointMeasurement> objects_;
  std::string objectsError_;
  std::vector<std::array<char, 64>> nameBuffers_;  // the Measurements list's name fields
  int renaming_ = -1;                               // the one being typed into, or -1
  bool outlining_ = false;                          // U: dragging rectangles stands objects up
  metrology::CutoutShape outlineShape_ = metrology::CutoutShape::kFlat;  // kOpening: O, opening doorways
  std::optional<glm::dvec2> outlineFrom_;           // where the button went down (photo pixels), while held
  std::vector<glm::dvec2> outlinePolygon_;          // a polygon's points clicked so far (photo pixels)
  std::vector<std::array<char, 64>> cutoutNameBuffers_;
  int renamingCutout_ = -1;
  // The Camera panel's widgets as last drawn (window pixels), by name: the trace's
  // "camera"."widgets", so that replay scripts can click them.
  std::vector<std::pair<std::string, WindowRect>> widgetRects_;
  std::string walkModelFrom_;  // the last W's model: "preview" (the preview's full one) or "built"
  // W's model being built on a thread of its own, the window drawing on meanwhile
  // (a replay waits for it in the frame's step, as for an export).
  struct PendingWalk {
    metrology::Shot shot;
    metrology::Measurement measurement;
    std::future<Result<engine::Scene>> scene;
    std::chrono::steady_clock::time_point started;
  };
  std::optional<PendingWalk> pendingWalk_;
  void finishWalk(app::Shell& shell, bool wait);
  std::string planMode_;     // building_mode.h's name while a building is open
  std::function<void(app::Shell&, const std::filesystem::path&)> layoutOpener_;
  std::function<bool(app::Shell&)> closeAsker_;

  // The Camera panel's number fields (number_field.h): the one being typed into, the last refusal.
  NumberFields fields_;
};

}  // namespace pw::edit
