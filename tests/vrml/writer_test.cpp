#include "engine/vrml/vrml_writer.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "base/atomic_file.h"
#include "engine/vrml/gzip.h"
#include "engine/vrml/vrml_reader.h"
#include "engine/vrml/vrml_geometry.h"
#include "tests/vrml/scene_compare.h"

namespace pw::engine {
namespace {

namespace fs = std::filesystem;

fs::path freshDir(const std::string& name) {
  const fs::path dir = fs::path(PW_BINARY_DIR) / "test_output" / "vrml" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

Scene texturedScene() {
  Scene s;
  auto image = std::make_shared<Image>(makeImage(2, 2, 0x336699ff));
  image->pixel(1, 1)[0] = 200;
  auto texture = std::make_shared<Texture>();
  texture->image = image;
  texture->url = "../photos/wall left.jpg";
  texture->wrapT = TextureWrap::kClamp;
  auto appearance = std::make_shared<Appearance>();
  appearance->texture = texture;
  appearance->material = Material{};
  appearance->material->diffuseColor = {0.1f, 0.2f, 0.3f};
  auto mesh = std::make_shared<Mesh>(vrml::makeBox({1, 2, 3}, true));
  for (int i = 0; i < 3; ++i) {
    Shape shape;
    shape.mesh = mesh;
    shape.appearance = appearance;
    shape.transform[3] = glm::vec4(static_cast<float>(i) * 2.5f, 0, 0, 1);
    shape.name = "wall_" + std::to_string(i);
    s.shapes.push_back(shape);
  }
  s.title = "Corridor \"A\"";
  Viewpoint v;
  v.description = "Start";
  v.position = {0.1f, 1.6f, 5};
  s.viewpoints.push_back(v);
  return s;
}

TEST(VrmlWriter, SharedPiecesBecomeDefUseAndTexturesGoBesideTheFile) {
  const fs::path dir = freshDir("shared");
  ASSERT_TRUE(writeVrml(texturedScene(), dir / "hall.wrl").ok());
  auto text = readFile(dir / "hall.wrl");
  ASSERT_TRUE(text.ok());
  EXPECT_EQ(text->rfind("#VRML V2.0 utf8\n", 0), 0u);
  EXPECT_NE(text->find("appearance DEF Appearance_"), std::string::npos);
  EXPECT_NE(text->find("appearance USE Appearance_"), std::string::npos);
  EXPECT_NE(text->find("geometry DEF Mesh_"), std::string::npos);
  EXPECT_NE(text->find("geometry USE Mesh_"), std::string::npos);
  EXPECT_NE(text->find("url \"hall_wall_left.png\""), std::string::npos);
  EXPECT_NE(text->find("title \"Corridor \\\"A\\\"\""), std::string::npos);
  EXPECT_NE(text->find("description \"Start\""), std::string::npos);
  EXPECT_NE(text->find("DEF wall_0 Shape"), std::string::npos);
  EXPECT_NE(text->find("position 0.1 1.6 5"), std::string::npos);  // shortest round-trip floats
  EXPECT_TRUE(fs::exists(dir / "hall_wall_left.png"));
  // No temporary files left behind.
  int files = 0;
  for (const auto& entry : fs::directory_iterator(dir)) files += entry.is_regular_file();
  EXPECT_EQ(files, 2);
}

TEST(VrmlWriter, GzipOutputAndTitleOption) {
  const fs::path dir = freshDir("gz");
  VrmlWriteOptions options;
  options.title = "Override";
  options.jpegTextures = true;
  ASSERT_TRUE(writeVrml(texturedScene(), dir / "hall.wrl.gz", options).ok());
  auto bytes = readFile(dir / "hall.wrl.gz");
  ASSERT_TRUE(bytes.ok());
  EXPECT_TRUE(isGzip(*bytes));
  EXPECT_TRUE(fs::exists(dir / "hall_wall_left.jpg"));
  auto scene = readVrml(dir / "hall.wrl.gz", nullptr);
  ASSERT_TRUE(scene.ok()) << scene.message();
  EXPECT_EQ(scene->title, "Override");
  EXPECT_EQ(scene->shapes.size(), 3u);
}

TEST(VrmlWriter, WrittenSceneReadsBackTheSame) {
  const fs::path dir = freshDir("exact");
  const Scene original = texturedScene();
  ASSERT_TRUE(writeVrml(original, dir / "hall.wrl").ok());
  auto back = readVrml(dir / "hall.wrl", nullptr);
  ASSERT_TRUE(back.ok()) << back.message();
  EXPECT_EQ(sceneDifference(original, *back), "");
  EXPECT_EQ(back->shapes[0].appearance->texture->url, "hall_wall_left.png");
}

TEST(VrmlWriter, MalformedScenesAreRefusedAndNothingIsWritten) {
  const fs::path dir = freshDir("bad");
  Scene s = texturedScene();
  auto broken = std::make_shared<Mesh>(*s.shapes[0].mesh);
  broken->indices.push_back(999);
  broken->indices.push_back(0);
  broken->indices.push_back(1);
  s.shapes[1].mesh = broken;
  const Status status = writeVrml(s, dir / "hall.wrl");
  ASSERT_FALSE(status.ok());
  EXPECT_EQ(status.message(), (dir / "hall.wrl").string() + ": shape 1: mesh index 999 is out of range");
  EXPECT_TRUE(fs::is_empty(dir));
  Scene nan = texturedScene();
  nan.shapes[2].transform[3].x = std::nanf("");
  EXPECT_FALSE(writeVrml(nan, dir / "hall.wrl").ok());
  EXPECT_TRUE(fs::is_empty(dir));
  EXPECT_FALSE(writeVrml(texturedScene(), dir / "no_such_folder" / "hall.wrl").ok());
}

TEST(VrmlWriter, NamesBecomeValidIdentifiers) {
  Scene s;
  Shape shape;
  shape.mesh = std::make_shared<Mesh>(vrml::makeBox({1, 1, 1}, false));
  for (const char* name : {"1st wall", "TRUE", "a.b{c}", "ok_name"}) {
    shape.name = name;
    s.shapes.push_back(shape);
  }
  auto text = vrmlText(s, {}, {});
  ASSERT_TRUE(text.ok());
  for (const char* id : {"DEF _1st_wall Shape", "DEF _TRUE Shape", "DEF a_b_c_ Shape", "DEF ok_name Shape"}) {
    EXPECT_NE(text->find(id), std::string::npos) << id;
  }
  auto back = readVrmlString(*text, ".", nullptr);
  ASSERT_TRUE(back.ok()) << back.message();
  EXPECT_EQ(back->shapes.size(), 4u);
}

}  // namespace
}  // namespace pw::engine
