// photowalk tour: a smooth walk through a model, rendered to numbered PNG frames and,
// where OpenCV's video writer can, a video (through the video plugin: editor/video/video_file.h).
#include <unistd.h>

#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include <glm/gtc/constants.hpp>
#include <opencv2/imgproc.hpp>

#include "base/atomic_file.h"
#include "base/staging.h"
#include "editor/cli/command.h"
#include "editor/video/video_file.h"
#include "engine/io/model_io.h"
#include "modeling/tour.h"
#include "engine/gpu/renderer.h"

namespace pw::editor {
namespace {
namespace fs = std::filesystem;

constexpr const char* kUsage =
    "usage: photowalk tour MODEL -o DIR [--frames N] [--size WxH] [--video OUT.mp4] [--fps F] [--cpu]\n\n"
    "Renders a walk through MODEL to DIR/frame_0000.png, frame_0001.png, ... A model made\n"
    "by `photowalk build` carries its tour: down each corridor at eye height, into side\n"
    "corridors, turning round at the far ends and back. Other models are toured through\n"
    "their viewpoints.\n\n"
    "  -o, --output DIR   folder for the frames (created if missing)\n"
    "  --frames N         number of frames (default 240)\n"
    "  --size WxH         frame size in pixels (default 1280x720)\n"
    "  --video OUT.mp4    also write a video (MPEG-4; .avi for Motion JPEG)\n"
    "  --fps F            video frame rate (default 30)\n"
    "  --cpu              use the CPU renderer (lavapipe) even if a GPU exists\n"
    "  --allow-folder DIR let the model's Inlines and textures come from DIR too (by\n"
    "                     default only from the model's own folder; repeatable)\n\n"
    "With Vulkan validation on (PW_VALIDATION=1, or a Debug build) any validation message\n"
    "fails the command (exit 1): the frames drawn before it stay, later frames and the\n"
    "video are not written.\n";

// Cameras through the scene's viewpoints in turn, back to the first, eased in and out.
std::vector<engine::Camera> viewpointTour(const engine::Scene& scene, int frames) {
  std::vector<engine::Viewpoint> stops = scene.viewpoints;
  if (stops.empty()) stops.push_back(engine::defaultViewpoint(scene));
  std::vector<engine::Camera> cameras;
  const int legs = static_cast<int>(stops.size());
  for (int i = 0; i < frames; ++i) {
    const double t = frames > 1 ? static_cast<double>(i) / (frames - 1) * legs : 0.0;
    const int leg = std::min(static_cast<int>(t), legs - 1);
    const double u = t - leg, ease = u * u * (3 - 2 * u);
    const engine::Camera a = engine::cameraFromViewpoint(stops[leg]);
    const engine::Camera b = engine::cameraFromViewpoint(stops[(leg + 1) % legs]);
    engine::Camera c = a;
    c.position = glm::mix(a.position, b.position, static_cast<float>(ease));
    c.orientation = glm::slerp(a.orientation, b.orientation, static_cast<float>(ease));
    c.fieldOfViewRad = glm::mix(a.fieldOfViewRad, b.fieldOfViewRad, static_cast<float>(ease));
    if (legs == 1) {  // one viewpoint: turn round on the spot
      c.orientation = glm::angleAxis(static_cast<float>(glm::two_pi<double>() * i / frames), glm::vec3(0, 1, 0)) *
                      a.orientation;
    }
    cameras.push_back(c);
  }
  return cameras;
}

void showProgress(int done, int total) {
  if (!isatty(fileno(stderr))) return;
  const int width = 40, filled = total > 0 ? width * done / total : width;
  std::fprintf(stderr, "\r[%s%s] %3d%%  frame %d/%d", std::string(filled, '#').c_str(),
               std::string(width - filled, ' ').c_str(), total > 0 ? 100 * done / total : 100, done, total);
  if (done == total) std::fprintf(stderr, "\n");
  std::fflush(stderr);
}

// Writes frames (PNG, and the video) on a thread of its own, in order, while the next
// frames render: encoding a 1280x720 frame takes a third as long as drawing it on
// lavapipe, and most of the time on a GPU. At most two frames wait.
class FrameWriter {
 public:
  FrameWriter(fs::path folder, VideoFile* video) : folder_(std::move(folder)), video_(video) {
    thread_ = std::thread([this] { run(); });
  }
  ~FrameWriter() { finish(); }

