// Views benchmark (not a test): medians, each against a baseline in the same run, of
//   1. a 12-megapixel photo (4000x3000 RGBA) made an image for ImageViews: how long
//      Renderer::addImage blocks the calling thread, and how long until the GPU has it
//      with its mip chain (addImage, then an empty submitAndWait, which waits for
//      everything queued before it), against copying its 48 MB in memory;
//      calls are timed by the wall clock and by the calling thread's CPU time (on
//      lavapipe the "GPU" shares the CPUs, so an upload still running slows the next
//      call's wall clock);
//   2. a textured scene replaced (Renderer::replaceScene), as the editor does while a
//      corner is dragged (a wall texture cut from a reduced photo, 1000x750) and after
//      (from the full photo, 4000x3000): the time the call blocks, and until the GPU
//      is done; and the same upload in halves, stageScene (which may run on a worker
//      thread) and replaceScene of the staged scene (the renderer's thread);
//   3. an offscreen 1280x720 frame of the photo fitted by an ImageView (minified
//      through its mip chain) and one magnified 16x, against an empty frame.
// Usage: views_bench [RUNS]   (default 9; PW_DEVICE=cpu for lavapipe)
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <ctime>
#include <string>
#include <vector>

#include "bench/bench_timing.h"
#include "engine/gpu/renderer.h"
#include "engine/scene/sample_scene.h"

namespace {

using namespace pw::engine;
using pw::bench::medianMs;

// CPU time of the whole process (all of lavapipe's threads): on a shared machine the
// wall clock also counts other people's work, this does not.
double processCpuMs() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) / 1e6;
}

double threadCpuMs() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) / 1e6;
}

// Medians of the wall clock and of the calling thread's CPU time: what a call costs
// the thread that makes it, which other people's load disturbs far less.
struct Timing {
  double wallMs = 0;
  double threadMs = 0;
};
Timing timed(int runs, const std::function<void()>& work) {
  std::vector<double> wall, thread;
  for (int i = 0; i < runs; ++i) {
    const double cpuStart = threadCpuMs();
    const auto start = std::chrono::steady_clock::now();
    work();
    wall.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    thread.push_back(threadCpuMs() - cpuStart);
  }
  return {pw::bench::median(wall), pw::bench::median(thread)};
}

int fail(const std::string& message) {
  std::fprintf(stderr, "views_bench: %s\n", message.c_str());
  return 1;
}

// A photo-like image: smooth gradients with some texture, so nothing compresses or
// short-cuts (no path here does, but the numbers should not depend on it).
Image photo(int width, int height) {
  Image image = makeImage(width, height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      uint8_t* p = image.pixel(x, y);
      p[0] = uint8_t(x * 255 / width);
      p[1] = uint8_t(y * 255 / height);
      p[2] = uint8_t((x ^ y) & 0xff);
    }
  }
  return image;
}

// The sample room with one wall's texture replaced by `wall`.
Scene roomWithWall(const Image& wall) {
  Scene scene = makeSampleScene();
  auto texture = std::make_shared<Texture>();
  texture->image = std::make_shared<const Image>(wall);
  texture->url = "wall.png";
  auto appearance = std::make_shared<Appearance>(*scene.shapes[0].appearance);
  appearance->texture = texture;
  scene.shapes[0].appearance = appearance;
  return scene;
}

}  // namespace

