// preview_bench: the editor's 3D preview and opening a photo (issue 13's speed), on a
// 12-megapixel photo (corridor_b's ground-truth render scaled to 4000 x 3000, its
// exact corners with it), medians, each against baselines in the same run:
//   1. a rebuild from the reduced photo (1024 x 768), as while a corner is dragged
//      (budget 50 ms): measure, cut the corridor model, stage it for the GPU
//      (buildPreviewModel, on the worker), and the swap the UI thread does
//      (Renderer::replaceScene of the staged scene); baselines: the measurement alone,
//      and reducing the photo (once per document);
//   2. the full-resolution rebuild after the release (budget 1 s, off the UI thread):
//      asked of a PreviewBuilder and timed until its result is there, with the worker's
//      own wall and thread-CPU time;
//   3. opening the photo as a JPEG with corner detection to the first frame with
//      corners (budget 1 s): Document::open, the photo uploaded (Renderer::addImage) and
//      one 1280 x 720 frame of it drawn (renderViews); baselines: decoding the JPEG
//      alone, Document::open alone;
//   4. W's model, built and uploaded;
//   5. a corner dragged with a person stood up (the random scene TUNE 0's standing shot,
//      its photo scaled to 4000 px wide): the reduced and the full rebuild with the
//      cut-outs kept between rebuilds (the worker's modeling::CutOutCache), against cut
//      again each time (GrabCut and the fill) and against no person.
// Wall clocks on a shared machine count other people's work too; the thread CPU times
// do not (on lavapipe the GPU's work is on other threads).
// Usage: preview_bench [RUNS]   (default 7; PW_DEVICE=cpu for lavapipe)
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <thread>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "bench/bench_timing.h"
#include "editor/edit/canvas.h"
#include "editor/edit/document.h"
#include "editor/edit/model_walk.h"
#include "editor/edit/preview_build.h"
#include "engine/gpu/renderer.h"
#include "metrology/measure.h"
#include "modeling/corridor_model.h"
#include "modeling/shot_file.h"
#include "tests/support/groundtruth.h"

namespace {

using namespace pw;
using namespace pw::edit;
using pw::bench::median;
using pw::bench::medianMs;
namespace fs = std::filesystem;

double threadCpuMs() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) / 1e6;
}

double processCpuMs() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) / 1e6;
}

double msSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// Where a rebuild's time goes: the model (measure, cut the textures, make the scene)
// and the staging, medians.
struct Parts {
  double modelMs = 0, stageMs = 0;
  double texels = 0;  // of the model's textures
};
Parts partsOf(const engine::Renderer& renderer, const metrology::Shot& shot, const cv::Mat& photo,
              PreviewResolution resolution, int runs) {
  std::vector<double> model, stage;
  Parts parts;
  for (int i = 0; i < runs; ++i) {
    const metrology::Shot inPhoto = scaledShot(shot, {photo.cols, photo.rows});
    auto start = std::chrono::steady_clock::now();
    auto measurement = metrology::measureCorridor(inPhoto);
    if (!measurement) return parts;
    auto scene = buildCorridorScene(inPhoto, photo, *measurement, previewModelOptions(resolution));
    if (!scene) return parts;
    model.push_back(msSince(start));
    start = std::chrono::steady_clock::now();
    (void)renderer.stageScene(*scene);
    stage.push_back(msSince(start));
    parts.texels = 0;
    for (const engine::Shape& shape : scene->shapes) {
      if (!shape.appearance || !shape.appearance->texture || !shape.appearance->texture->image) continue;
      const engine::Image& texture = *shape.appearance->texture->image;
      parts.texels += double(texture.width) * texture.height;
    }
  }
  parts.modelMs = median(model);
  parts.stageMs = median(stage);
  return parts;
}

