#include "tests/gpu/image_compare.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <vector>

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

std::string TileDifference::describe() const {
  if (sizeMismatch) return "image sizes differ";
  std::ostringstream s;
  s.precision(3);
  s << columns << "x" << rows << " tiles: worst tile (" << worstColumn << ", " << worstRow << ") differs by " << worst
    << "/255 in its mean colour, tiles on average by " << average << "/255";
  if (gain[0] != 1 || gain[1] != 1 || gain[2] != 1) s << " (after gains " << gain[0] << ", " << gain[1] << ", " << gain[2] << ")";
  return s.str();
}

namespace {

// Mean RGB of each tile, row by row.
std::vector<std::array<double, 3>> tileMeans(const engine::Image& image, int columns, int rows) {
  std::vector<std::array<double, 3>> means(static_cast<size_t>(columns) * rows);
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < columns; ++c) {
      const int x0 = c * image.width / columns, x1 = (c + 1) * image.width / columns;
      const int y0 = r * image.height / rows, y1 = (r + 1) * image.height / rows;
      std::array<double, 3> sum{0, 0, 0};
      for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x) {
          for (int k = 0; k < 3; ++k) sum[k] += image.pixel(x, y)[k];
        }
      }
      const double n = std::max(1, (x1 - x0) * (y1 - y0));
      for (int k = 0; k < 3; ++k) means[static_cast<size_t>(r) * columns + c][k] = sum[k] / n;
    }
  }
  return means;
}

}  // namespace

TileDifference compareTiles(const engine::Image& actual, const engine::Image& expected, int columns, int rows,
                            TileGain gain) {
  TileDifference d;
  d.columns = columns;
  d.rows = rows;
  if (actual.width != expected.width || actual.height != expected.height || actual.empty() || columns < 1 ||
      rows < 1 || columns > actual.width || rows > actual.height) {
    d.sizeMismatch = true;
    return d;
  }
  const auto a = tileMeans(actual, columns, rows), e = tileMeans(expected, columns, rows);
  if (gain == TileGain::kMatchGlobalMean) {
    // Tiles differ in size by at most a pixel; weighting them alike is close enough.
    for (int k = 0; k < 3; ++k) {
      double sumA = 0, sumE = 0;
      for (size_t t = 0; t < a.size(); ++t) {
        sumA += a[t][k];
        sumE += e[t][k];
      }
      d.gain[k] = sumA > 0 ? sumE / sumA : 1.0;
    }
  }
  double total = 0;
  for (size_t t = 0; t < a.size(); ++t) {
    double tileWorst = 0;
    for (int k = 0; k < 3; ++k) tileWorst = std::max(tileWorst, std::abs(a[t][k] * d.gain[k] - e[t][k]));
    total += tileWorst;
    if (tileWorst > d.worst) {
      d.worst = tileWorst;
      d.worstColumn = static_cast<int>(t % columns);
      d.worstRow = static_cast<int>(t / columns);
    }
  }
  d.average = total / static_cast<double>(a.size());
  return d;
}

engine::Image mirroredLeftRight(const engine::Image& image) {
  engine::Image out = image;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) std::copy_n(image.pixel(image.width - 1 - x, y), 4, out.pixel(x, y));
  }
  return out;
}

engine::Image upsideDown(const engine::Image& image) {
  engine::Image out = image;
  const size_t row = static_cast<size_t>(image.width) * 4;
  for (int y = 0; y < image.height; ++y) {
    std::copy_n(image.rgba.data() + (image.height - 1 - y) * row, row, out.rgba.data() + y * row);
  }
  return out;
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
