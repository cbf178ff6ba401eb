// photowalk's renders of VRML97 files against view3dscene's screenshots of them: the
// samples (tests/data/vrml-samples/X.wrl_screenshot.png, 1600x900) and photowalk's own
// fixtures for nodes the samples lack (tests/data/vrml/X.wrl_screenshot.png). The
// silhouettes of non-background pixels must overlap, as intersection over union, from
// the same viewpoint and size. Side-by-side images go to test_output/vrml/render.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>

#include "engine/gpu/renderer.h"
#include "engine/scene/camera.h"
#include "engine/vrml/vrml_reader.h"
#include "tests/vrml/silhouette.h"
#include "tests/vrml/vrml_samples.h"

namespace pw::engine {
namespace {

namespace fs = std::filesystem;

// view3dscene's camera for a file without a Viewpoint (Castle Game Engine,
// CameraViewpointForWholeScene): looking along -Z from the bounding box's centre,
// moved to its front face plus twice the box's average side.
Viewpoint castleDefaultViewpoint(const Scene& scene) {
  Viewpoint v;
  // The box of the transformed vertices (tighter than transformed local boxes).
  Bounds b;
  for (const Shape& shape : scene.shapes) {
    for (const glm::vec3& p : shape.mesh->positions) b.add(glm::vec3(shape.transform * glm::vec4(p, 1.0f)));
  }
  if (b.empty()) return v;
  const glm::vec3 size = b.size();
  const float average = (size.x + size.y + size.z) / 3.0f;
  v.position = b.center();
  v.position.z = b.max.z + 2.0f * average;
  v.orientation = {0, 0, 1, 0};
  return v;
}

// Reference left, photowalk right, each at half size; silhouette disagreement in the
// bottom row (red: only the reference, green: only photowalk).
Image sideBySide(const Image& reference, const Image& ours, const std::vector<bool>& a, const std::vector<bool>& b) {
  const int w = reference.width / 2, h = reference.height / 2;
  Image out = makeImage(2 * w, 2 * h, 0x000000ff);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      for (int c = 0; c < 3; ++c) {
        out.pixel(x, y)[c] = reference.pixel(2 * x, 2 * y)[c];
        out.pixel(w + x, y)[c] = ours.pixel(2 * x, 2 * y)[c];
      }
      const size_t i = static_cast<size_t>(2 * y) * reference.width + 2 * x;
      uint8_t* d = out.pixel(x + w / 2, h + y);
      d[0] = a[i] && !b[i] ? 255 : (a[i] && b[i] ? 120 : 0);
      d[1] = b[i] && !a[i] ? 255 : (a[i] && b[i] ? 120 : 0);
      d[2] = a[i] && b[i] ? 120 : 0;
    }
  }
  return out;
}

// Lowest overlap accepted per sample, below the measured value by a margin; the notes
// say what photowalk draws differently. minIou 0: the file shows nothing from its
// default view, and both frames must be empty (an IoU of two empty frames proves
// nothing, so it is not asked for).
struct Expectation {
  double minIou;
  const char* why;
};
const std::map<std::string, Expectation> kExpected = {
    {"cones.wrl", {0.35, "points are 1 pixel, view3dscene draws large squares"}},
    {"cones.wrl.gz", {0.35, "as cones.wrl"}},
    {"cones_gzipped_but_with_normal_extension.wrl",
     {0.35, "as cones.wrl (its longer Text widens the bounding box, so the default camera moves back)"}},
    {"reuse_coordinate.wrl", {0.45, "its third shape is a PointSet: 1-pixel points against large squares"}},
    {"pointset.wrl", {0.0, "both frames must be empty: the two points lie outside the default view"}},
};
constexpr double kDefaultMinIou = 0.95;
// Each silhouette covers at least this fraction of the frame (smallest measured: 0.0155,
// photowalk's cones_gzipped_but_with_normal_extension.wrl; 0.037 without 1-pixel
// points), so that a blank or nearly blank frame on either side fails.
constexpr double kMinCoverage = 0.01;

// Files with a view3dscene screenshot beside them.
std::vector<fs::path> filesWithScreenshots() {
  std::vector<fs::path> files = vrmlSamples();
  for (const auto& entry : fs::directory_iterator(PW_TEST_DATA_DIR "/vrml")) {
    const std::string name = entry.path().filename().string();
    if (name.ends_with(".wrl") && fs::exists(entry.path().string() + "_screenshot.png")) files.push_back(entry.path());
  }
  return files;
}

