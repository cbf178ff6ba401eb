// Renderer benchmark (not a test): medians of
//   1. an offscreen frame of the sample room, 1280x720, 4x MSAA, read back to memory,
//      against an empty frame (clear + resolve + read-back) of the same size, same run;
//   2. startup to first PNG: `photowalk render sample -o x.png` end to end, and the
//      same in process (instance + device + pipelines + upload + first frame + PNG).
// Usage: render_bench [FRAMES] [STARTUPS]   (defaults 30 and 5; PW_DEVICE=cpu for lavapipe)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <ctime>

#include <sys/resource.h>
#include <string>
#include <vector>

#include "bench/bench_timing.h"
#include "engine/gpu/renderer.h"
#include "engine/scene/sample_scene.h"

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// CPU time of the whole process (all of lavapipe's threads): on a shared machine the
// wall clock also counts other people's work, this does not.
double processCpuMs() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) / 1e6;
}

// CPU time (user + system) of finished child processes so far.
double childrenCpuMs() {
  rusage usage{};
  getrusage(RUSAGE_CHILDREN, &usage);
  const auto ms = [](const timeval& t) { return double(t.tv_sec) * 1e3 + double(t.tv_usec) / 1e3; };
  return ms(usage.ru_utime) + ms(usage.ru_stime);
}

using pw::bench::median;

int fail(const std::string& message) {
  std::fprintf(stderr, "render_bench: %s\n", message.c_str());
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace pw::engine;
  const int frames = argc > 1 ? std::max(1, std::atoi(argv[1])) : 30;
  const int startups = argc > 2 ? std::max(1, std::atoi(argv[2])) : 5;
  constexpr int kWidth = 1280, kHeight = 720;

  RendererOptions options;
  options.validation = RendererOptions::Validation::kOff;  // measure the renderer, not the layer
  options.msaaSamples = 4;
  auto renderer = Renderer::create(options);
  if (!renderer) return fail(renderer.message());
  Renderer& r = **renderer;
  const Scene sample = makeSampleScene();
  const Camera camera = cameraFromViewpoint(sample.viewpoints[0]);
  const Scene empty;

  // Warm up: pipelines are created on first use, targets on the first frame of a size.
  for (const Scene* scene : {&sample, &empty}) {
    if (auto s = r.setScene(*scene); !s) return fail(s.message());
    if (auto f = r.renderToImage(camera, kWidth, kHeight); !f) return fail(f.message());
  }
  // Alternate the two so that load from other processes hits both alike.
  std::vector<double> sampleMs, emptyMs, sampleCpuMs, emptyCpuMs;
  for (int i = 0; i < frames; ++i) {
    for (const Scene* scene : {&sample, &empty}) {
      if (auto s = r.setScene(*scene); !s) return fail(s.message());
      const double cpuStart = processCpuMs();
      const auto start = Clock::now();
      auto frame = r.renderToImage(camera, kWidth, kHeight);
      const double ms = msSince(start);
      const double cpuMs = processCpuMs() - cpuStart;
      if (!frame) return fail(frame.message());
      (scene == &sample ? sampleMs : emptyMs).push_back(ms);
      (scene == &sample ? sampleCpuMs : emptyCpuMs).push_back(cpuMs);
    }
  }
  if (auto s = r.setScene(sample); !s) return fail(s.message());
  const double sampleMedian = median(sampleMs), emptyMedian = median(emptyMs);
  std::printf("device: %s, %dx%d, %dx MSAA, %d frames each\n", r.deviceName().c_str(), kWidth, kHeight,
              r.msaaSamples(), frames);
  std::printf("sample room frame (draw + resolve + read-back): median %.2f ms (min %.2f, max %.2f)\n", sampleMedian,
              *std::min_element(sampleMs.begin(), sampleMs.end()), *std::max_element(sampleMs.begin(), sampleMs.end()));
  std::printf("empty frame (clear + resolve + read-back):      median %.2f ms (min %.2f, max %.2f)\n", emptyMedian,
              *std::min_element(emptyMs.begin(), emptyMs.end()), *std::max_element(emptyMs.begin(), emptyMs.end()));
  std::printf("ratio sample / empty: %.2f (the scene's own cost: %.2f ms)\n", sampleMedian / emptyMedian,
              sampleMedian - emptyMedian);
  const double sampleCpu = median(sampleCpuMs), emptyCpu = median(emptyCpuMs);
  std::printf("process CPU time per frame (all threads): sample %.2f ms, empty %.2f ms, ratio %.2f\n", sampleCpu,
              emptyCpu, sampleCpu / emptyCpu);
  renderer.value().reset();

  // Startup to first PNG, in process.
  const std::filesystem::path out = std::filesystem::temp_directory_path() / "pw_render_bench.png";
  std::vector<double> inProcessMs, inProcessCpuMs;
  for (int i = 0; i < startups; ++i) {
    const double cpuStart = processCpuMs();
    const auto start = Clock::now();
    auto fresh = Renderer::create(options);
    if (!fresh) return fail(fresh.message());
    if (auto s = (*fresh)->setScene(makeSampleScene()); !s) return fail(s.message());
    auto frame = (*fresh)->renderToImage(camera, kWidth, kHeight);
    if (!frame) return fail(frame.message());
    if (auto saved = saveImage(out, *frame); !saved) return fail(saved.message());
    inProcessMs.push_back(msSince(start));
    inProcessCpuMs.push_back(processCpuMs() - cpuStart);
  }
  // And end to end through the command line (process start, Vulkan loader, driver, PNG).
  const std::string command = std::string(PW_BINARY_DIR) + "/photowalk render sample -o " + out.string() + " > /dev/null";
  std::vector<double> commandMs, commandCpuMs;
  for (int i = 0; i < startups; ++i) {
    const double cpuStart = childrenCpuMs();
    const auto start = Clock::now();
    if (std::system(command.c_str()) != 0) return fail("'" + command + "' failed");
    commandMs.push_back(msSince(start));
    commandCpuMs.push_back(childrenCpuMs() - cpuStart);
  }
  std::filesystem::remove(out);
  std::printf("startup to first PNG, in process (create + upload + frame + PNG): median %.1f ms (CPU %.1f ms) over %d\n",
              median(inProcessMs), median(inProcessCpuMs), startups);
  std::printf("startup to first PNG, photowalk render sample (1280x720):        median %.1f ms (CPU %.1f ms) over %d\n",
              median(commandMs), median(commandCpuMs), startups);
  std::printf("ratio startup (command) / one sample frame: %.1f\n", median(commandMs) / sampleMedian);
  return 0;
}
