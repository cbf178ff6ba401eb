// edit_bench: one drag step of the editor (issue 13: 16.7 ms or less, so that dragging
// keeps 60 frames a second), medians over one-second drags of P5 (60 steps) on a
// 12-megapixel photo's corners (corridor_b's exact corners scaled to 4000 x 3000).
//
// A step is what the editor's CPU does when the cursor moves: the corner moves
// (Document::setLive), the shot is measured again with its warnings (measureLive) and
// the overlay is built (ImGui draw lists: planes, edges, handles, labels, drawn in the
// four pieces around the loupe, and the loupe's lines; ImGui::Render). Baselines in
// the same run: an empty ImGui frame, the measurement alone, the overlay alone. A drag
// that takes P5 off the box also refits it up to eight times a step to find the corner
// to blame (warnings.h): timed apart.
// The renderer's frame (the photo's two image views) is views_bench's.
#include <cstdio>
#include <vector>

#include <imgui.h>

#include "bench/bench_timing.h"
#include "editor/edit/canvas.h"
#include "editor/edit/document.h"
#include "editor/edit/live_measurement.h"
#include "editor/edit/overlay.h"
#include "tests/support/groundtruth.h"

namespace {

using namespace pw;
using namespace pw::edit;

constexpr int kRuns = 7;
constexpr int kSteps = 60;  // a one-second drag

struct Drag {
  metrology::Shot start;
  Canvas canvas;
  double lastMeasureWidthM = 0;
};

// One editor frame's overlay, as EditMode::drawCanvasOverlay builds it during a drag.
void buildOverlay(const Drag& drag, const metrology::Shot& shot, const LiveMeasurement& live) {
  ImGui::NewFrame();
  ImDrawList* list = ImGui::GetBackgroundDrawList();
  OverlayInput input;
  input.canvas = &drag.canvas;
  input.shot = &shot;
  input.selected = metrology::P5;
  input.vanishing = live.vanishing ? &*live.vanishing : nullptr;
  input.measurement = live.measurement ? &*live.measurement : nullptr;
  const Loupe loupe = placeLoupe(drag.canvas, shot.cornersPx[metrology::P5], metrology::P5,
                                 drag.canvas.toWindow(shot.cornersPx[metrology::P5]));
  const WindowRect& a = drag.canvas.area();
  const WindowRect& h = loupe.rect;
  const WindowRect pieces[4] = {{a.min, {a.max.x, h.min.y}},
                                {{a.min.x, h.max.y}, a.max},
                                {{a.min.x, h.min.y}, {h.min.x, h.max.y}},
                                {{h.max.x, h.min.y}, {a.max.x, h.max.y}}};
  for (const WindowRect& piece : pieces) {
    list->PushClipRect({float(piece.min.x), float(piece.min.y)}, {float(piece.max.x), float(piece.max.y)}, false);
    drawOverlay(list, input);
    list->PopClipRect();
  }
  drawLoupe(list, loupe, shot);
  ImGui::Render();
}

// Median milliseconds per step of a drag of P5 from `start` by `byPx` a step, doing
// `step` each time.
template <class Step>
double perStepMs(const metrology::Shot& start, Step&& step, const glm::dvec2& byPx = {0.02, -0.01}) {
  std::vector<double> perStep;
  for (int run = 0; run < kRuns; ++run) {
    metrology::Shot shot = start;
    const double ms = pw::bench::medianMs(kSteps, [&] {
      shot.cornersPx[metrology::P5] += byPx;
      step(shot);
    });
    perStep.push_back(ms);
  }
  return pw::bench::median(perStep);
}

}  // namespace

int main() {
  const groundtruth::GroundTruth truth = groundtruth::loadGroundTruth("corridor_b");
  const double k = 4000.0 / truth.imageWidth;  // to a 4000 x 3000 photo
  metrology::Shot shot;
  shot.imagePath = "corridor_b (scaled to 12 MP)";
  shot.imageWidth = 4000;
  shot.imageHeight = 3000;
  shot.focalPx = truth.focalPx * k;
  shot.cameraHeightM = truth.cameraHeightM;
  for (int c = 0; c < metrology::kCornerCount; ++c) shot.cornersPx[c] = (truth.cornersPx[c] + 0.5) * k - 0.5;

  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;
  io.DisplaySize = ImVec2(1280, 720);
  io.DeltaTime = 1.0f / 60;
  unsigned char* pixels = nullptr;
  int w = 0, h = 0;
  io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);  // builds the atlas NewFrame needs

  Drag drag;
  drag.start = shot;
  drag.canvas.setArea({{0, 0}, {896, 720}}, {4000, 3000});  // a 1280 x 720 window less its panel

  const LiveMeasurement atStart = measureLive(shot);
  if (!atStart.measurement) {
    std::fprintf(stderr, "error: %s\n", atStart.error.c_str());
    return 1;
  }
  const double emptyFrameMs = perStepMs(shot, [](const metrology::Shot&) {
    ImGui::NewFrame();
    ImGui::Render();
  });
  const double measureMs = perStepMs(shot, [](const metrology::Shot& s) { (void)metrology::measureCorridor(s); });
  const double overlayMs = perStepMs(shot, [&](const metrology::Shot& s) { buildOverlay(drag, s, atStart); });
  Document doc = [] {
    auto opened = Document::open(groundtruth::groundTruthShot("corridor_b"));
    return opened ? std::move(*opened) : Document();
  }();
  const double stepMs = perStepMs(shot, [&](const metrology::Shot& s) {
    doc.setLive(s);
    const LiveMeasurement live = measureLive(doc.shot(), doc.inputOrigins());  // as the editor measures
    buildOverlay(drag, doc.shot(), live);
  });
  // P5 dragged 42 px away from where the box puts it (0.7 px a step, as a hand drags at
  // the fitted zoom): the corners soon make no box, and the warnings refit.
  size_t warnings = 0;
  const double brokenStepMs = perStepMs(
      shot,
      [&](const metrology::Shot& s) {
        doc.setLive(s);
        const LiveMeasurement live = measureLive(doc.shot(), doc.inputOrigins());  // as the editor measures
        warnings = live.warnings.size();
        buildOverlay(drag, doc.shot(), live);
      },
      {0.7, -0.3});
  ImGui::DestroyContext();

  std::printf("edit_bench: one drag step of P5, %d steps x %d runs, medians; budget 16.7 ms (60 fps)\n", kSteps, kRuns);
  std::printf("  baseline: empty ImGui frame              %7.3f ms\n", emptyFrameMs);
  std::printf("  baseline: measure alone                  %7.3f ms\n", measureMs);
  std::printf("  baseline: overlay alone                  %7.3f ms\n", overlayMs);
  std::printf("  drag step: corner, measure, overlay      %7.3f ms  (%.1f%% of the budget; P5 moved 1.2 px)\n", stepMs,
              100 * stepMs / 16.7);
  std::printf("  drag step off the box (refits to blame)  %7.3f ms  (%.1f%% of the budget; P5 moved 42 px, %zu warning(s))\n",
              brokenStepMs, 100 * brokenStepMs / 16.7, warnings);
  return 0;
}
