// Views in a window (engine/gpu/view.h through Presenter): a scene in a rectangle of
// the swapchain image and in a texture, a photo under a pan/zoom transform, two
// cameras in one frame, the overlay on top, all read back with the Presenter's
// capture. The app shell's Window (editor/app; pw_gpu never sees GLFW) opens an X11
// window with its surface; ctest runs this under xvfb-run, lavapipe presents to it.
#include <GLFW/glfw3.h>

#include <cstdlib>

#include <gtest/gtest.h>

#include "editor/app/glfw_session.h"
#include "editor/app/window.h"
#include "engine/gpu/presenter.h"
#include "engine/scene/sample_scene.h"
#include "tests/gpu/image_compare.h"
#include "tests/gpu/renderer_fixture.h"
#include "tests/gpu/view_checks.h"

namespace pw::engine {
namespace {

constexpr int kWidth = 320, kHeight = 240;

// One window, renderer and presenter for the whole binary: making a renderer costs a
// second on lavapipe, and GLFW stays initialised for the binary (app::initGlfw).
class ViewsWindowTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (!std::getenv("DISPLAY")) return;
    auto extensions = app::windowInstanceExtensions();
    if (!extensions.ok()) {
      setupError_ = extensions.message();
      return;
    }
    RendererOptions options;
    options.forceCpu = true;
    options.validation = RendererOptions::Validation::kOn;
    options.instanceExtensions = *extensions;
    auto renderer = Renderer::create(options);
    if (!renderer.ok()) {
      setupError_ = renderer.message();
      return;
    }
    renderer_ = std::move(*renderer);
    auto window = app::Window::create({kWidth, kHeight, "photowalk views test"}, renderer_->instance());
    if (!window.ok()) {
      setupError_ = window.message();
      return;
    }
    window_ = std::move(*window);
    const glm::ivec2 size = window_->framebufferSize();
    auto presenter = Presenter::create(*renderer_, window_->surface(), size.x, size.y);
    if (!presenter.ok()) {
      setupError_ = presenter.message();
      return;
    }
    presenter_ = std::move(*presenter);
  }

  static void TearDownTestSuite() {
    if (presenter_) (void)presenter_->waitIdle();
    presenter_.reset();  // before the surface, which is before the renderer's instance
    window_.reset();
    renderer_.reset();
  }

  void SetUp() override {
    if (!std::getenv("DISPLAY")) GTEST_SKIP() << "no X display (ctest runs this test under xvfb-run)";
    ASSERT_TRUE(presenter_) << setupError_;
    ASSERT_EQ(presenter_->extent().width, uint32_t(kWidth));
    ASSERT_EQ(presenter_->extent().height, uint32_t(kHeight));
    messagesBefore_ = renderer_->validationMessageCount();
  }

  void TearDown() override {
    if (renderer_) {
      EXPECT_EQ(renderer_->validationMessageCount(), messagesBefore_) << test::validationReport(*renderer_);
    }
  }

  // Draws `views` with `overlay` on top and returns what the window shows.
  static Image drawAndCapture(const std::vector<View>& views, const OverlayCallback& overlay = {},
                              glm::vec3 clear = glm::vec3(0.0f)) {
    presenter_->captureNextFrame();
    auto drawn = presenter_->drawFrame(views, overlay, clear);
    EXPECT_TRUE(drawn.ok()) << drawn.message();
    glfwPollEvents();
    auto image = presenter_->takeCapture();
    EXPECT_TRUE(image.ok()) << image.message();
    return image.ok() ? std::move(*image) : makeImage(kWidth, kHeight, 0);
  }

  static Scene room() { return makeSampleScene(); }
  static Camera camera(int viewpoint) { return cameraFromViewpoint(room().viewpoints.at(size_t(viewpoint))); }

  // The room from a viewpoint as renderToImage draws it offscreen: the reference.
  static Image reference(int viewpoint, int width, int height) {
    EXPECT_TRUE(renderer_->setScene(room()).ok());
    auto image = renderer_->renderToImage(camera(viewpoint), width, height);
    EXPECT_TRUE(image.ok()) << image.message();
    return image.ok() ? std::move(*image) : Image{};
  }

  static inline std::unique_ptr<app::Window> window_;
  static inline std::unique_ptr<Renderer> renderer_;
  static inline std::unique_ptr<Presenter> presenter_;
  static inline std::string setupError_ = "the renderer or presenter could not be made";
  size_t messagesBefore_ = 0;
};

void expectSame(const Image& actual, const Image& expected, const std::string& what) {
  const test::ImageDifference d = test::compareImages(actual, expected);
  EXPECT_TRUE(d.passes()) << what << ": " << d.describe();
  if (!d.passes()) (void)saveImage(test::testOutputDir() / ("views_" + what.substr(0, what.find(' ')) + ".png"), actual);
}

