#include "tests/gpu/image_compare.h"

#include <algorithm>
#include <cstdlib>
#include <sstream>

namespace pw::test {

std::string ImageDifference::describe() const {
  if (sizeMismatch) return "image sizes differ";
  std::ostringstream s;
  s << (fractionWithin2 * 100) << "% of pixels within 2/255 (need 99%), " << (fractionWithin16 * 100)
    << "% within 16/255 (need 99.9%), largest difference " << maxDifference << "/255";
  return s.str();
}

ImageDifference compareImages(const engine::Image& actual, const engine::Image& expected) {
  ImageDifference d;
  if (actual.width != expected.width || actual.height != expected.height || actual.rgba.size() != expected.rgba.size()) {
    d.sizeMismatch = true;
    return d;
  }
  size_t within2 = 0, within16 = 0;
  const size_t pixels = actual.rgba.size() / 4;
  for (size_t i = 0; i < pixels; ++i) {
    int worst = 0;
    for (int c = 0; c < 4; ++c) worst = std::max(worst, std::abs(int(actual.rgba[i * 4 + c]) - int(expected.rgba[i * 4 + c])));
    within2 += worst <= 2;
    within16 += worst <= 16;
    d.maxDifference = std::max(d.maxDifference, worst);
  }
  d.fractionWithin2 = pixels ? double(within2) / double(pixels) : 1.0;
  d.fractionWithin16 = pixels ? double(within16) / double(pixels) : 1.0;
  return d;
}

engine::Image differenceImage(const engine::Image& actual, const engine::Image& expected) {
  engine::Image out = engine::makeImage(actual.width * 2, actual.height);
  if (actual.width != expected.width || actual.height != expected.height) return out;
  for (int y = 0; y < actual.height; ++y) {
    for (int x = 0; x < actual.width; ++x) {
      const uint8_t* a = actual.pixel(x, y);
      const uint8_t* e = expected.pixel(x, y);
      uint8_t* left = out.pixel(x, y);
      uint8_t* right = out.pixel(x + actual.width, y);
      int worst = 0;
      for (int c = 0; c < 3; ++c) {
        const int diff = std::abs(int(a[c]) - int(e[c]));
        left[c] = uint8_t(std::min(255, diff * 8));
        worst = std::max(worst, diff);
      }
      // Right half: the actual frame, darkened, with failing pixels in red.
      for (int c = 0; c < 3; ++c) right[c] = uint8_t(a[c] / 3);
      if (worst > 2) {
        right[0] = 255;
        right[1] = right[2] = 0;
      }
    }
  }
  return out;
}

std::filesystem::path testOutputDir() {
  const std::filesystem::path dir = std::filesystem::path(PW_BINARY_DIR) / "test-output";
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  return dir;
}

std::string checkGolden(const engine::Image& actual, const std::string& name) {
  const std::filesystem::path golden = std::filesystem::path(PW_GOLDEN_DIR) / (name + ".png");
  const char* update = std::getenv("PW_UPDATE_GOLDEN");
  if (update && std::string(update) == "1") {
    if (auto saved = engine::saveImage(golden, actual); !saved) return "cannot write golden: " + saved.message();
    return "";
  }
  auto expected = engine::loadImage(golden);
  const std::filesystem::path dir = testOutputDir();
  const std::filesystem::path actualPath = dir / (name + "_actual.png");
  if (!expected) {
    (void)engine::saveImage(actualPath, actual);
    return "no golden image (" + expected.message() + "); the frame is in " + actualPath.string() +
           "; create the golden with PW_UPDATE_GOLDEN=1";
  }
  const ImageDifference d = compareImages(actual, *expected);
  if (d.passes()) return "";
  const std::filesystem::path diffPath = dir / (name + "_diff.png");
  (void)engine::saveImage(actualPath, actual);
  (void)engine::saveImage(diffPath, differenceImage(actual, *expected));
  return name + ": " + d.describe() + "; see " + actualPath.string() + " and " + diffPath.string();
}

}  // namespace pw::test