TEST(VrmlRender, RendersMatchViewerScreenshotSilhouettes) {
  RendererOptions options;
  options.validation = RendererOptions::Validation::kOn;
  auto renderer = Renderer::create(options);
  ASSERT_TRUE(renderer.ok()) << renderer.message();
  const fs::path outDir = fs::path(PW_BINARY_DIR) / "test_output" / "vrml" / "render";
  fs::create_directories(outDir);
  int compared = 0, samples = 0;
  for (const fs::path& file : filesWithScreenshots()) {
    const fs::path referencePath = file.string() + "_screenshot.png";
    if (!fs::exists(referencePath)) continue;
    const std::string name = file.filename().string();
    SCOPED_TRACE(name);
    auto reference = loadImage(referencePath);
    ASSERT_TRUE(reference.ok()) << reference.message();
    auto scene = readVrml(file, nullptr, samplesFolders());
    ASSERT_TRUE(scene.ok()) << scene.message();
    const Viewpoint viewpoint = scene->viewpoints.empty() ? castleDefaultViewpoint(*scene) : scene->viewpoints[0];
    ASSERT_TRUE((*renderer)->setScene(*scene).ok());
    FrameSettings settings;
    settings.backgroundColor = glm::vec3(1, 0, 1);  // a colour no file here uses
    auto ours = (*renderer)->renderToImage(cameraFromViewpoint(viewpoint), reference->width, reference->height, settings);
    ASSERT_TRUE(ours.ok()) << ours.message();
    const auto a = silhouette(*reference, 8);
    const auto b = silhouette(*ours, 40);
    const double iou = intersectionOverUnion(a, b);
    auto expected = kExpected.find(name);
    const double minIou = expected == kExpected.end() ? kDefaultMinIou : expected->second.minIou;
    std::printf("  %-46s IoU %.3f (at least %.2f), coverage %.4f / %.4f%s%s\n", name.c_str(), iou, minIou, coverage(a),
                coverage(b), expected == kExpected.end() ? "" : ": ", expected == kExpected.end() ? "" : expected->second.why);
    if (minIou == 0.0) {
      EXPECT_EQ(coverage(a), 0.0) << "view3dscene's screenshot is expected to be empty";
      EXPECT_EQ(coverage(b), 0.0) << "photowalk's frame is expected to be empty";
    } else {
      EXPECT_GE(coverage(a), kMinCoverage) << "view3dscene's screenshot shows (almost) nothing";
      EXPECT_GE(coverage(b), kMinCoverage) << "photowalk drew (almost) nothing";
      EXPECT_GE(iou, minIou);
    }
    EXPECT_TRUE(saveImage(outDir / (name + "_compare.png"), sideBySide(*reference, *ours, a, b)).ok());
    ++compared;
    samples += file.string().find("vrml-samples") != std::string::npos;
  }
  EXPECT_EQ((*renderer)->validationMessageCount(), 0u);
  EXPECT_GE(compared, 1);
  EXPECT_GE(samples, 1) << "no samples in " PW_TEST_DATA_DIR "/vrml-samples";
}

// The command a person runs, through engine/io/model_io: every sample renders, with the
// reader's warnings on stderr and nothing else. Validation is on: render exits non-zero
// on any validation message.
TEST(VrmlRender, PhotowalkRenderDrawsEverySample) {
  const auto samples = vrmlSamples();
  ASSERT_FALSE(samples.empty()) << "no samples in " PW_TEST_DATA_DIR "/vrml-samples";
  const fs::path outDir = fs::path(PW_BINARY_DIR) / "test_output" / "vrml" / "render_command";
  fs::create_directories(outDir);
  for (const fs::path& sample : samples) {
    SCOPED_TRACE(sample.string());
    const fs::path out = outDir / (sample.filename().string() + ".png");
    fs::remove(out);
    const std::string command = std::string("PW_VALIDATION=1 '") + PW_PHOTOWALK + "' render '" + sample.string() +
                                "' -o '" + out.string() + "' --allow-folder '" + samplesFolders().front().string() +
                                "' --size 320x180 --cpu > '" + out.string() + ".log' 2>&1";
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
    auto image = loadImage(out);
    ASSERT_TRUE(image.ok()) << image.message();
    EXPECT_EQ(image->width, 320);
    const auto mask = silhouette(*image, 8);
    EXPECT_TRUE(std::count(mask.begin(), mask.end(), true) > 0 || sample.filename() == "pointset.wrl")
        << "nothing drawn";
  }
}

}  // namespace
}  // namespace pw::engine
