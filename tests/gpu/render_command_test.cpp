// photowalk render, end to end: exit codes, messages, and the PNG it writes.

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/videoio.hpp>

#include "engine/scene/image.h"
#include "tests/gpu/image_compare.h"
#include "tests/support/run_command.h"

namespace pw::engine {
namespace {

using test::CommandRun;
CommandRun photowalk(const std::string& arguments) { return test::runCommand(std::string(PW_PHOTOWALK) + " " + arguments); }

std::filesystem::path outputPath(const std::string& name) {
  const std::filesystem::path path = test::testOutputDir() / name;
  std::filesystem::remove(path);
  return path;
}

TEST(RenderCommand, WritesTheSampleRoomAsPng) {
  const auto out = outputPath("render_command_sample.png");
  const CommandRun run = photowalk("render sample -o " + out.string() + " --size 96x54 --cpu");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  auto image = loadImage(out);
  ASSERT_TRUE(image.ok()) << image.message();
  EXPECT_EQ(image->width, 96);
  EXPECT_EQ(image->height, 54);
  EXPECT_NE(run.output.find("llvmpipe"), std::string::npos) << run.output;
}

TEST(RenderCommand, SecondViewpointDiffersFromTheFirst) {
  const auto first = outputPath("render_command_vp1.png"), second = outputPath("render_command_vp2.png");
  ASSERT_EQ(photowalk("render sample -o " + first.string() + " --size 64x48 --msaa 1").exitCode, 0);
  ASSERT_EQ(photowalk("render sample -o " + second.string() + " --size 64x48 --msaa 1 --viewpoint 2").exitCode, 0);
  EXPECT_NE(loadImage(first)->rgba, loadImage(second)->rgba);
}

TEST(RenderCommand, ZeroSizeIsAnError) {
  const auto out = outputPath("render_command_zero.png");
  const CommandRun run = photowalk("render sample -o " + out.string() + " --size 0x0");
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_NE(run.output.find("error: --size 0x0 is out of range"), std::string::npos) << run.output;
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(RenderCommand, HugeSizeIsAnError) {
  const CommandRun run = photowalk("render sample -o " + outputPath("x.png").string() + " --size 100000x100000");
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_NE(run.output.find("100000x100000 is out of range"), std::string::npos) << run.output;
}

TEST(RenderCommand, ViewpointOutOfRangeNamesTheCount) {
  const CommandRun run = photowalk("render sample -o " + outputPath("x.png").string() + " --viewpoint 3");
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_NE(run.output.find("sample has 2 viewpoints"), std::string::npos) << run.output;
}

TEST(RenderCommand, MissingOrUnsupportedSceneIsNamed) {
  const CommandRun missing = photowalk("render no/such/room.wrl -o " + outputPath("x.png").string());
  EXPECT_EQ(missing.exitCode, 1);
  EXPECT_NE(missing.output.find("no/such/room.wrl: no such file"), std::string::npos) << missing.output;
}

TEST(RenderCommand, UnwritableOutputLeavesNoFile) {
  const CommandRun run = photowalk("render sample -o /nonexistent-dir/frame.png --size 32x32");
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_NE(run.output.find("/nonexistent-dir/frame.png"), std::string::npos) << run.output;
}

TEST(RenderCommand, BadMsaaAndMissingOutputAreErrors) {
  const CommandRun msaa = photowalk("render sample -o " + outputPath("x.png").string() + " --msaa 3 --size 8x8");
  EXPECT_EQ(msaa.exitCode, 1);
  EXPECT_NE(msaa.output.find("MSAA 3x is not available"), std::string::npos) << msaa.output;
  const CommandRun noOutput = photowalk("render sample");
  EXPECT_EQ(noOutput.exitCode, 1);
  EXPECT_NE(noOutput.output.find("-o OUT.png"), std::string::npos) << noOutput.output;
}

// photowalk convert: VRML97 and glTF both ways, through loadModel's readers. A
// photo-lit model (unlit textures) looks the same after the round trip; lit scenes
// do not quite, glTF having no ambient light nor VRML's light radius.
TEST(ConvertCommand, ConvertsBetweenVrmlAndGltfBothWays) {
  const auto dir = test::testOutputDir() / "convert";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string wrl = (dir / "corridor.wrl").string(), glb = (dir / "corridor.glb").string(),
                    back = (dir / "back.wrl.gz").string();
  CommandRun run = photowalk("build " + std::string(PW_SOURCE_DIR) + "/assets/corridor.json -o " + wrl);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  run = photowalk("convert " + wrl + " " + glb + " --title 'Sample corridor'");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  run = photowalk("convert " + glb + " " + back);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("4 viewpoints"), std::string::npos) << run.output;
  const std::string first = (dir / "first.png").string(), last = (dir / "last.png").string();
  ASSERT_EQ(photowalk("render " + wrl + " -o " + first + " --size 160x90 --cpu").exitCode, 0);
  ASSERT_EQ(photowalk("render " + back + " -o " + last + " --size 160x90 --cpu").exitCode, 0);
  auto a = loadImage(first), b = loadImage(last);
  ASSERT_TRUE(a.ok() && b.ok());
  int differing = 0;
  for (size_t i = 0; i < a->rgba.size(); ++i) differing += std::abs(int(a->rgba[i]) - int(b->rgba[i])) > 4;
  EXPECT_LT(differing, int(a->rgba.size() / 200)) << "the round trip through glTF changed the picture";
}

TEST(ConvertCommand, RefusesUnknownOutputsAndMissingInputsInOneLine) {
  CommandRun run = photowalk("convert sample " + outputPath("x.obj").string());
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_NE(run.output.find("error: "), std::string::npos) << run.output;
  EXPECT_NE(run.output.find(".glb"), std::string::npos) << "names the extensions it writes: " << run.output;
  run = photowalk("convert /nonexistent/in.wrl " + outputPath("y.glb").string());
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_EQ(std::count(run.output.begin(), run.output.end(), '\n'), 1) << run.output;
  EXPECT_FALSE(std::filesystem::exists(test::testOutputDir() / "y.glb"));
}

// photowalk tour: numbered frames along the model's tour (the sample room has none:
// its viewpoints), a video, one-line errors.
TEST(TourCommand, WritesMovingFramesAndAVideo) {
  const auto dir = test::testOutputDir() / "tour";
  std::filesystem::remove_all(dir);
  const std::string video = (dir / "tour.mp4").string();
  constexpr int kFrames = 5;
  const CommandRun run = photowalk("tour sample -o " + dir.string() + " --frames " + std::to_string(kFrames) +
                                   " --size 96x54 --cpu --video " + video);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  std::vector<Image> frames;
  for (int i = 0; i < kFrames; ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.png", i);
    auto frame = loadImage(dir / name);
    ASSERT_TRUE(frame.ok()) << frame.message();
    EXPECT_EQ(frame->width, 96);
    EXPECT_EQ(frame->height, 54);
    frames.push_back(std::move(*frame));
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "frame_0005.png"));
  // The sample room's tour goes round its two viewpoints and back to the first, eased:
  // with 5 frames, frame 0 is viewpoint 1, frame 2 viewpoint 2, frame 4 viewpoint 1
  // again, frames 1 and 3 the same point halfway between them.
  const auto viewpoint1 = outputPath("tour_viewpoint1.png"), viewpoint2 = outputPath("tour_viewpoint2.png");
  ASSERT_EQ(photowalk("render sample -o " + viewpoint1.string() + " --size 96x54 --cpu").exitCode, 0);
  ASSERT_EQ(photowalk("render sample -o " + viewpoint2.string() + " --size 96x54 --cpu --viewpoint 2").exitCode, 0);
  auto still1 = loadImage(viewpoint1), still2 = loadImage(viewpoint2);
  ASSERT_TRUE(still1.ok() && still2.ok());
  ASSERT_FALSE(test::compareImages(*still1, *still2).passes()) << "the two viewpoints must look different";
  EXPECT_TRUE(test::compareImages(frames[0], *still1).passes()) << test::compareImages(frames[0], *still1).describe();
  EXPECT_TRUE(test::compareImages(frames[2], *still2).passes()) << test::compareImages(frames[2], *still2).describe();
  EXPECT_TRUE(test::compareImages(frames[4], *still1).passes()) << test::compareImages(frames[4], *still1).describe();
  EXPECT_TRUE(test::compareImages(frames[1], frames[3]).passes()) << test::compareImages(frames[1], frames[3]).describe();
  EXPECT_FALSE(test::compareImages(frames[1], *still1).passes()) << "frame 1 lies between the viewpoints";
  EXPECT_FALSE(test::compareImages(frames[1], *still2).passes()) << "frame 1 lies between the viewpoints";