  // Queues frame `index`; false when an earlier frame failed (see error()).
  bool push(int index, engine::Image image) {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return queue_.size() < 2 || !error_.empty(); });
    if (!error_.empty()) return false;
    queue_.emplace_back(index, std::move(image));
    changed_.notify_all();
    return true;
  }
  // Waits for every queued frame; the first error, or "".
  std::string finish() {
    {
      std::lock_guard lock(mutex_);
      done_ = true;
      changed_.notify_all();
    }
    if (thread_.joinable()) thread_.join();
    return error_;
  }

 private:
  void run() {
    for (;;) {
      std::pair<int, engine::Image> item;
      {
        std::unique_lock lock(mutex_);
        changed_.wait(lock, [&] { return !queue_.empty() || done_; });
        if (queue_.empty()) return;
        item = std::move(queue_.front());
        queue_.pop_front();
        changed_.notify_all();
      }
      const std::string failure = write(item.first, item.second);
      if (!failure.empty()) {
        std::lock_guard lock(mutex_);
        error_ = failure;
        queue_.clear();
        changed_.notify_all();
        return;
      }
    }
  }
  std::string write(int index, engine::Image& image) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.png", index);
    if (auto saved = engine::saveImage(folder_ / name, image); !saved) return saved.message();
    if (video_) {
      cv::Mat rgba(image.height, image.width, CV_8UC4, image.rgba.data()), bgr;
      cv::cvtColor(rgba, bgr, cv::COLOR_RGBA2BGR);
      video_->write(bgr);
    }
    return {};
  }

  fs::path folder_;
  VideoFile* video_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<std::pair<int, engine::Image>> queue_;
  bool done_ = false;
  std::string error_;
  std::thread thread_;  // last: started once the rest exists
};

