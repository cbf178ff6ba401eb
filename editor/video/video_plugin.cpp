// libpw_video.so: OpenCV's VideoWriter and VideoCapture behind video_plugin_api.h,
// loaded by video_file.cpp only when a tour writes a video.
#include <type_traits>

#include <opencv2/core.hpp>
#include <opencv2/videoio.hpp>

#include "editor/video/video_plugin_api.h"

extern "C" {

__attribute__((visibility("default"))) void* pw_video_open(const char* path, int fourcc, double fps, int width, int height) {
  auto* video = new cv::VideoWriter(path, fourcc, fps, cv::Size(width, height));
  if (!video->isOpened()) {
    delete video;
    return nullptr;
  }
  return video;
}

__attribute__((visibility("default"))) void pw_video_write(void* video, const unsigned char* bgr, int width, int height,
                                                           std::size_t stride) {
  // (OpenCV's writer only reads the frame.)
  const cv::Mat frame(height, width, CV_8UC3, const_cast<unsigned char*>(bgr), stride);
  static_cast<cv::VideoWriter*>(video)->write(frame);
}

__attribute__((visibility("default"))) void pw_video_close(void* video) { delete static_cast<cv::VideoWriter*>(video); }

__attribute__((visibility("default"))) double pw_video_frame_count(const char* path) {
  cv::VideoCapture reader(path);
  if (!reader.isOpened()) return -1;
  return reader.get(cv::CAP_PROP_FRAME_COUNT);
}

}  // extern "C"

// The interface's types and these functions' must agree.
static_assert(std::is_same_v<decltype(&pw_video_open), PwVideoOpen>);
static_assert(std::is_same_v<decltype(&pw_video_write), PwVideoWrite>);
static_assert(std::is_same_v<decltype(&pw_video_close), PwVideoClose>);
static_assert(std::is_same_v<decltype(&pw_video_frame_count), PwVideoFrameCount>);
