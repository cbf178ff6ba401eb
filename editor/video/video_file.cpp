#include "editor/video/video_file.h"

#include <dlfcn.h>

#include <mutex>
#include <string>
#include <system_error>

#include "editor/video/video_plugin_api.h"

namespace pw::editor {
namespace {
namespace fs = std::filesystem;

constexpr const char* kPluginFile = "libpw_video.so";

struct Plugin {
  PwVideoOpen open = nullptr;
  PwVideoWrite write = nullptr;
  PwVideoClose close = nullptr;
  PwVideoFrameCount frameCount = nullptr;
  std::string error;  // why it could not be loaded; empty when it was
};

// Loaded once, beside the program, and kept for the process's life (FFmpeg's and
// GStreamer's threads may outlive a video).
const Plugin& plugin() {
  static Plugin loaded;
  static std::once_flag once;
  std::call_once(once, [] {
    std::error_code ec;
    const fs::path program = fs::read_symlink("/proc/self/exe", ec);
    const fs::path file = ec ? fs::path(kPluginFile) : program.parent_path() / kPluginFile;
    void* handle = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      const char* why = dlerror();
      loaded.error = "cannot load the video plugin (" + std::string(why ? why : file.string()) +
                     "; it is built beside the program: cmake --build build)";
      return;
    }
    const auto symbol = [&](const char* name) { return dlsym(handle, name); };
    loaded.open = reinterpret_cast<PwVideoOpen>(symbol("pw_video_open"));
    loaded.write = reinterpret_cast<PwVideoWrite>(symbol("pw_video_write"));
    loaded.close = reinterpret_cast<PwVideoClose>(symbol("pw_video_close"));
    loaded.frameCount = reinterpret_cast<PwVideoFrameCount>(symbol("pw_video_frame_count"));
    if (!loaded.open || !loaded.write || !loaded.close || !loaded.frameCount) {
      loaded.error = file.string() + ": not photowalk's video plugin (a function is missing); build it again";
    }
  });
  return loaded;
}

}  // namespace

void VideoFile::Closer::operator()(void* video) const { plugin().close(video); }

Result<VideoFile> VideoFile::open(const fs::path& path, int fourcc, double fps, int width, int height) {
  const Plugin& p = plugin();
  if (!p.error.empty()) return makeError(p.error);
  void* video = p.open(path.c_str(), fourcc, fps, width, height);
  if (!video) return makeError("this OpenCV cannot write that video format");
  VideoFile file;
  file.video_.reset(video);
  return file;
}

void VideoFile::write(const cv::Mat& bgr) {
  if (!video_ || bgr.type() != CV_8UC3) return;
  plugin().write(video_.get(), bgr.data, bgr.cols, bgr.rows, bgr.step);
}

Result<double> videoFrameCount(const fs::path& path) {
  const Plugin& p = plugin();
  if (!p.error.empty()) return makeError(p.error);
  const double frames = p.frameCount(path.c_str());
  if (frames < 0) return makeError(path.string() + ": cannot be read back as a video");
  return frames;
}

}  // namespace pw::editor
