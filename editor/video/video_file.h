// A video being written by `tour --video`, through the video plugin (video_plugin_api.h),
// which is loaded from beside the program on the first open.
#pragma once

#include <filesystem>
#include <memory>

#include <opencv2/core/mat.hpp>

#include "base/result.h"

namespace pw::editor {

class VideoFile {
 public:
  // `fourcc` as cv::VideoWriter::fourcc packs it ('m','p','4','v': MPEG-4; 'M','J','P','G':
  // Motion JPEG). An error where the plugin cannot be loaded, or OpenCV cannot write
  // that format.
  static Result<VideoFile> open(const std::filesystem::path& path, int fourcc, double fps, int width, int height);

  // Appends a CV_8UC3 BGR frame of the size opened. The file is finished when the
  // VideoFile is destroyed.
  void write(const cv::Mat& bgr);

 private:
  struct Closer {
    void operator()(void* video) const;
  };
  std::unique_ptr<void, Closer> video_;
};

// The frames a reader finds in the video at `path` (0 where its container does not
// say); an error where it cannot be read or the plugin cannot be loaded.
Result<double> videoFrameCount(const std::filesystem::path& path);

// The four-character code of a codec, packed as cv::VideoWriter::fourcc packs it.
constexpr int videoFourcc(char a, char b, char c, char d) {
  return (a & 255) + ((b & 255) << 8) + ((c & 255) << 16) + ((d & 255) << 24);
}

}  // namespace pw::editor
