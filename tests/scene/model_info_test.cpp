// photowalk's own lines in a model file (model_info.h): the tour and the photo
// viewpoint's intrinsics typed in the Scene, encoded only at the file boundary.
#include "engine/scene/model_info.h"

#include <gtest/gtest.h>

#include "engine/scene/texture_source.h"

namespace pw::engine {
namespace {

const Intrinsics kPhotoLens{760.25, 760.25, 541.5, 360.125, 1024, 768};

Scene photoScene() {
  Scene scene;
  scene.info = {"the user's own line"};
  scene.tour = {{0, 1.6f, 2.5f}, {0, 1.6f, -8.25f}, {-3.125f, 1.6f, -4.0f}};
  Viewpoint photo;
  photo.description = "Photo";
  photo.intrinsics = kPhotoLens;
  Viewpoint other;
  other.description = "Far end";
  scene.viewpoints = {photo, other};
  return scene;
}

std::string urlOf(const Texture& t) { return t.url; }

TEST(ModelInfo, TourAndIntrinsicsSurviveTheInfoLines) {
  const Scene scene = photoScene();
  const std::vector<std::string> info = infoForFile(scene, urlOf);
  ASSERT_EQ(info.size(), 3u);
  EXPECT_EQ(info[0], "the user's own line");
  EXPECT_EQ(info[1].rfind(std::string(kTourTag) + " ", 0), 0u);
  EXPECT_EQ(info[2].rfind(std::string(kCameraTag) + " ", 0), 0u);

  Scene read;  // what a reader builds: the viewpoints without intrinsics, the lines in info
  read.viewpoints = scene.viewpoints;
  for (Viewpoint& v : read.viewpoints) v.intrinsics.reset();
  read.info = info;
  takeModelInfo(read);
  EXPECT_EQ(read.info, std::vector<std::string>{"the user's own line"});
  EXPECT_EQ(read.tour, scene.tour);  // %.9g keeps each float exactly
  ASSERT_TRUE(read.viewpoints[0].intrinsics);
  EXPECT_EQ(*read.viewpoints[0].intrinsics, kPhotoLens);  // %.17g keeps each double exactly
  EXPECT_FALSE(read.viewpoints[1].intrinsics);
  EXPECT_EQ(infoForFile(read, urlOf), info);
}

TEST(ModelInfo, LinesGoInOrderToViewpointsOfTheSameDescription) {
  Scene scene;
  Viewpoint a;
  a.description = "two words";
  a.intrinsics = kPhotoLens;
  Viewpoint b = a;
  b.intrinsics->principalU = 100;
  scene.viewpoints = {a, b};
  Scene read;
  read.viewpoints = {Viewpoint{}, Viewpoint{}};
  read.viewpoints[0].description = read.viewpoints[1].description = "two words";
  read.info = infoForFile(scene, urlOf);
  takeModelInfo(read);
  ASSERT_TRUE(read.viewpoints[0].intrinsics && read.viewpoints[1].intrinsics);
  EXPECT_EQ(read.viewpoints[0].intrinsics->principalU, 541.5);
  EXPECT_EQ(read.viewpoints[1].intrinsics->principalU, 100.0);
}

TEST(ModelInfo, MalformedLinesAreDroppedAndStrayOnesReplaced) {
  EXPECT_FALSE(decodeTourLine("photowalk-tour 1 2"));
  EXPECT_FALSE(decodeTourLine("photowalk-tour 1 2 3"));  // one point is no walk
  EXPECT_FALSE(decodeTourLine("photowalk-tour 1 2 3 4 5 nan"));
  EXPECT_FALSE(decodeTourLine("photowalk-tour 1 2 3 4 5 6 7"));
  EXPECT_FALSE(decodeTourLine("a photowalk-tour 1 2 3 4 5 6"));
  EXPECT_TRUE(decodeTourLine("photowalk-tour 1 2 3 4 5 6"));
  EXPECT_FALSE(decodeCameraLine("photowalk-camera 700 700 320 240 640 480"));  // no viewpoint named
  EXPECT_FALSE(decodeCameraLine("photowalk-camera 0 700 320 240 640 480 Photo"));
  EXPECT_FALSE(decodeCameraLine("photowalk-camera 700 700 inf 240 640 480 Photo"));
  EXPECT_FALSE(decodeCameraLine("photowalk-camera 700 700 320 240 0 480 Photo"));
  auto camera = decodeCameraLine("photowalk-camera 700 701 320 240 640 480 Photo of the hall");
  ASSERT_TRUE(camera);
  EXPECT_EQ(camera->first, "Photo of the hall");
  EXPECT_EQ(camera->second, (Intrinsics{700, 701, 320, 240, 640, 480}));

  Scene scene;
  scene.info = {"keep", "photowalk-tour 1 2", "photowalk-camera 1 2 3", "photowalk-tour 1 2 3 4 5 6"};
  takeModelInfo(scene);
  EXPECT_EQ(scene.info, std::vector<std::string>{"keep"});
  EXPECT_EQ(scene.tour.size(), 2u);
  // A scene made in code with a tour line in its info: the typed tour is what is written.
  scene.info.push_back("photowalk-tour 9 9 9 8 8 8");
  const std::vector<std::string> info = infoForFile(scene, urlOf);
  ASSERT_EQ(info.size(), 2u);
  EXPECT_EQ(info[1], encodeTourLine(scene.tour));
}

TEST(ModelInfo, TextureSourcesStayLastAndComeBack) {
  Scene scene = photoScene();
  auto texture = std::make_shared<Texture>();
  texture->image = std::make_shared<Image>();
  texture->url = "wall.png";
  texture->sourceFromTexCoord = glm::mat3(2.0f);
  auto appearance = std::make_shared<Appearance>();
  appearance->texture = texture;
  scene.shapes.push_back({std::make_shared<Mesh>(), appearance, glm::mat4(1.0f), "wall"});
  const std::vector<std::string> info = infoForFile(scene, urlOf);
  ASSERT_EQ(info.size(), 4u);
  EXPECT_EQ(info[3].rfind(std::string(kTextureSourceTag) + " ", 0), 0u);
  Scene read = scene;
  read.info = info;
  read.tour.clear();
  auto plain = std::make_shared<Texture>(*texture);
  plain->sourceFromTexCoord.reset();
  auto plainAppearance = std::make_shared<Appearance>();
  plainAppearance->texture = plain;
  read.shapes[0].appearance = plainAppearance;
  takeModelInfo(read);
  EXPECT_EQ(read.tour, scene.tour);
  ASSERT_TRUE(read.shapes[0].appearance->texture->sourceFromTexCoord);
  EXPECT_EQ(*read.shapes[0].appearance->texture->sourceFromTexCoord, glm::mat3(2.0f));
}

}  // namespace
}  // namespace pw::engine