  // The video: Debian's OpenCV writes MPEG-4 through FFmpeg; a machine without that
  // writer fails here rather than skip the check.
  ASSERT_EQ(run.output.find("cannot write that video format"), std::string::npos)
      << "this OpenCV has no MPEG-4 video writer (libopencv-videoio with FFmpeg, scripts/install-deps.sh): "
      << run.output;
  EXPECT_NE(run.output.find("video: " + video), std::string::npos) << run.output;
  cv::VideoCapture capture(video);
  ASSERT_TRUE(capture.isOpened()) << video << " does not open as a video";
  int decoded = 0;
  for (cv::Mat bgr; capture.read(bgr); ++decoded) {
    ASSERT_EQ(bgr.cols, 96);
    ASSERT_EQ(bgr.rows, 54);
    ASSERT_LT(decoded, kFrames) << "more frames in the video than rendered";
    Image frame = makeImage(bgr.cols, bgr.rows);
    for (int y = 0; y < bgr.rows; ++y) {
      for (int x = 0; x < bgr.cols; ++x) {
        const cv::Vec3b p = bgr.at<cv::Vec3b>(y, x);
        frame.pixel(x, y)[0] = p[2];
        frame.pixel(x, y)[1] = p[1];
        frame.pixel(x, y)[2] = p[0];
      }
    }
    // The MPEG-4 codec blurs and shifts colour a little: each 8x6 tile's mean colour
    // stays within 7.4/255 of the PNG frame's (measured, all five frames; limit 12).
    // A frame out of order differs by 29/255 or more, a mirrored one by 65/255.
    const test::TileDifference d = test::compareTiles(frame, frames[decoded], 8, 6);
    EXPECT_LT(d.worst, 12.0) << "video frame " << decoded << ": " << d.describe();
    EXPECT_GT(test::compareTiles(frame, test::mirroredLeftRight(frames[decoded]), 8, 6).worst, 12.0)
        << "the tile comparison must see a mirrored frame";
  }
  EXPECT_EQ(decoded, kFrames);
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    EXPECT_EQ(entry.path().filename().string().find(".partial"), std::string::npos) << "a temporary file was left";
  }
}

