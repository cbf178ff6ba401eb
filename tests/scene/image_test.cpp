#include "engine/scene/image.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

namespace pw::engine {
namespace {
namespace fs = std::filesystem;

// A directory of this test process's own, removed when the test ends.
struct TempDir {
  fs::path path = fs::temp_directory_path() / ("pw_image_test_" + std::to_string(::getpid()));
  TempDir() { fs::create_directories(path); }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
  fs::path operator/(const char* name) const { return path / name; }
};

TEST(Image, PngRoundTripIsExact) {
  Image img = makeImage(5, 3, 0x11223344);
  img.pixel(4, 2)[0] = 200;
  TempDir dir;
  const fs::path path = dir / "round.png";
  ASSERT_TRUE(saveImage(path, img).ok());
  auto back = loadImage(path);
  ASSERT_TRUE(back.ok()) << back.message();
  EXPECT_EQ(*back, img);
}

// Grey images (intensity textures) stay grey through PNG files.
TEST(Image, GreyImagesStayGreyInFiles) {
  Image grey = makeImage(4, 2, 0x808080ff);
  grey.grey = true;
  grey.pixel(1, 1)[0] = grey.pixel(1, 1)[1] = grey.pixel(1, 1)[2] = 17;
  Image greyAlpha = grey;
  greyAlpha.pixel(3, 0)[3] = 40;
  TempDir dir;
  for (const Image& image : {grey, greyAlpha}) {
    const fs::path path = dir / "grey.png";
    ASSERT_TRUE(saveImage(path, image).ok());
    auto back = loadImage(path);
    ASSERT_TRUE(back.ok()) << back.message();
    EXPECT_EQ(*back, image);
    std::ifstream file(path, std::ios::binary);
    char header[26];
    file.read(header, sizeof header);
    EXPECT_EQ(header[25], image.pixel(3, 0)[3] == 255 ? 0 : 4) << "PNG colour type: grey, or grey + alpha";
  }
}

TEST(Image, MissingFileNamesTheFile) {
  auto r = loadImage("/nonexistent/brick.png");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.message().find("/nonexistent/brick.png"), std::string::npos);
}

TEST(Image, CorruptFileIsAnErrorNotACrash) {
  TempDir dir;
  const fs::path path = dir / "corrupt.png";
  std::ofstream(path) << "\x89PNG\r\n\x1a\n garbage";
  auto r = loadImage(path);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.message().find("corrupt.png"), std::string::npos);
}

TEST(Image, SaveIntoMissingFolderFailsCleanly) {
  Status s = saveImage("/nonexistent-folder/x.png", makeImage(2, 2));
  EXPECT_FALSE(s.ok());
}

}  // namespace
}  // namespace pw::engine
