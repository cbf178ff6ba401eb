// modeling/image_decode.h: photos the decoders complain of, written here: a JPEG cut
// short (refused, in photowalk's words), one with a damaged block (read, with a
// warning), a PNG cut short (refused, quoting libpng), and a whole one (no warning).
#include "modeling/image_decode.h"

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "modeling/exif.h"

namespace pw::modeling {
namespace {
namespace fs = std::filesystem;

fs::path outDir() {
  const fs::path dir = fs::path(PW_BINARY_DIR) / "test-output" / "image_decode";
  fs::create_directories(dir);
  return dir;
}

// A 320 x 240 photo with detail in every block (so that every part of the file is
// entropy-coded data, not runs of one value).
cv::Mat texturedPhoto() {
  cv::Mat image(240, 320, CV_8UC3);
  cv::randu(image, cv::Scalar::all(0), cv::Scalar::all(255));
  cv::GaussianBlur(image, image, cv::Size(3, 3), 0);
  return image;
}

std::vector<unsigned char> encoded(const std::string& ext) {
  std::vector<unsigned char> bytes;
  EXPECT_TRUE(cv::imencode(ext, texturedPhoto(), bytes));
  return bytes;
}

fs::path write(const std::string& name, const std::vector<unsigned char>& bytes) {
  const fs::path path = outDir() / name;
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  return path;
}

TEST(ImageDecode, AWholePhotoDecodesWithNoWarning) {
  auto image = decodeImage(write("whole.jpg", encoded(".jpg")), cv::IMREAD_COLOR);
  ASSERT_TRUE(image.ok()) << image.message();
  EXPECT_EQ(image->image.size(), cv::Size(320, 240));
  EXPECT_FALSE(image->decoderWarning.has_value()) << *image->decoderWarning;
}

TEST(ImageDecode, AJpegCutShortIsRefusedInPhotowalksWords) {
  std::vector<unsigned char> bytes = encoded(".jpg");
  bytes.resize(bytes.size() / 2);  // a download stopped half way
  const fs::path path = write("cut_short.jpg", bytes);
  auto image = decodeImage(path, cv::IMREAD_COLOR);
  ASSERT_FALSE(image.ok()) << "libjpeg fills the missing rows with grey: the photo would be measured as it is";
  EXPECT_NE(image.message().find("cut short"), std::string::npos) << image.message();
  EXPECT_NE(image.message().find("Premature end of JPEG file"), std::string::npos) << image.message();
  // readPhoto (detect, the editor) says the same, after the file's name.
  auto photo = readPhoto(path);
  ASSERT_FALSE(photo.ok());
  EXPECT_EQ(photo.message().rfind(path.string() + ": the JPEG ends before its last row", 0), 0u) << photo.message();
}

TEST(ImageDecode, AJpegWithADamagedBlockIsReadWithAWarning) {
  std::vector<unsigned char> bytes = encoded(".jpg");
  // A restart marker where the entropy-coded data has none: libjpeg resynchronizes
  // and says "Corrupt JPEG data: ...", and the image is still there.
  const size_t at = bytes.size() * 3 / 4;
  const unsigned char marker[] = {0xFF, 0xD5, 0x00, 0x13};
  std::copy(std::begin(marker), std::end(marker), bytes.begin() + static_cast<std::ptrdiff_t>(at));
  const fs::path path = write("damaged.jpg", bytes);
  auto image = decodeImage(path, cv::IMREAD_COLOR);
  ASSERT_TRUE(image.ok()) << image.message();
  ASSERT_TRUE(image->decoderWarning.has_value());
  EXPECT_EQ(image->decoderWarning->rfind(path.string() + ": the image decoder said \"Corrupt JPEG data", 0), 0u)
      << *image->decoderWarning;
  auto photo = readPhoto(path);
  ASSERT_TRUE(photo.ok()) << photo.message();
  EXPECT_EQ(photo->warnings, std::vector<std::string>{*image->decoderWarning});
}

TEST(ImageDecode, APngCutShortIsRefusedQuotingLibpng) {
  std::vector<unsigned char> bytes = encoded(".png");
  bytes.resize(bytes.size() / 2);
  auto image = decodeImage(write("cut_short.png", bytes), cv::IMREAD_COLOR);
  ASSERT_FALSE(image.ok());
  EXPECT_EQ(image.message().rfind("not a readable PNG/JPEG image (libpng", 0), 0u) << image.message();
}

}  // namespace
}  // namespace pw::modeling