int fail(const std::string& message) {
  std::fprintf(stderr, "preview_bench: error: %s\n", message.c_str());
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  const int runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 7;
  const groundtruth::GroundTruth truth = groundtruth::loadGroundTruth("corridor_b");
  const cv::Mat source = cv::imread(truth.image.string());
  if (source.empty()) return fail("cannot read " + truth.image.string());
  cv::Mat photo;
  cv::resize(source, photo, cv::Size(4000, 3000), 0, 0, cv::INTER_CUBIC);
  const double k = 4000.0 / truth.imageWidth;
  metrology::Shot shot;
  shot.imagePath = "corridor_12mp.jpg";
  shot.imageWidth = 4000;
  shot.imageHeight = 3000;
  shot.focalPx = truth.focalPx * k;
  shot.cameraHeightM = truth.cameraHeightM;
  for (int c = 0; c < metrology::kCornerCount; ++c) shot.cornersPx[c] = (truth.cornersPx[c] + 0.5) * k - 0.5;

  engine::RendererOptions options;
  options.profile = engine::RenderProfile::kInteractive;
  auto created = engine::Renderer::create(options);
  if (!created) return fail(created.message());
  engine::Renderer& renderer = **created;

  // 1. The reduced rebuild, and the swap.
  const double reduceMs = medianMs(runs, [&] { (void)reducePhoto(photo, kReducedPhotoSidePx); });
  const cv::Mat reduced = reducePhoto(photo, kReducedPhotoSidePx);
  const double measureMs = medianMs(runs, [&] { (void)metrology::measureCorridor(shot); });
  auto first = buildPreviewModel(renderer, shot, reduced, PreviewResolution::kReduced);
  if (!first) return fail(first.message());
  auto handle = renderer.addScene(std::move(first->staged));
  if (!handle) return fail(handle.message());
  std::vector<double> reducedWall, reducedCpu, reducedProcessCpu, swapMs;
  metrology::Shot dragged = shot;
  for (int i = 0; i < 3 * runs; ++i) {
    dragged.cornersPx[metrology::P5] += glm::dvec2(0.7, -0.3);  // a drag step
    const double cpu = threadCpuMs(), processCpu = processCpuMs();
    const auto start = std::chrono::steady_clock::now();
    auto model = buildPreviewModel(renderer, dragged, reduced, PreviewResolution::kReduced);
    reducedWall.push_back(msSince(start));
    reducedCpu.push_back(threadCpuMs() - cpu);
    reducedProcessCpu.push_back(processCpuMs() - processCpu);
    if (!model) return fail(model.message());
    const auto swapStart = std::chrono::steady_clock::now();
    if (Status swapped = renderer.replaceScene(*handle, std::move(model->staged)); !swapped) return fail(swapped.message());
    swapMs.push_back(msSince(swapStart));
  }

  // 2. The full rebuild, on the worker.
  std::vector<double> fullAskedMs, fullWorkerMs, fullSwapMs, fullGpuMs;
  {
    PreviewBuilder builder(renderer);
    for (int i = 0; i < runs; ++i) {
      dragged.cornersPx[metrology::P5] += glm::dvec2(0.7, -0.3);
      const auto start = std::chrono::steady_clock::now();
      builder.request({uint64_t(i + 1), 1, dragged, photo, false, false});
      std::vector<PreviewBuilder::Done> done;
      while (done.empty()) {
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
        done = builder.takeDone();
      }
      fullAskedMs.push_back(msSince(start));
      if (!done.front().model) return fail(done.front().model.message());
      fullWorkerMs.push_back(done.front().model->buildMs);
      const auto swapStart = std::chrono::steady_clock::now();
      if (Status swapped = renderer.replaceScene(*handle, std::move(done.front().model->staged)); !swapped) {
        return fail(swapped.message());
      }
      fullSwapMs.push_back(msSince(swapStart));
      // Until the GPU has it (on lavapipe the copies and mip blits run on the CPU; a
      // frame after the swap waits for them in the queue).
      const auto gpuStart = std::chrono::steady_clock::now();
      if (Status idle = renderer.submitAndWait([](VkCommandBuffer) {}); !idle) return fail(idle.message());
      fullGpuMs.push_back(msSince(gpuStart));
    }
  }
  std::vector<double> fullCpu, fullProcessCpu;
  for (int i = 0; i < std::max(1, runs / 2); ++i) {
    const double cpu = threadCpuMs(), processCpu = processCpuMs();
    auto model = buildPreviewModel(renderer, shot, photo, PreviewResolution::kFull);
    fullCpu.push_back(threadCpuMs() - cpu);
    fullProcessCpu.push_back(processCpuMs() - processCpu);
    if (!model) return fail(model.message());
  }

  const Parts reducedParts = partsOf(renderer, shot, reduced, PreviewResolution::kReduced, runs);
  const Parts fullParts = partsOf(renderer, shot, photo, PreviewResolution::kFull, std::max(1, runs / 2));

  // 4. W's model (the walk's, full resolution with every texture layer): built on a
  // thread of its own since W no longer blocks the window (EditMode::walk), then
  // uploaded on the UI thread (WalkMode::open: Renderer::addScene), which is what the
  // window waits for. Against the preview's full rebuild above.
  std::vector<double> walkBuildMs, walkUploadMs;
  auto walkMeasurement = metrology::measureCorridor(shot);
  if (!walkMeasurement) return fail(walkMeasurement.message());
  for (int i = 0; i < std::max(1, runs / 2); ++i) {
    const auto start = std::chrono::steady_clock::now();
    auto scene = buildCorridorScene(shot, photo, *walkMeasurement);
    walkBuildMs.push_back(msSince(start));
    if (!scene) return fail(scene.message());
    const auto uploadStart = std::chrono::steady_clock::now();
    auto walkHandle = renderer.addScene(*scene);
    walkUploadMs.push_back(msSince(uploadStart));
    if (!walkHandle) return fail(walkHandle.message());
    if (Status idle = renderer.submitAndWait([](VkCommandBuffer) {}); !idle) return fail(idle.message());
    (void)renderer.removeScene(*walkHandle);
  }

  // 3. Opening the photo with detection, to the first frame with corners.
  const fs::path jpeg = fs::path(PW_BINARY_DIR) / "bench" / "preview_bench_12mp.jpg";
  fs::create_directories(jpeg.parent_path());
  if (!cv::imwrite(jpeg.string(), photo, {cv::IMWRITE_JPEG_QUALITY, 95})) return fail("cannot write " + jpeg.string());
  const double decodeMs = medianMs(runs, [&] { (void)cv::imread(jpeg.string()); });
  bool detected = true;
  const double openMs = medianMs(runs, [&] {
    auto doc = Document::open(jpeg);
    detected = detected && doc && doc->detectionConfidence(0).has_value();
  });
  std::vector<double> firstFrameMs, firstFrameCpu;
  for (int i = 0; i < runs; ++i) {
    const double processCpu = processCpuMs();
    const auto start = std::chrono::steady_clock::now();
    auto doc = Document::open(jpeg);
    if (!doc) return fail(doc.message());
    auto image = renderer.addImage(modeling::imageFromBgr(doc->photo()));
    if (!image) return fail(image.message());
    Canvas canvas;
    canvas.setArea({{0, 0}, {896, 720}}, {doc->photo().cols, doc->photo().rows});
    engine::ImageView view;
    view.image = *image;
    view.transform = canvas.transform();
    view.rect = pixelRect(canvas.area());
    auto frame = renderer.renderViews({view}, 1280, 720);
    if (!frame) return fail(frame.message());
    firstFrameMs.push_back(msSince(start));
    firstFrameCpu.push_back(processCpuMs() - processCpu);
    (void)renderer.removeImage(*image);
  }

  // 5. A person stood up while a corner moves.
  auto standing = modeling::loadShot(fs::path(PW_GROUNDTRUTH_DIR) / "random" / "seed_00000_standing.json");
  if (!standing) return fail(standing.message() + " (cmake --build build --target groundtruth)");
  cv::Mat bigStanding;
  const int bigWidth = 4000, bigHeight = static_cast<int>(std::lround(4000.0 * standing->image.rows / standing->image.cols));
  cv::resize(standing->image, bigStanding, cv::Size(bigWidth, bigHeight), 0, 0, cv::INTER_CUBIC);
  const metrology::Shot standingShot = scaledShot(standing->shot, {bigWidth, bigHeight});
  metrology::Shot withoutPerson = standingShot;
  withoutPerson.cutouts.clear();
  const cv::Mat reducedStanding = reducePhoto(bigStanding, kReducedPhotoSidePx);
  struct Timed {
    double reducedMs = 0, fullMs = 0;
  };
  const auto dragWith = [&](const metrology::Shot& base, modeling::CutOutCache* cache) -> Result<Timed> {
    metrology::Shot moved = base;
    std::vector<double> reducedMs, fullMs;
    for (int i = 0; i < runs; ++i) {
      moved.cornersPx[metrology::P5] += glm::dvec2(0.7, -0.3);
      auto start = std::chrono::steady_clock::now();
      auto reducedModel = buildPreviewModel(renderer, moved, reducedStanding, PreviewResolution::kReduced, cache);
      reducedMs.push_back(msSince(start));
      if (!reducedModel) return reducedModel.error();
      start = std::chrono::steady_clock::now();
      auto fullModel = buildPreviewModel(renderer, moved, bigStanding, PreviewResolution::kFull, cache);
      fullMs.push_back(msSince(start));
      if (!fullModel) return fullModel.error();
    }
    return Timed{median(reducedMs), median(fullMs)};
  };
  modeling::CutOutCache cutOuts;
  (void)buildPreviewModel(renderer, standingShot, reducedStanding, PreviewResolution::kReduced, &cutOuts);  // as the
  (void)buildPreviewModel(renderer, standingShot, bigStanding, PreviewResolution::kFull, &cutOuts);  // press's build
  auto kept = dragWith(standingShot, &cutOuts);
  // With a second outline that cannot stand up (the person's moved above the horizon:
  // left painted), the fill is about the person alone, kept too (CutOutCache::behindStood).
  metrology::Shot withLeftPainted = standingShot;
  metrology::Cutout above = standingShot.cutouts.at(0);
  double lowest = 0;
  for (const glm::dvec2& p : above.outlinePx) lowest = std::max(lowest, p.y);
  for (glm::dvec2& p : above.outlinePx) p.y -= lowest - 0.3 * bigHeight;  // the camera is nearly level
  above.name = "above";
  withLeftPainted.cutouts.push_back(above);
  modeling::CutOutCache leftPaintedCutOuts;
  (void)buildPreviewModel(renderer, withLeftPainted, reducedStanding, PreviewResolution::kReduced, &leftPaintedCutOuts);
  (void)buildPreviewModel(renderer, withLeftPainted, bigStanding, PreviewResolution::kFull, &leftPaintedCutOuts);
  auto keptLeftPainted = dragWith(withLeftPainted, &leftPaintedCutOuts);
  auto cutAgain = dragWith(standingShot, nullptr);
  auto noPerson = dragWith(withoutPerson, nullptr);
  if (!kept || !cutAgain || !noPerson || !keptLeftPainted) return fail("the standing shot does not build");
  // The editor's check when an outline is closed (on the UI thread): the person stood
  // up alone, without the fill behind her, against with it.
  auto standingMeasurement = metrology::measureCorridor(standingShot);
  if (!standingMeasurement) return fail(standingMeasurement.message());
  const auto checkMs = [&](modeling::StandUpParts parts) {
    return medianMs(runs, [&] {
      (void)modeling::standUpObjects(bigStanding, *standingMeasurement, standingShot.cutouts, nullptr, parts);
    });
  };
  const double checkWithFillMs = checkMs(modeling::StandUpParts::kObjectsAndFill);
  const double checkMsOnly = checkMs(modeling::StandUpParts::kObjectsOnly);
  // The same outline stood up as a box (the stand-up list's "box"): GrabCut as before,
  // then the box's fit to the mask.
  std::vector<metrology::Cutout> asBoxes = standingShot.cutouts;
  for (metrology::Cutout& c : asBoxes) c.shape = metrology::CutoutShape::kBox;
  const double checkBoxMs = medianMs(runs, [&] {
    (void)modeling::standUpObjects(bigStanding, *standingMeasurement, asBoxes, nullptr, modeling::StandUpParts::kObjectsOnly);
  });

  std::printf("preview_bench: %s, a 4000 x 3000 photo (corridor_b scaled), %d runs, medians in ms\n",
              renderer.deviceName().c_str(), runs);
  std::printf("  baseline: measure the corners alone            %8.2f\n", measureMs);
  std::printf("  baseline: reduce the photo to 1024 px (once)   %8.2f\n", reduceMs);
  std::printf("  reduced rebuild (measure, model, stage)        %8.2f  wall; CPU %.2f this thread, %.2f all threads (budget 50)\n",
              median(reducedWall), median(reducedCpu), median(reducedProcessCpu));
  std::printf("    of which: model %.2f, staging %.2f (%.2f Mtexels)\n", reducedParts.modelMs, reducedParts.stageMs,
              reducedParts.texels / 1e6);
  std::printf("  swap of the staged model (UI thread)           %8.2f\n", median(swapMs));
  std::printf("  full rebuild on the worker, asked to done      %8.2f  (worker %.2f wall; CPU %.2f its thread, %.2f all; budget 1000)\n",
              median(fullAskedMs), median(fullWorkerMs), median(fullCpu), median(fullProcessCpu));
  std::printf("    of which: model %.2f, staging %.2f (%.2f Mtexels)\n", fullParts.modelMs, fullParts.stageMs,
              fullParts.texels / 1e6);
  std::printf("  swap of the full model (UI thread)             %8.2f  (then %.2f until the GPU has copied it)\n",
              median(fullSwapMs), median(fullGpuMs));
  std::printf("  W's model, built off the UI thread             %8.2f  (the full preview's above is its baseline)\n",
              median(walkBuildMs));
  std::printf("  W's model uploaded (UI thread: the window waits) %6.2f  (budget 100)\n", median(walkUploadMs));
  std::printf("  baseline: decode the 12 MP JPEG alone          %8.2f\n", decodeMs);
  std::printf("  baseline: Document::open (decode, detect)      %8.2f  (%s)\n", openMs,
              detected ? "corners detected" : "NO corners detected: a default box");
  std::printf("  open to the first frame with corners           %8.2f  (CPU %.2f all threads; open, upload, one 1280x720 frame; budget 1000)\n",
              median(firstFrameMs), median(firstFrameCpu));
  std::printf("a person stood up (TUNE 0's standing shot, %d x %d), a corner dragged: reduced / full rebuild\n", bigWidth,
              bigHeight);
  std::printf("  baseline: no person                            %8.2f / %8.2f\n", noPerson->reducedMs, noPerson->fullMs);
  std::printf("  baseline: the person cut out again each time   %8.2f / %8.2f\n", cutAgain->reducedMs, cutAgain->fullMs);
  std::printf("  the person's cut-outs kept (the worker's cache) %7.2f / %8.2f\n", kept->reducedMs, kept->fullMs);
  std::printf("  the same, a second object left painted         %8.2f / %8.2f  (the fill about the person alone kept)\n",
              keptLeftPainted->reducedMs, keptLeftPainted->fullMs);
  std::printf("  baseline: the outline's check with the fill    %8.2f\n", checkWithFillMs);
  std::printf("  the outline's check, the object alone (UI thread) %5.2f\n", checkMsOnly);
  std::printf("  the same outline's check as a box (UI thread)  %8.2f\n", checkBoxMs);
  return 0;
}
