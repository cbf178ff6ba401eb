// Views without a window (Renderer::renderViews): scenes in rectangles and render
// targets, several scenes and cameras in one frame, images under a pan/zoom
// transform, and the errors a caller can cause. views_test.cpp does the same through
// a window's swapchain.
#include <cmath>
#include <thread>

#include <gtest/gtest.h>

#include "engine/scene/sample_scene.h"
#include "tests/gpu/image_compare.h"
#include "tests/gpu/renderer_fixture.h"
#include "tests/gpu/view_checks.h"

namespace pw::engine {
namespace {

class ViewsOffscreenTest : public test::RendererTest {
 protected:
  static Scene room() { return makeSampleScene(); }
  static Camera entrance() { return cameraFromViewpoint(room().viewpoints[0]); }
  static Camera corner() { return cameraFromViewpoint(room().viewpoints[1]); }

  SceneHandle addRoom() {
    auto handle = renderer().addScene(room());
    EXPECT_TRUE(handle.ok()) << handle.message();
    return handle.ok() ? *handle : SceneHandle{};
  }

  // The room from `camera` as renderToImage draws it (the reference every view is held to).
  Image reference(const Camera& camera, int width, int height) {
    EXPECT_TRUE(renderer().setScene(room()).ok());
    auto image = renderer().renderToImage(camera, width, height);
    EXPECT_TRUE(image.ok()) << image.message();
    return image.ok() ? std::move(*image) : Image{};
  }

