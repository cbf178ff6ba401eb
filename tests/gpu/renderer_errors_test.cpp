// What a user can get wrong reaches them as one clear error, never a crash.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "engine/scene/sample_scene.h"
#include "tests/gpu/renderer_fixture.h"

namespace pw::engine {
namespace {

class RendererErrorTest : public test::RendererTest {};

Camera sampleCamera() { return cameraFromViewpoint(makeSampleScene().viewpoints[0]); }

TEST_F(RendererErrorTest, ZeroSizeIsRefused) {
  auto image = renderer().renderToImage(sampleCamera(), 0, 0);
  ASSERT_FALSE(image.ok());
  EXPECT_NE(image.message().find("0x0 is out of range"), std::string::npos) << image.message();
}

TEST_F(RendererErrorTest, HugeSizeIsRefused) {
  auto image = renderer().renderToImage(sampleCamera(), 100000, 100000);
  ASSERT_FALSE(image.ok());
  EXPECT_NE(image.message().find("100000x100000 is out of range"), std::string::npos) << image.message();
}

TEST_F(RendererErrorTest, SizeBeyondTheMemoryBudgetIsRefused) {
  auto image = renderer().renderToImage(sampleCamera(), 16384, 16384);  // within the side limit, 8 GiB of targets
  ASSERT_FALSE(image.ok());
  EXPECT_NE(image.message().find("MiB of render targets"), std::string::npos) << image.message();
}

TEST_F(RendererErrorTest, TextureWithoutPixelsIsNamed) {
  Scene scene = makeSampleScene();
  auto texture = std::make_shared<Texture>();
  texture->url = "textures/missing_wall.png";  // as a reader would leave it when the file is gone
  auto appearance = std::make_shared<Appearance>();
  appearance->material = Material{};
  appearance->texture = texture;
  scene.shapes[0].appearance = appearance;
  const Status status = renderer().setScene(scene);
  ASSERT_FALSE(status.ok());
  EXPECT_NE(status.message().find("textures/missing_wall.png"), std::string::npos) << status.message();
}

TEST_F(RendererErrorTest, TextureWithTruncatedPixelsIsNamed) {
  Scene scene = makeSampleScene();
  auto image = std::make_shared<Image>(makeImage(64, 64));
  image->rgba.resize(100);
  auto texture = std::make_shared<Texture>();
  texture->image = image;
  texture->url = "broken.jpg";
  auto appearance = std::make_shared<Appearance>();
  appearance->texture = texture;
  scene.shapes[1].appearance = appearance;
  const Status status = renderer().setScene(scene);
  ASSERT_FALSE(status.ok());
  EXPECT_NE(status.message().find("broken.jpg"), std::string::npos) << status.message();
}

TEST_F(RendererErrorTest, TextureLargerThanTheDeviceAllowsIsNamed) {
  Scene scene = makeSampleScene();
  auto texture = std::make_shared<Texture>();
  texture->image = std::make_shared<Image>(makeImage(20000, 1));
  texture->url = "panorama.png";
  auto appearance = std::make_shared<Appearance>();
  appearance->texture = texture;
  scene.shapes[0].appearance = appearance;
  const Status status = renderer().setScene(scene);
  ASSERT_FALSE(status.ok());
  EXPECT_NE(status.message().find("panorama.png"), std::string::npos) << status.message();
  EXPECT_NE(status.message().find("scale it down"), std::string::npos) << status.message();
}

TEST_F(RendererErrorTest, FailedSetSceneKeepsThePreviousScene) {
  Scene scene = makeSampleScene();
  ASSERT_TRUE(renderer().setScene(scene).ok());
  auto before = renderer().renderToImage(sampleCamera(), 64, 36);
  ASSERT_TRUE(before.ok());
  auto bad = std::make_shared<Mesh>(*scene.shapes[0].mesh);
  bad->indices.push_back(999);
  bad->indices.push_back(0);
  bad->indices.push_back(1);
  scene.shapes[0].mesh = bad;
  const Status status = renderer().setScene(scene);
  ASSERT_FALSE(status.ok());
  EXPECT_NE(status.message().find("shape 'floor'"), std::string::npos) << status.message();
  auto after = renderer().renderToImage(sampleCamera(), 64, 36);
  ASSERT_TRUE(after.ok());
  EXPECT_EQ(before->rgba, after->rgba);
}

TEST_F(RendererErrorTest, NonFiniteCameraIsRefused) {
  Camera camera = sampleCamera();
  camera.position.x = std::numeric_limits<float>::quiet_NaN();
  auto image = renderer().renderToImage(camera, 64, 36);
  ASSERT_FALSE(image.ok());
  EXPECT_NE(image.message().find("not a finite number"), std::string::npos) << image.message();
}

TEST_F(RendererErrorTest, UnsupportedMsaaNamesTheChoices) {
  RendererOptions options;
  options.forceCpu = true;
  options.msaaSamples = 3;
  auto created = Renderer::create(options);
  ASSERT_FALSE(created.ok());
  EXPECT_NE(created.message().find("choose one of 1"), std::string::npos) << created.message();
}

TEST_F(RendererErrorTest, EmptySceneRendersTheBackground) {
  Scene scene;
  scene.backgroundColor = {1.0f, 0.6f, 0.0f};
  ASSERT_TRUE(renderer().setScene(scene).ok());
  auto image = renderer().renderToImage(sampleCamera(), 16, 8);
  ASSERT_TRUE(image.ok()) << image.message();
  const uint8_t* p = image->pixel(3, 5);
  EXPECT_EQ(p[0], 255);
  EXPECT_NEAR(p[1], 153, 1);  // sRGB 0.6 survives the round trip through linear
  EXPECT_EQ(p[2], 0);
  EXPECT_EQ(p[3], 255);
}

TEST_F(RendererErrorTest, ShapesOutsideTheViewAreCulled) {
  Scene scene = makeSampleScene();
  ASSERT_TRUE(renderer().setScene(scene).ok());
  Camera camera = sampleCamera();
  camera.orientation = lookAtOrientation(camera.position, camera.position + glm::vec3(0, 0, 1));  // out of the room
  ASSERT_TRUE(renderer().renderToImage(camera, 64, 36).ok());
  const FrameStats stats = renderer().lastFrameStats();
  EXPECT_GE(stats.culledShapes, 9u);
  EXPECT_LE(stats.drawCalls, 4u);  // the floor, ceiling and side walls reach past the camera
}

}  // namespace
}  // namespace pw::engine

namespace pw::engine {
namespace {

// The zero-message checks mean something only if misuse is reported: provoke one.
TEST(ValidationLayer, ReportsMisuseThroughTheCounter) {
  RendererOptions options;
  options.forceCpu = true;
  options.validation = RendererOptions::Validation::kOn;
  auto created = Renderer::create(options);
  ASSERT_TRUE(created.ok()) << created.message();
  Renderer& renderer = **created;
  ASSERT_EQ(renderer.validationMessageCount(), 0u) << test::validationReport(renderer);
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = 16;
  info.usage = 0;  // VUID-VkBufferCreateInfo-usage-requiredbitmask
  VkBuffer buffer = VK_NULL_HANDLE;
  if (vkCreateBuffer(renderer.device(), &info, nullptr, &buffer) == VK_SUCCESS) {
    vkDestroyBuffer(renderer.device(), buffer, nullptr);
  }
  EXPECT_GE(renderer.validationMessageCount(), 1u);
  ASSERT_FALSE(renderer.validationMessages().empty());
  EXPECT_NE(renderer.validationMessages()[0].find("usage"), std::string::npos) << renderer.validationMessages()[0];
}

}  // namespace
}  // namespace pw::engine
