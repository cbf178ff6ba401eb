// Golden images of the sample room on lavapipe (tolerance in image_compare.h). To
// change a golden on purpose: PW_UPDATE_GOLDEN=1 ctest -R Golden, look at the PNGs
// in tests/golden, commit them.
#include <gtest/gtest.h>

#include "engine/scene/sample_scene.h"
#include "tests/gpu/image_compare.h"
#include "tests/gpu/renderer_fixture.h"

namespace pw::engine {
namespace {

class GoldenTest : public test::RendererTest {
 protected:
  Image render(int viewpoint, int width, int height) {
    const Scene scene = makeSampleScene();
    auto set = renderer().setScene(scene);
    EXPECT_TRUE(set.ok()) << set.message();
    auto image = renderer().renderToImage(cameraFromViewpoint(scene.viewpoints.at(size_t(viewpoint))), width, height);
    EXPECT_TRUE(image.ok()) << image.message();
    return image.ok() ? std::move(*image) : Image{};
  }
};

TEST_F(GoldenTest, SampleRoomFromTheEntrance) {
  const Image frame = render(0, 480, 270);
  ASSERT_FALSE(frame.empty());
  EXPECT_EQ(renderer().lastFrameStats().drawCalls, 13u);
  const std::string failure = test::checkGolden(frame, "sample_entrance");
  EXPECT_TRUE(failure.empty()) << failure;
}

TEST_F(GoldenTest, SampleRoomFromTheCorner) {
  const Image frame = render(1, 320, 240);
  ASSERT_FALSE(frame.empty());
  const std::string failure = test::checkGolden(frame, "sample_corner");
  EXPECT_TRUE(failure.empty()) << failure;
}

// Without multisampling the edges are hard: a different image, its own golden.
TEST_F(GoldenTest, SampleRoomWithoutMsaa) {
  RendererOptions options;
  options.forceCpu = true;
  options.msaaSamples = 1;
  options.validation = RendererOptions::Validation::kOn;
  auto single = Renderer::create(options);
  ASSERT_TRUE(single.ok()) << single.message();
  const Scene scene = makeSampleScene();
  ASSERT_TRUE((*single)->setScene(scene).ok());
  auto frame = (*single)->renderToImage(cameraFromViewpoint(scene.viewpoints[0]), 320, 180);
  ASSERT_TRUE(frame.ok()) << frame.message();
  const std::string failure = test::checkGolden(*frame, "sample_entrance_nomsaa");
  EXPECT_TRUE(failure.empty()) << failure;
  EXPECT_EQ((*single)->validationMessageCount(), 0u) << test::validationReport(**single);
}

// The comparison itself must be able to fail.
TEST(ImageCompare, RejectsAMissingFeatureAndAcceptsNoise) {
  Image a = makeImage(100, 100, 0x808080ff);
  Image noisy = a;
  for (size_t i = 0; i < noisy.rgba.size(); i += 4 * 7) noisy.rgba[i] = uint8_t(noisy.rgba[i] + 2);
  EXPECT_TRUE(test::compareImages(noisy, a).passes());
  Image missingLine = a;
  for (int x = 0; x < 100; ++x) missingLine.pixel(x, 50)[1] = 0;  // 1% of pixels far off
  EXPECT_FALSE(test::compareImages(missingLine, a).passes());
  EXPECT_FALSE(test::compareImages(makeImage(10, 10), a).passes());
}

}  // namespace
}  // namespace pw::engine