// A frame that cannot be written (here a folder is in its way) stops the tour with a
// one-line error, the frames written in the background included, and no video is left.
// OpenCV's video module (FFmpeg, GStreamer: about 100 more shared libraries, 60-90 ms of
// every command's start, bench/startup.py) is loaded only when a tour writes a video,
// from the plugin beside the program; the program itself does not link it.
TEST(TourCommand, TheProgramStartsWithoutTheVideoLibraries) {
  const CommandRun run = test::runCommand("LD_TRACE_LOADED_OBJECTS=1 " + std::string(PW_PHOTOWALK));
  ASSERT_NE(run.output.find("libopencv_core"), std::string::npos) << run.output;  // (the list is there)
  EXPECT_EQ(run.output.find("libopencv_videoio"), std::string::npos) << "photowalk links OpenCV's video module";
  EXPECT_EQ(run.output.find("libavcodec"), std::string::npos) << "photowalk links FFmpeg";
}

// Where the plugin is missing (the program copied alone elsewhere), a tour says so and
// writes its frames, as where OpenCV cannot write the format.
TEST(TourCommand, WithoutTheVideoPluginTheFramesAreWrittenAndItSaysSo) {
  const auto dir = test::testOutputDir() / "tour_no_plugin";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const auto program = dir / "photowalk";
  std::error_code ec;
  std::filesystem::create_hard_link(PW_PHOTOWALK, program, ec);
  if (ec) std::filesystem::copy_file(PW_PHOTOWALK, program);
  ASSERT_FALSE(std::filesystem::exists(dir / "libpw_video.so"));
  const std::string video = (dir / "tour.mp4").string();
  const CommandRun run =
      test::runCommand(program.string() + " tour sample -o " + (dir / "frames").string() + " --frames 2 --size 32x18 --cpu --video " + video);
  EXPECT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("cannot load the video plugin"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("writing frames only"), std::string::npos) << run.output;
  EXPECT_TRUE(std::filesystem::exists(dir / "frames" / "frame_0001.png"));
  EXPECT_FALSE(std::filesystem::exists(video));
  std::filesystem::remove_all(dir);
}

TEST(TourCommand, AFrameThatCannotBeWrittenStopsTheTour) {
  const auto dir = test::testOutputDir() / "tour_blocked";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir / "frame_0002.png");
  const std::string video = (dir / "tour.mp4").string();
  const CommandRun run = photowalk("tour sample -o " + dir.string() + " --frames 8 --size 64x36 --cpu --video " + video);
  EXPECT_EQ(run.exitCode, 1) << run.output;
  EXPECT_NE(run.output.find("frame_0002.png: cannot write: Is a directory"), std::string::npos) << run.output;
  EXPECT_FALSE(std::filesystem::exists(video));
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    EXPECT_EQ(entry.path().filename().string().find(".partial"), std::string::npos) << "a temporary file was left";
  }
}

TEST(TourCommand, BadArgumentsAreOneLineErrors) {
  const auto dir = test::testOutputDir() / "tour_bad";
  std::filesystem::remove_all(dir);
  for (const std::string& arguments : {"tour sample -o " + dir.string() + " --frames 0",
                                       "tour /nonexistent/model.wrl -o " + dir.string(), std::string("tour sample")}) {
    const CommandRun run = photowalk(arguments);
    EXPECT_EQ(run.exitCode, 1) << arguments;
    EXPECT_EQ(std::count(run.output.begin(), run.output.end(), '\n'), 1) << arguments << ": " << run.output;
  }
  EXPECT_FALSE(std::filesystem::exists(dir)) << "nothing written for a tour that did not start";
}

}  // namespace
}  // namespace pw::engine
