// Presenting to a real window: the app shell's Window (editor/app: GLFW here and in
// the shell only; pw_gpu never sees it) opens an X11 window with its Vulkan surface,
// ctest runs this under xvfb-run, lavapipe presents to it.
#include <GLFW/glfw3.h>

#include <cstdlib>

#include <gtest/gtest.h>

#include "editor/app/glfw_session.h"
#include "editor/app/window.h"
#include "engine/gpu/presenter.h"
#include "engine/scene/sample_scene.h"
#include "tests/gpu/renderer_fixture.h"

namespace pw::engine {
namespace {

class PresenterTest : public ::testing::Test {
 protected:
  // GLFW stays initialised for the binary (app::initGlfw): terminating and
  // re-initialising it between tests sometimes failed to reach the X server again.
  void SetUp() override {
    if (!std::getenv("DISPLAY")) GTEST_SKIP() << "no X display (ctest runs this test under xvfb-run)";
    auto extensions = app::windowInstanceExtensions();
    ASSERT_TRUE(extensions.ok()) << extensions.message();
    RendererOptions options;
    options.forceCpu = true;
    options.validation = RendererOptions::Validation::kOn;
    options.instanceExtensions = *extensions;
    auto renderer = Renderer::create(options);
    ASSERT_TRUE(renderer.ok()) << renderer.message();
    renderer_ = std::move(*renderer);
    auto window = app::Window::create({320, 240, "photowalk presenter test"}, renderer_->instance());
    ASSERT_TRUE(window.ok()) << window.message();
    window_ = std::move(*window);
    surface_ = window_->surface();
  }

  void TearDown() override {
    presenter_.reset();  // before the surface, which is before the renderer's instance
    window_.reset();
    if (renderer_) {
      EXPECT_EQ(renderer_->validationMessageCount(), 0u) << test::validationReport(*renderer_);
    }
    renderer_.reset();
  }

  std::pair<int, int> framebufferSize() {
    const glm::ivec2 size = window_->framebufferSize();
    return {size.x, size.y};
  }

  std::unique_ptr<Renderer> renderer_;
  std::unique_ptr<app::Window> window_;
  VkSurfaceKHR surface_ = VK_NULL_HANDLE;
  std::unique_ptr<Presenter> presenter_;
};

TEST_F(PresenterTest, DrawsFramesWithTheOverlayAndSurvivesResizeAndSceneChange) {
  const Scene scene = makeSampleScene();
  ASSERT_TRUE(renderer_->setScene(scene).ok());
  const auto [w, h] = framebufferSize();
  auto presenter = Presenter::create(*renderer_, surface_, w, h);
  ASSERT_TRUE(presenter.ok()) << presenter.message();
  presenter_ = std::move(*presenter);
  EXPECT_NE(presenter_->overlayRenderPass(), VK_NULL_HANDLE);
  int oneOffCalls = 0;  // as ImGui's font upload would use it
  ASSERT_TRUE(renderer_->submitAndWait([&](VkCommandBuffer cmd) { oneOffCalls += cmd != VK_NULL_HANDLE; }).ok());
  EXPECT_EQ(oneOffCalls, 1);
  EXPECT_GE(presenter_->imageCount(), presenter_->minImageCount());
  EXPECT_EQ(presenter_->extent().width, uint32_t(w));

  int overlayCalls = 0;
  // The overlay draws into the swapchain image inside the render pass, as ImGui does.
  const OverlayCallback overlay = [&](VkCommandBuffer cmd) {
    ++overlayCalls;
    VkClearAttachment clear{VK_IMAGE_ASPECT_COLOR_BIT, 0, {{{1.0f, 0.0f, 1.0f, 1.0f}}}};
    VkClearRect rect{{{4, 4}, {16, 16}}, 0, 1};
    vkCmdClearAttachments(cmd, 1, &clear, 1, &rect);
  };
  const Camera camera = cameraFromViewpoint(scene.viewpoints[0]);
  for (int i = 0; i < 4; ++i) {
    auto drawn = presenter_->drawFrame(camera, {}, overlay);
    ASSERT_TRUE(drawn.ok()) << drawn.message();
    glfwPollEvents();
  }
  EXPECT_EQ(presenter_->lastFrameStats().drawCalls, 13u);

  // A new scene while frames are in flight: they keep the old one alive.
  Scene smaller = scene;
  smaller.shapes.resize(5);
  ASSERT_TRUE(renderer_->setScene(smaller).ok());

  window_->resizeAndWait(400, 300);
  const auto [w2, h2] = framebufferSize();
  presenter_->resize(w2, h2);
  for (int i = 0; i < 4; ++i) {
    auto drawn = presenter_->drawFrame(camera, {}, overlay);
    ASSERT_TRUE(drawn.ok()) << drawn.message();
    glfwPollEvents();
  }
  EXPECT_EQ(presenter_->extent().width, uint32_t(w2));
  EXPECT_EQ(presenter_->extent().height, uint32_t(h2));
  EXPECT_EQ(presenter_->lastFrameStats().drawCalls, 5u);
  EXPECT_EQ(overlayCalls, 8);
  EXPECT_EQ(presenter_->framesPresented(), 8u);

  // Minimised: frames are skipped, not errors.
  presenter_->resize(0, 0);
  ASSERT_TRUE(presenter_->drawFrame(camera, {}, overlay).ok());
  EXPECT_EQ(presenter_->framesPresented(), 8u);
  ASSERT_TRUE(presenter_->waitIdle().ok());
}

TEST_F(PresenterTest, RendererWithoutSurfaceExtensionsIsRefused) {
  RendererOptions options;
  options.forceCpu = true;
  auto offscreen = Renderer::create(options);
  ASSERT_TRUE(offscreen.ok()) << offscreen.message();
  auto presenter = Presenter::create(**offscreen, surface_, 320, 240);
  ASSERT_FALSE(presenter.ok());
  EXPECT_NE(presenter.message().find("VK_KHR_surface"), std::string::npos) << presenter.message();
}

}  // namespace
}  // namespace pw::engine