  Image render(const std::vector<View>& views, int width, int height, glm::vec3 clear = glm::vec3(0.0f)) {
    auto image = renderer().renderViews(views, width, height, clear);
    EXPECT_TRUE(image.ok()) << image.message();
    return image.ok() ? std::move(*image) : makeImage(width, height, 0);
  }
};

void expectSame(const Image& actual, const Image& expected, const std::string& what) {
  const test::ImageDifference d = test::compareImages(actual, expected);
  EXPECT_TRUE(d.passes()) << what << ": " << d.describe();
}

TEST_F(ViewsOffscreenTest, SceneInARectangleEqualsItsOffscreenRender) {
  const Image expected = reference(entrance(), 160, 120);
  SceneView view{addRoom(), entrance(), {37, 21, 160, 120}, {}, {}};
  const Image frame = render({view}, 256, 192, glm::vec3(1.0f, 0.0f, 1.0f));
  expectSame(test::crop(frame, 37, 21, 160, 120), expected, "the rectangle");
  // Outside the rectangle: the frame's clear colour, untouched.
  const uint8_t* outside[] = {frame.pixel(36, 60), frame.pixel(197, 60), frame.pixel(100, 20), frame.pixel(100, 141)};
  for (const uint8_t* p : outside) {
    EXPECT_EQ(p[0], 255);
    EXPECT_EQ(p[1], 0);
    EXPECT_EQ(p[2], 255);
  }
  // The comparison can fail: the rectangle one pixel off does not match.
  EXPECT_FALSE(test::compareImages(test::crop(frame, 38, 21, 160, 120), expected).passes());
}

TEST_F(ViewsOffscreenTest, SceneInARenderTargetEqualsItsOffscreenRenderAndShowsThroughAnImageView) {
  const Image expected = reference(corner(), 160, 120);
  const uint32_t drawCalls = renderer().lastFrameStats().drawCalls;  // 12: one shape is outside the view
  auto target = renderer().addRenderTarget(160, 120);
  ASSERT_TRUE(target.ok()) << target.message();
  auto before = renderer().readImage(*target);
  ASSERT_TRUE(before.ok()) << before.message();
  EXPECT_EQ(before->pixel(80, 60)[3], 0) << "a new render target is transparent";

  // Drawn into the texture and shown 1:1 in the same frame (image pixel centres on
  // frame pixel centres: offset + 0.5).
  SceneView into{addRoom(), corner(), {}, {}, *target};
  ImageView shown{*target, {1.0, {20.5, 10.5}}, {20, 10, 160, 120}, ImageFilter::kAuto, {}};
  const Image frame = render({into, shown}, 200, 140);
  auto texture = renderer().readImage(*target);
  ASSERT_TRUE(texture.ok()) << texture.message();
  expectSame(*texture, expected, "the render target");
  expectSame(test::crop(frame, 20, 10, 160, 120), expected, "the render target through an image view");
  EXPECT_EQ(renderer().lastFrameStats().views, 2u);
  EXPECT_EQ(renderer().lastFrameStats().drawCalls, drawCalls);

  // A later frame shows what an earlier one drew into it.
  const Image later = render({shown}, 200, 140);
  expectSame(test::crop(later, 20, 10, 160, 120), expected, "the render target a frame later");
  ASSERT_TRUE(renderer().removeImage(*target).ok());
  EXPECT_FALSE(renderer().renderViews({shown}, 200, 140).ok());
}

TEST_F(ViewsOffscreenTest, TwoViewsInOneFrameEachShowTheirOwnCamera) {
  const Image fromEntrance = reference(entrance(), 120, 90);
  const Image fromCorner = reference(corner(), 120, 90);
  ASSERT_FALSE(test::compareImages(fromEntrance, fromCorner).passes()) << "the two cameras must see differently";
  const SceneHandle handle = addRoom();
  const Image frame = render({SceneView{handle, entrance(), {0, 0, 120, 90}, {}, {}},
                              SceneView{handle, corner(), {120, 0, 120, 90}, {}, {}}},
                             240, 90);
  expectSame(test::crop(frame, 0, 0, 120, 90), fromEntrance, "the left view");
  expectSame(test::crop(frame, 120, 0, 120, 90), fromCorner, "the right view");
  EXPECT_EQ(renderer().lastFrameStats().views, 2u);
}

TEST_F(ViewsOffscreenTest, ScenesAreHandlesThatCanBeReplacedAndRemoved) {
  const SceneHandle full = addRoom();
  Scene reduced = room();
  reduced.shapes.resize(5);
  auto small = renderer().addScene(reduced);
  ASSERT_TRUE(small.ok()) << small.message();
  EXPECT_NE(small->id, full.id);
  const PixelRect rect{0, 0, 64, 48};
  render({SceneView{full, entrance(), rect, {}, {}}, SceneView{*small, entrance(), {64, 0, 64, 48}, {}, {}}}, 128, 48);
  const uint32_t both = renderer().lastFrameStats().drawCalls;
  render({SceneView{full, entrance(), rect, {}, {}}}, 64, 48);
  const uint32_t fullCalls = renderer().lastFrameStats().drawCalls;
  EXPECT_EQ(fullCalls, 13u);
  EXPECT_LT(both - fullCalls, fullCalls) << "the reduced scene draws fewer shapes";

  // Replaced: the same handle draws the new upload; the other scene is untouched.
  ASSERT_TRUE(renderer().replaceScene(full, reduced).ok());
  render({SceneView{full, entrance(), rect, {}, {}}}, 64, 48);
  EXPECT_EQ(renderer().lastFrameStats().drawCalls, both - fullCalls);

  // A failed replacement keeps the scene there was.
  Scene broken = room();
  auto badMesh = std::make_shared<Mesh>(*broken.shapes[0].mesh);
  badMesh->indices.insert(badMesh->indices.end(), {999, 0, 1});
  broken.shapes[0].mesh = badMesh;
  EXPECT_FALSE(renderer().replaceScene(full, broken).ok());
  render({SceneView{full, entrance(), rect, {}, {}}}, 64, 48);
  EXPECT_EQ(renderer().lastFrameStats().drawCalls, both - fullCalls);

  ASSERT_TRUE(renderer().removeScene(*small).ok());
  auto gone = renderer().renderViews({SceneView{*small, entrance(), rect, {}, {}}}, 64, 48);
  ASSERT_FALSE(gone.ok());
  EXPECT_NE(gone.message().find("view 0: scene handle"), std::string::npos) << gone.message();
  EXPECT_FALSE(renderer().removeScene(*small).ok());
  EXPECT_FALSE(renderer().replaceScene(*small, reduced).ok());
  auto removeDefault = renderer().removeScene(renderer().defaultScene());
  ASSERT_FALSE(removeDefault.ok());
  EXPECT_NE(removeDefault.message().find("default scene"), std::string::npos);
}

// The slow half of an upload on a worker thread while the renderer's thread draws;
// the renderer's thread swaps each staged scene in.
TEST_F(ViewsOffscreenTest, ScenesStagedOnAnotherThreadWhileFramesAreDrawn) {
  const Image expected = reference(entrance(), 96, 72);
  const SceneHandle handle = addRoom();
  Scene reduced = room();
  reduced.shapes.resize(6);
  std::vector<StagedScene> staged;
  std::string workerError;
  std::thread worker([&] {
    for (int i = 0; i < 4; ++i) {
      auto s = renderer().stageScene(i % 2 ? room() : reduced);
      if (!s) {
        workerError = s.message();
        return;
      }
      staged.push_back(std::move(*s));
    }
  });
  for (int i = 0; i < 8; ++i) render({SceneView{handle, entrance(), {}, {}, {}}}, 96, 72);
  worker.join();
  ASSERT_EQ(workerError, "");
  ASSERT_EQ(staged.size(), 4u);
  for (StagedScene& s : staged) {
    ASSERT_TRUE(renderer().replaceScene(handle, std::move(s)).ok());
    render({SceneView{handle, entrance(), {}, {}, {}}}, 96, 72);
  }
  expectSame(render({SceneView{handle, entrance(), {}, {}, {}}}, 96, 72), expected, "the last staged scene (the full room)");
  auto reused = renderer().replaceScene(handle, std::move(staged[0]));
  ASSERT_FALSE(reused.ok());
  EXPECT_NE(reused.message().find("already used"), std::string::npos) << reused.message();
  auto broken = renderer().stageScene([&] {
    Scene s = room();
    auto mesh = std::make_shared<Mesh>(*s.shapes[0].mesh);
    mesh->indices.insert(mesh->indices.end(), {999, 0, 1});
    s.shapes[0].mesh = mesh;
    return s;
  }());
  ASSERT_FALSE(broken.ok());
  EXPECT_NE(broken.message().find("shape 'floor'"), std::string::npos) << broken.message();
}

// Zoom 1, 4 and 16: every frame pixel shows the image pixel the transform puts under
// its centre, and the image's edges lie where the transform says (within 0.5 px).
TEST_F(ViewsOffscreenTest, ImagePixelsLieWhereTheTransformPutsThem) {
  const Image pattern = test::patternImage(40, 30);
  auto handle = renderer().addImage(pattern);
  ASSERT_TRUE(handle.ok()) << handle.message();
  const std::array<uint8_t, 3> background{10, 20, 30};
  const glm::vec4 backgroundColor(10 / 255.0f, 20 / 255.0f, 30 / 255.0f, 1.0f);
  const PixelRect rect{8, 6, 240, 180};
  const ImageTransform transforms[] = {{1.0, {20.5, 15.5}}, {4.0, {13.25, 9.75}}, {16.0, {-100.6, -60.3}}};
  for (const ImageTransform& t : transforms) {
    SCOPED_TRACE("scale " + std::to_string(t.scale));
    const Image frame = render({ImageView{*handle, t, rect, ImageFilter::kAuto, backgroundColor}}, 256, 192);
    // At zoom 1 the centres meet exactly; magnified 4x and more the filter is nearest.
    const std::string layout = test::checkImageLayout(frame, pattern, t, rect, background, 1, 0.0);
    EXPECT_TRUE(layout.empty()) << layout;
    // Image pixel (u, v)'s block spans offset + scale * (u -+ 0.5): compare its measured
    // edges with that for pixels whose colours are unique.
    for (const auto& [u, v] : {std::pair(0, 0), std::pair(17, 11), std::pair(39, 29), std::pair(13, 6)}) {
      const uint8_t* c = pattern.pixel(u, v);
      const double left = t.offset.x + t.scale * (u - 0.5), right = t.offset.x + t.scale * (u + 0.5);
      const double top = t.offset.y + t.scale * (v - 0.5), bottom = t.offset.y + t.scale * (v + 0.5);
      if (right <= rect.x || bottom <= rect.y || left >= rect.x + rect.width || top >= rect.y + rect.height) continue;
      const test::PixelBox box = test::findColor(frame, rect, {c[0], c[1], c[2]});
      ASSERT_GT(box.x1, box.x0) << "image pixel (" << u << ", " << v << ") is missing";
      EXPECT_NEAR(box.x0, std::max<double>(left, rect.x), 0.5) << u << "," << v;
      EXPECT_NEAR(box.x1, std::min<double>(right, rect.x + rect.width), 0.5) << u << "," << v;
      EXPECT_NEAR(box.y0, std::max<double>(top, rect.y), 0.5) << u << "," << v;
      EXPECT_NEAR(box.y1, std::min<double>(bottom, rect.y + rect.height), 0.5) << u << "," << v;
    }
    // Outside the view's rectangle the frame is untouched (clear colour black).
    EXPECT_EQ(frame.pixel(4, 100)[2], 0);
    EXPECT_EQ(frame.pixel(250, 100)[2], 0);
  }
}

// Magnified 4x and more (kAuto) or on request (kNearest), single pixels are solid
// blocks; below 4x kAuto filters smoothly, which blends neighbours at block edges.
TEST_F(ViewsOffscreenTest, MagnifiedPixelsAreBlocksFromFourTimesUp) {
  const Image pattern = test::patternImage(16, 12);
  auto handle = renderer().addImage(pattern);
  ASSERT_TRUE(handle.ok()) << handle.message();
  const PixelRect rect{0, 0, 128, 96};
  const auto blended = [&](double scale, ImageFilter filter) {
    const ImageTransform t{scale, {0.3, 0.6}};
    const Image frame = render({ImageView{*handle, t, rect, filter, {}}}, 128, 96);
    // Pixels showing neither of the image's blue values (0, 255) were blended.
    int count = 0;
    for (int y = 0; y < 96; ++y) {
      for (int x = 0; x < 128; ++x) {
        const double px = (x + 0.5 - t.offset.x) / t.scale, py = (y + 0.5 - t.offset.y) / t.scale;
        if (px >= -0.5 && py >= -0.5 && px < 15.5 && py < 11.5) count += frame.pixel(x, y)[2] % 255 != 0;
      }
    }
    return count;
  };
  EXPECT_EQ(blended(4.0, ImageFilter::kAuto), 0);
  EXPECT_EQ(blended(16.0, ImageFilter::kAuto), 0);
  EXPECT_EQ(blended(2.5, ImageFilter::kNearest), 0);
  // Measured: about 3000 blended pixels at 3.9x with kAuto; a nearest filter there would give 0.
  EXPECT_GT(blended(3.9, ImageFilter::kAuto), 1000);
  EXPECT_GT(blended(8.0, ImageFilter::kSmooth), 1000);
}

// Minified, the mip chain averages light, not sRGB codes: a black and white
// checkerboard of single pixels is mid-grey in light, 188/255 encoded (128 would be
// averaging the codes).
TEST_F(ViewsOffscreenTest, MinificationAveragesLinearLight) {
  Image checker = makeImage(256, 256);
  for (int y = 0; y < 256; ++y) {
    for (int x = 0; x < 256; ++x) std::fill_n(checker.pixel(x, y), 3, (x + y) % 2 ? 255 : 0);
  }
  auto handle = renderer().addImage(checker);
  ASSERT_TRUE(handle.ok()) << handle.message();
  for (const double scale : {0.5, 0.25, 0.3}) {
    SCOPED_TRACE("scale " + std::to_string(scale));
    const Image frame = render({ImageView{*handle, {scale, {0.0, 0.0}}, {}, ImageFilter::kAuto, {}}}, 64, 64);
    for (const auto& [x, y] : {std::pair(10, 10), std::pair(30, 20), std::pair(60, 5)}) {
      if ((x + 0.5) / scale > 255 || (y + 0.5) / scale > 255) continue;
      EXPECT_NEAR(frame.pixel(x, y)[0], 188, 3) << x << "," << y;
    }
  }
}

TEST_F(ViewsOffscreenTest, BackgroundBeyondTheImageIsDrawnOrLeftAsItWas) {
  auto handle = renderer().addImage(makeImage(4, 4, 0xffffffff));
  ASSERT_TRUE(handle.ok()) << handle.message();
  const ImageTransform t{4.0, {20.5, 20.5}};  // the image covers frame pixels 19..34
  const Image drawn = render({ImageView{*handle, t, {}, ImageFilter::kAuto, {0.0f, 1.0f, 0.0f, 1.0f}}}, 64, 64,
                             glm::vec3(1.0f, 0.0f, 0.0f));
  EXPECT_EQ(drawn.pixel(5, 5)[1], 255);  // background
  EXPECT_EQ(drawn.pixel(5, 5)[0], 0);
  EXPECT_EQ(drawn.pixel(25, 25)[0], 255);  // the image: white
  EXPECT_EQ(drawn.pixel(25, 25)[1], 255);
  const Image kept = render({ImageView{*handle, t, {}, ImageFilter::kAuto, {0.0f, 1.0f, 0.0f, 0.0f}}}, 64, 64,
                            glm::vec3(1.0f, 0.0f, 0.0f));
  EXPECT_EQ(kept.pixel(5, 5)[0], 255);  // the frame's clear colour shows through
  EXPECT_EQ(kept.pixel(5, 5)[1], 0);
  EXPECT_EQ(kept.pixel(25, 25)[1], 255);

  // A translucent image blends over the frame in linear light: half-covering white
  // over black is linear 0.5, 188/255 encoded.
  auto translucent = renderer().addImage(makeImage(4, 4, 0xffffff80));
  ASSERT_TRUE(translucent.ok()) << translucent.message();
  const Image blended = render({ImageView{*translucent, t, {}, ImageFilter::kAuto, {0.0f, 0.0f, 0.0f, 1.0f}}}, 64, 64);
  EXPECT_NEAR(blended.pixel(25, 25)[0], 188, 2);
  EXPECT_EQ(blended.pixel(25, 25)[3], 255);  // the frame stays opaque
  EXPECT_EQ(blended.pixel(5, 5)[0], 0);
}

// A 12-megapixel photo: uploaded with its mip chain, fitted into a small rectangle and
// looked at 16x at one corner.
TEST_F(ViewsOffscreenTest, TwelveMegapixelPhotoFitsAndMagnifies) {
  Image photo = makeImage(4000, 3000, 0x404040ff);
  for (int y = 0; y < 3000; ++y) {  // left half bright: the fitted view shows the edge in the middle
    for (int x = 0; x < 2000; ++x) std::fill_n(photo.pixel(x, y), 3, 220);
  }
  std::copy_n(std::array<uint8_t, 4>{255, 0, 0, 255}.data(), 4, photo.pixel(3999, 2999));  // one red pixel
  auto handle = renderer().addImage(photo);
  ASSERT_TRUE(handle.ok()) << handle.message();
  auto size = renderer().imageSize(*handle);
  ASSERT_TRUE(size.ok());
  EXPECT_EQ(*size, glm::ivec2(4000, 3000));

  const double fit = 200.0 / 4000.0;  // 4000x3000 into 200x150
  const Image fitted = render({ImageView{*handle, {fit, {fit * 0.5, fit * 0.5}}, {}, ImageFilter::kAuto, {}}}, 200, 150);
  EXPECT_NEAR(fitted.pixel(50, 75)[0], 220, 2);
  EXPECT_NEAR(fitted.pixel(150, 75)[0], 0x40, 2);
  // The red pixel at 16x: a 16x16 block whose top-left corner lies at offset + 16 * 3998.5.
  const ImageTransform zoom{16.0, {-16.0 * 3990, -16.0 * 2990}};
  const Image magnified = render({ImageView{*handle, zoom, {}, ImageFilter::kAuto, {}}}, 200, 200);
  const test::PixelBox red = test::findColor(magnified, {0, 0, 200, 200}, {255, 0, 0});
  EXPECT_NEAR(red.x0, zoom.offset.x + 16 * 3998.5, 0.5);
  EXPECT_NEAR(red.y0, zoom.offset.y + 16 * 2998.5, 0.5);
  EXPECT_EQ(red.x1 - red.x0, 16);
  EXPECT_EQ(red.y1 - red.y0, 16);
}

TEST_F(ViewsOffscreenTest, BadViewsAreNamedErrors) {
  auto image = renderer().addImage(makeImage(8, 8));
  ASSERT_TRUE(image.ok());
  const auto message = [&](const View& view) {
    auto result = renderer().renderViews({SceneView{renderer().defaultScene(), entrance(), {}, {}, {}}, view}, 32, 32);
    return result.ok() ? std::string("(no error)") : result.message();
  };
  EXPECT_NE(message(ImageView{ImageHandle{999999}, {}, {}, ImageFilter::kAuto, {}}).find("view 1: image handle 999999"),
            std::string::npos);
  EXPECT_NE(message(ImageView{*image, {0.0, {0.0, 0.0}}, {}, ImageFilter::kAuto, {}}).find("positive"), std::string::npos);
  EXPECT_NE(message(ImageView{*image, {NAN, {0.0, 0.0}}, {}, ImageFilter::kAuto, {}}).find("positive"), std::string::npos);
  EXPECT_NE(message(ImageView{*image, {}, {0, 0, -4, 4}, ImageFilter::kAuto, {}}).find("negative"), std::string::npos);
  EXPECT_NE(message(ImageView{*image, {}, {0, 0, 1000000, 4}, ImageFilter::kAuto, {}}).find("viewport limits"),
            std::string::npos);
  EXPECT_NE(message(SceneView{renderer().defaultScene(), entrance(), {}, {}, *image}).find("not a render target"),
            std::string::npos);
  Camera bad = entrance();
  bad.nearM = 0;
  EXPECT_NE(message(SceneView{renderer().defaultScene(), bad, {}, {}, {}}).find("view 1: the camera"), std::string::npos);

  auto empty = renderer().addImage(Image{});
  ASSERT_FALSE(empty.ok());
  EXPECT_NE(empty.message().find("0x0"), std::string::npos) << empty.message();
  Image huge;
  huge.width = 20000;
  huge.height = 1;
  huge.rgba.assign(20000 * 4, 0);
  auto tooLarge = renderer().addImage(huge);
  ASSERT_FALSE(tooLarge.ok());
  EXPECT_NE(tooLarge.message().find("scale it down"), std::string::npos) << tooLarge.message();
  EXPECT_FALSE(renderer().addRenderTarget(0, 10).ok());
  EXPECT_FALSE(renderer().readImage(ImageHandle{999999}).ok());
  EXPECT_FALSE(renderer().imageSize(ImageHandle{999999}).ok());
}

// Views wholly outside the frame are skipped, not errors; a rectangle reaching past an
// edge is drawn where it is inside and keeps the camera's projection.
TEST_F(ViewsOffscreenTest, RectanglesReachingPastTheFrameAreClipped) {
  const Image expected = reference(entrance(), 160, 120);
  const SceneHandle handle = addRoom();
  const Image frame = render({SceneView{handle, entrance(), {-40, -30, 160, 120}, {}, {}},
                              SceneView{handle, entrance(), {500, 500, 160, 120}, {}, {}}},
                             100, 80);
  EXPECT_EQ(renderer().lastFrameStats().views, 1u);
  expectSame(frame, test::crop(expected, 40, 30, 100, 80), "the part inside the frame");
}

}  // namespace
}  // namespace pw::engine