int main(int argc, char** argv) {
  const int runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 9;
  RendererOptions options;
  options.validation = RendererOptions::Validation::kOff;  // measure the renderer, not the layer
  options.profile = RenderProfile::kInteractive;            // the editor's window
  auto created = Renderer::create(options);
  if (!created) return fail(created.message());
  Renderer& r = **created;
  const auto waitForGpu = [&] {
    if (auto s = r.submitAndWait([](VkCommandBuffer) {}); !s) std::exit(fail(s.message()));
  };
  std::printf("device: %s, %d runs each\n", r.deviceName().c_str(), runs);

  // 1. The photo.
  const Image full = photo(4000, 3000);
  double copied = 0;
  const Timing copying = timed(runs, [&] {
    std::vector<uint8_t> copy(full.rgba);
    copied += copy[copy.size() / 2];
  });
  std::vector<ImageHandle> handles;
  const Timing add = timed(runs, [&] {
    auto handle = r.addImage(full);
    if (!handle) std::exit(fail(handle.message()));
    handles.push_back(*handle);
  });
  waitForGpu();
  for (ImageHandle h : handles) (void)r.removeImage(h);
  handles.clear();
  const double addAndGpuMs = medianMs(runs, [&] {
    auto handle = r.addImage(full);
    if (!handle) std::exit(fail(handle.message()));
    waitForGpu();
    (void)r.removeImage(*handle);
  });
  std::printf("wall (the calling thread's CPU) in ms\n");
  std::printf("12 MP photo: copying its 48 MB in memory  %7.1f (%5.1f) (baseline)\n", copying.wallMs, copying.threadMs);
  std::printf("12 MP photo: addImage blocks the caller   %7.1f (%5.1f)\n", add.wallMs, add.threadMs);
  std::printf("12 MP photo: addImage until the GPU has it with 13 mip levels %7.1f\n", addAndGpuMs);

  // 2. A scene replaced while dragging (reduced photo) and after (full photo).
  const Image reduced = photo(1000, 750);
  const Scene dragging = roomWithWall(reduced), released = roomWithWall(full);
  auto model = r.addScene(dragging);
  if (!model) return fail(model.message());
  for (const auto& [name, scene] : {std::pair("reduced (1000x750 wall)", &dragging), std::pair("full (4000x3000 wall)", &released)}) {
    const Timing block = timed(runs, [&] {
      if (auto s = r.replaceScene(*model, *scene); !s) std::exit(fail(s.message()));
    });
    waitForGpu();
    const double doneMs = medianMs(runs, [&] {
      if (auto s = r.replaceScene(*model, *scene); !s) std::exit(fail(s.message()));
      waitForGpu();
    });
    // Staged on another thread (stageScene), the renderer's thread only swaps it in.
    std::vector<StagedScene> staged;
    const Timing stage = timed(runs, [&] {
      auto s = r.stageScene(*scene);
      if (!s) std::exit(fail(s.message()));
      staged.push_back(std::move(*s));
    });
    size_t next = 0;
    const Timing swap = timed(int(staged.size()), [&] {
      if (auto status = r.replaceScene(*model, std::move(staged[next++])); !status) std::exit(fail(status.message()));
    });
    waitForGpu();
    std::printf("replaceScene, %-24s blocks the caller %6.1f (%5.1f), until the GPU is done %6.1f; staged apart:"
                " stageScene %6.1f (%5.1f) on any thread, replaceScene(staged) %.2f (%.2f)\n",
                name, block.wallMs, block.threadMs, doneMs, stage.wallMs, stage.threadMs, swap.wallMs, swap.threadMs);
  }

  // 3. Frames of the photo against an empty frame, alternated.
  auto handle = r.addImage(full);
  if (!handle) return fail(handle.message());
  constexpr int kWidth = 1280, kHeight = 720;
  const double fit = std::min(double(kWidth) / 4000, double(kHeight) / 3000);
  const glm::vec4 canvas(0.2f, 0.2f, 0.2f, 1.0f);  // an editor's opaque background beyond the photo
  const std::vector<View> fitted{ImageView{*handle, {fit, {0.5 * fit, 0.5 * fit}}, {}, ImageFilter::kAuto, canvas}};
  const std::vector<View> magnified{ImageView{*handle, {16.0, {-16.0 * 2000, -16.0 * 1500}}, {}, ImageFilter::kAuto, canvas}};
  const std::vector<View> none;
  std::vector<double> ms[3], cpuMs[3];
  for (int i = 0; i < runs + 1; ++i) {
    for (int k = 0; k < 3; ++k) {
      const std::vector<View>& views = k == 0 ? none : k == 1 ? fitted : magnified;
      const double cpuStart = processCpuMs();
      const auto start = std::chrono::steady_clock::now();
      auto frame = r.renderViews(views, kWidth, kHeight);
      const double wall = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
      if (!frame) return fail(frame.message());
      if (i == 0) continue;  // warm-up: pipelines and targets are made on first use
      ms[k].push_back(wall);
      cpuMs[k].push_back(processCpuMs() - cpuStart);
    }
  }
  std::printf("1280x720 frame (with read-back), wall (CPU of all threads): empty %.2f (%.2f) ms (baseline), photo fitted"
              " (%.3fx) %.2f (%.2f) ms, photo at 16x %.2f (%.2f) ms\n",
              pw::bench::median(ms[0]), pw::bench::median(cpuMs[0]), fit, pw::bench::median(ms[1]),
              pw::bench::median(cpuMs[1]), pw::bench::median(ms[2]), pw::bench::median(cpuMs[2]));
  return copied < 0 ? 1 : 0;  // keeps the copies from being optimised away
}