// An overlay as ImGui would record it: drawing inside the overlay render pass.
void magentaSquare(VkCommandBuffer cmd) {
  const VkClearAttachment clear{VK_IMAGE_ASPECT_COLOR_BIT, 0, {{{1.0f, 0.0f, 1.0f, 1.0f}}}};
  const VkClearRect rect{{{4, 4}, {16, 16}}, 0, 1};
  vkCmdClearAttachments(cmd, 1, &clear, 1, &rect);
}

// ImGui 1.86's colours are sRGB-encoded values its backend writes unchanged; the window
// must show them as written. Before the overlay pass wrote through a UNORM view of the
// sRGB swapchain image, the hardware encoded them again: (70, 220, 90) showed as
// (143, 239, 160) and ImGui's window background 15 as 67.
TEST_F(ViewsWindowTest, OverlayColoursReachTheWindowUnchanged) {
  struct Square {
    int x, y;
    uint8_t rgb[3];
  };
  const Square squares[] = {
      {40, 40, {70, 220, 90}},    // a handle colour
      {80, 40, {15, 15, 15}},     // ImGui's default window background (0.06)
      {120, 40, {128, 64, 200}},  // mid-range values, where the sRGB curve departs most
  };
  const OverlayCallback overlay = [&](VkCommandBuffer cmd) {
    for (const Square& s : squares) {
      const VkClearAttachment clear{
          VK_IMAGE_ASPECT_COLOR_BIT, 0, {{{s.rgb[0] / 255.0f, s.rgb[1] / 255.0f, s.rgb[2] / 255.0f, 1.0f}}}};
      const VkClearRect rect{{{s.x, s.y}, {16, 16}}, 0, 1};
      vkCmdClearAttachments(cmd, 1, &clear, 1, &rect);
    }
  };
  // Over a scene view and over the clear colour (sRGB 0.5 grey: 128), which the views
  // still encode as before.
  auto scene = renderer_->addScene(room());
  ASSERT_TRUE(scene.ok()) << scene.message();
  const Image shown = drawAndCapture({SceneView{*scene, camera(0), {0, 0, 100, 100}, {}, {}}}, overlay,
                                     glm::vec3(0.5f));
  for (const Square& s : squares) {
    const uint8_t* p = shown.pixel(s.x + 8, s.y + 8);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(p[c], s.rgb[c], 1) << "square at " << s.x << "," << s.y << " channel " << c;
    }
  }
  const uint8_t* clear = shown.pixel(300, 200);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(clear[c], 128, 1) << "clear colour channel " << c;
  EXPECT_TRUE(renderer_->removeScene(*scene).ok());
}

TEST_F(ViewsWindowTest, SampleRoomInARectangleAndInATextureEqualsItsOffscreenRender) {
  constexpr int w = 140, h = 105;
  const Image expected = reference(0, w, h);
  auto scene = renderer_->addScene(room());
  ASSERT_TRUE(scene.ok()) << scene.message();
  auto texture = renderer_->addRenderTarget(w, h);
  ASSERT_TRUE(texture.ok()) << texture.message();
  const Image shown = drawAndCapture(
      {SceneView{*scene, camera(0), {10, 20, w, h}, {}, {}}, SceneView{*scene, camera(0), {}, {}, *texture},
       ImageView{*texture, {1.0, {170.5, 120.5}}, {170, 120, w, h}, ImageFilter::kAuto, {}}},
      magentaSquare, glm::vec3(0.0f, 0.0f, 1.0f));
  EXPECT_TRUE(saveImage(test::testOutputDir() / "views_window_scene_and_texture.png", shown).ok());
  expectSame(test::crop(shown, 10, 20, w, h), expected, "window rectangle");
  expectSame(test::crop(shown, 170, 120, w, h), expected, "texture shown 1:1");
  EXPECT_FALSE(test::compareImages(test::crop(shown, 11, 20, w, h), expected).passes()) << "a shifted crop must differ";
  // The overlay is in the capture, on top; pixels no view covers are the clear colour.
  const uint8_t* overlay = shown.pixel(8, 8);
  EXPECT_EQ(overlay[0], 255);
  EXPECT_EQ(overlay[1], 0);
  EXPECT_EQ(overlay[2], 255);
  const uint8_t* clear = shown.pixel(300, 20);
  EXPECT_EQ(clear[0], 0);
  EXPECT_EQ(clear[2], 255);
  EXPECT_EQ(presenter_->lastFrameStats().views, 3u);
  EXPECT_TRUE(renderer_->removeScene(*scene).ok());
  EXPECT_TRUE(renderer_->removeImage(*texture).ok());
}

