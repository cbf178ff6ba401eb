// The C interface between photowalk and its video plugin (libpw_video.so, built from
// video_plugin.cpp beside the program). OpenCV's video module pulls FFmpeg and
// GStreamer in, 102 more shared libraries that took 60-90 ms of every command's start
// (bench/startup.py); only `tour --video` writes a video, so only it loads them,
// through video_file.h. A C interface, so that nothing but plain data crosses it.
#pragma once

#include <cstddef>

extern "C" {

// Opens `path` for frames of `width` x `height` at `fps`, encoded as `fourcc`
// (cv::VideoWriter::fourcc's packing); null where OpenCV cannot write that format.
using PwVideoOpen = void* (*)(const char* path, int fourcc, double fps, int width, int height);
// Appends one frame: `height` rows of `width` BGR pixels, `stride` bytes apart.
using PwVideoWrite = void (*)(void* video, const unsigned char* bgr, int width, int height, std::size_t stride);
// Finishes the file and frees `video`.
using PwVideoClose = void (*)(void* video);
// How many frames a reader finds in the video at `path`: -1 where it cannot open it,
// 0 where the container does not say.
using PwVideoFrameCount = double (*)(const char* path);

}  // extern "C"