int runTour(Args& args) {
  const auto output = args.value("--output", "-o");
  const auto framesText = args.value("--frames");
  const auto sizeText = args.value("--size");
  const auto videoPath = args.value("--video");
  const auto fpsText = args.value("--fps");
  const std::vector<std::string> allowed = args.values("--allow-folder");
  engine::RendererOptions options;
  options.forceCpu = args.flag("--cpu");
  const std::vector<std::string> positionals = args.positionals();
  if (auto finished = args.finish(); !finished) return fail(finished.message());
  if (positionals.size() != 1) return fail("tour takes one model; see photowalk tour --help");
  if (!output) return fail("tour needs -o DIR for the frames");

  int frames = 240;
  if (framesText) {
    auto n = parseNumber(*framesText, "--frames");
    if (!n) return fail(n.message());
    if (*n < 1 || *n > 100000 || *n != std::floor(*n)) return fail("--frames must be a whole number from 1 to 100000");
    frames = static_cast<int>(*n);
  }
  std::pair<int, int> size{1280, 720};
  if (sizeText) {
    auto parsed = parseSize(*sizeText, "--size");
    if (!parsed) return fail(parsed.message());
    size = *parsed;
  }
  double fps = 30;
  if (fpsText) {
    auto parsed = parseNumber(*fpsText, "--fps");
    if (!parsed) return fail(parsed.message());
    if (*parsed <= 0 || *parsed > 240) return fail("--fps must be between 0 and 240");
    fps = *parsed;
  }

  if (videoPath) {
    if (auto distinct = checkNotAnInput(*videoPath, "--video", {{"the model", positionals[0]}}); !distinct) {
      return fail(distinct.message());
    }
  }
  // What runs killed before left goes first, however far this one gets: a partial
  // video, and the frames' temporary files (".frame_0007.tmp-PID-N.png").
  if (videoPath) removeLeftoversOf(*videoPath);
  removeStaleTemporaries(*output, ".frame_", ".tmp-");
  std::vector<std::string> warnings;
  auto scene = engine::loadModel(positionals[0], &warnings, std::vector<fs::path>(allowed.begin(), allowed.end()));
  for (const std::string& w : warnings) printWarning(w);
  if (!scene) return fail(scene.message());

  std::vector<engine::Camera> cameras;
  const float fov = scene->viewpoints.empty() ? engine::kDefaultFieldOfViewRad : scene->viewpoints[0].fieldOfViewRad;
  if (scene->tour.size() >= 2) {
    const std::vector<glm::dvec3> waypoints(scene->tour.begin(), scene->tour.end());
    cameras = modeling::TourPath(waypoints, modeling::TourOptions{}).cameras(frames, fov);
  } else {
    cameras = viewpointTour(*scene, frames);
  }

  std::error_code ec;
  fs::create_directories(*output, ec);
  if (!fs::is_directory(*output, ec)) return fail(*output + ": cannot create this folder");

  auto renderer = engine::Renderer::create(options);
  if (!renderer) return fail(renderer.message());
  if (auto uploaded = (*renderer)->setScene(*scene); !uploaded) return fail(uploaded.message());
  if (auto clean = (*renderer)->validationStatus(); !clean) return fail(clean.message());

  std::optional<VideoFile> video;
  fs::path videoTemp;
  if (videoPath) {
    const fs::path target(*videoPath);
    const bool avi = target.extension() == ".avi";
    // A name of this process's own (two tours to one --video do not share it); what a
    // killed tour left is removed first.
    const std::string prefix = "." + target.stem().string() + ".partial-";
    removeStaleTemporaries(target.parent_path(), prefix);
    videoTemp = target.parent_path() / (prefix + processIdText() + target.extension().string());
    auto opened = VideoFile::open(videoTemp, videoFourcc(avi ? 'M' : 'm', avi ? 'J' : 'p', avi ? 'P' : '4', avi ? 'G' : 'v'),
                                  fps, size.first, size.second);
    if (opened) {
      video = std::move(*opened);
    } else {
      printWarning(*videoPath + ": " + opened.message() + "; writing frames only");
    }
  }

  // A failed tour leaves no half-written video behind.
  const auto abandon = [&](const std::string& message) {
    video.reset();
    if (!videoTemp.empty()) fs::remove(videoTemp, ec);
    return fail(message);
  };
  FrameWriter writer(*output, video ? &*video : nullptr);
  for (int i = 0; i < frames; ++i) {
    auto image = (*renderer)->renderToImage(cameras[i], size.first, size.second);
    if (!image) {
      writer.finish();
      return abandon(image.message());
    }
    // Each frame is checked before it is queued, so every frame written was drawn
    // without a validation message.
    if (auto clean = (*renderer)->validationStatus(); !clean) {
      writer.finish();
      return abandon(clean.message());
    }
    if (!writer.push(i, std::move(*image))) return abandon(writer.finish());
    showProgress(i + 1, frames);
  }
  if (const std::string failure = writer.finish(); !failure.empty()) return abandon(failure);
  std::printf("%d frames of %dx%d in %s\n", frames, size.first, size.second, output->c_str());
  if (video) {
    video.reset();
    // OpenCV's writer says nothing when the disk fills: read the video back, and keep
    // the previous one unless every frame is there.
    const Result<double> count = videoFrameCount(videoTemp);
    const bool readable = count.ok();
    const double written = readable ? *count : 0;
    const auto bytes = fs::file_size(videoTemp, ec);
    if (!readable || ec || bytes == 0 || (written > 0 && written < frames)) {
      fs::remove(videoTemp, ec);
      return fail(*videoPath + ": the video is incomplete (" + std::to_string(static_cast<long long>(written)) + " of " +
                  std::to_string(frames) + " frames could be read back; disk full?); the frames are in " + *output);
    }
    fs::rename(videoTemp, *videoPath, ec);
    if (ec) return fail(*videoPath + ": cannot write: " + ec.message());
    std::printf("video: %s (%.0f fps)\n", videoPath->c_str(), fps);
  }
  return kExitOk;
}

}  // namespace

PW_COMMAND(tour, "tour", "render a walk through a model to PNG frames (and a video)", kUsage, runTour);

}  // namespace pw::editor