TEST_F(ViewsWindowTest, PhotoAtZoomOneFourAndSixteenPutsItsPixelsWhereTheTransformSays) {
  const Image pattern = test::patternImage(48, 36);
  auto photo = renderer_->addImage(pattern);
  ASSERT_TRUE(photo.ok()) << photo.message();
  const PixelRect canvas{16, 12, 288, 216};
  const std::array<uint8_t, 3> background{40, 40, 40};
  const glm::vec4 backgroundColor(40 / 255.0f, 40 / 255.0f, 40 / 255.0f, 1.0f);
  const ImageTransform transforms[] = {{1.0, {100.5, 80.5}}, {4.0, {30.4, 20.7}}, {16.0, {-290.2, -150.9}}};
  for (const ImageTransform& t : transforms) {
    SCOPED_TRACE("zoom " + std::to_string(t.scale));
    const Image shown = drawAndCapture({ImageView{*photo, t, canvas, ImageFilter::kAuto, backgroundColor}});
    EXPECT_TRUE(saveImage(test::testOutputDir() / ("views_window_photo_zoom" + std::to_string(int(t.scale)) + ".png"), shown).ok());
    const std::string layout = test::checkImageLayout(shown, pattern, t, canvas, background, 1, 0.0);
    EXPECT_TRUE(layout.empty()) << layout;
    // Blocks: at 16x image pixel (20, 12) fills a 16 x 16 square of one colour whose
    // edges lie at offset + 16 * (u -+ 0.5), within half a pixel.
    if (t.scale == 16.0) {
      const uint8_t* c = pattern.pixel(20, 12);
      const test::PixelBox box = test::findColor(shown, canvas, {c[0], c[1], c[2]});
      EXPECT_NEAR(box.x0, t.offset.x + 16 * 19.5, 0.5);
      EXPECT_NEAR(box.y0, t.offset.y + 16 * 11.5, 0.5);
      EXPECT_EQ(box.x1 - box.x0, 16);
      EXPECT_EQ(box.y1 - box.y0, 16);
    }
  }
  EXPECT_TRUE(renderer_->removeImage(*photo).ok());
}

TEST_F(ViewsWindowTest, TwoViewsInOneFrameEachShowTheirOwnCamera) {
  const Image fromEntrance = reference(0, 150, 110);
  const Image fromCorner = reference(1, 150, 110);
  auto scene = renderer_->addScene(room());
  ASSERT_TRUE(scene.ok()) << scene.message();
  const Image shown = drawAndCapture(
      {SceneView{*scene, camera(0), {5, 60, 150, 110}, {}, {}}, SceneView{*scene, camera(1), {165, 60, 150, 110}, {}, {}}});
  expectSame(test::crop(shown, 5, 60, 150, 110), fromEntrance, "left camera");
  expectSame(test::crop(shown, 165, 60, 150, 110), fromCorner, "right camera");
  EXPECT_FALSE(test::compareImages(test::crop(shown, 5, 60, 150, 110), fromCorner).passes());
  EXPECT_TRUE(renderer_->removeScene(*scene).ok());
}

// A scene replaced while frames that draw it are still in flight: they finish with the
// old upload, the next frame draws the new one, nothing waits for the GPU to go idle
// and validation stays quiet.
TEST_F(ViewsWindowTest, ReplacingASceneBetweenFramesInFlight) {
  auto scene = renderer_->addScene(room());
  ASSERT_TRUE(scene.ok()) << scene.message();
  Scene reduced = room();
  reduced.shapes.resize(4);
  const std::vector<View> views{SceneView{*scene, camera(0), {}, {}, {}}};
  for (int i = 0; i < 6; ++i) {
    ASSERT_TRUE(presenter_->drawFrame(views).ok());
    ASSERT_TRUE(renderer_->replaceScene(*scene, i % 2 ? room() : reduced).ok());  // reduced while dragging, full after
  }
  ASSERT_TRUE(renderer_->replaceScene(*scene, reduced).ok());
  ASSERT_TRUE(presenter_->drawFrame(views).ok());
  const uint32_t reducedCalls = presenter_->lastFrameStats().drawCalls;
  ASSERT_TRUE(renderer_->replaceScene(*scene, room()).ok());
  const Image shown = drawAndCapture(views);
  EXPECT_EQ(presenter_->lastFrameStats().drawCalls, 13u);
  EXPECT_LT(reducedCalls, 13u);
  EXPECT_TRUE(test::compareImages(shown, reference(0, kWidth, kHeight)).passes());

  // A bad view is refused before anything is acquired: the next frame draws normally.
  auto bad = presenter_->drawFrame({SceneView{SceneHandle{123456}, camera(0), {}, {}, {}}});
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.message().find("view 0: scene handle 123456"), std::string::npos) << bad.message();
  ASSERT_TRUE(presenter_->drawFrame(views).ok());
  EXPECT_TRUE(renderer_->removeScene(*scene).ok());
}

TEST_F(ViewsWindowTest, CaptureMustBeAskedForFirst) {
  auto none = presenter_->takeCapture();
  ASSERT_FALSE(none.ok());
  EXPECT_NE(none.message().find("captureNextFrame"), std::string::npos) << none.message();
  // The old single-camera call still draws the default scene over the whole window.
  ASSERT_TRUE(renderer_->setScene(room()).ok());
  presenter_->captureNextFrame();
  ASSERT_TRUE(presenter_->drawFrame(camera(1), {}, {}).ok());
  auto shown = presenter_->takeCapture();
  ASSERT_TRUE(shown.ok()) << shown.message();
  EXPECT_TRUE(test::compareImages(*shown, reference(1, kWidth, kHeight)).passes());
}

}  // namespace
}  // namespace pw::engine
