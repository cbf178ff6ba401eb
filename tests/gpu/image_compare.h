// Golden-image comparison for render tests.
//
// Tolerance: at least 99% of pixels within 2/255 in every channel, and at least
// 99.9% within 16/255 (so a missing thin feature, a few hundred pixels, still fails).
// Lavapipe is deterministic on one machine; the slack absorbs other CPUs' vector
// widths and LLVM versions at edges and in pow()/acos().
//
// Goldens change only through the explicit update step: run the test with
// PW_UPDATE_GOLDEN=1, look at the new PNG, commit it.
#pragma once

#include <filesystem>
#include <string>

#include "engine/scene/image.h"

namespace pw::test {

struct ImageDifference {
  double fractionWithin2 = 0;   // pixels whose channels all differ by <= 2
  double fractionWithin16 = 0;  // ... by <= 16
  int maxDifference = 0;
  bool sizeMismatch = false;
  bool passes() const { return !sizeMismatch && fractionWithin2 >= 0.99 && fractionWithin16 >= 0.999; }
  std::string describe() const;
};

ImageDifference compareImages(const engine::Image& actual, const engine::Image& expected);

// |actual - expected| x 8 per channel, pixels beyond 2/255 marked in red on the right half.
engine::Image differenceImage(const engine::Image& actual, const engine::Image& expected);

// Layout-aware comparison of two frames of the same view that need not match pixel for
// pixel (another renderer, a video codec): both are cut into a grid of `columns` x
// `rows` tiles and each tile's mean colour is compared. A mirrored or upside-down
// frame, or swapped textures, moves colour between tiles, which a global mean colour
// or a global coverage cannot see. Tile (c, r) spans pixels [c * width / columns,
// (c + 1) * width / columns) and likewise in y.
enum class TileGain {
  kNone,
  // Each RGB channel of `actual` scaled first so that its mean over the frame equals
  // `expected`'s: another viewer's headlight or exposure, not the layout.
  kMatchGlobalMean,
};

struct TileDifference {
  int columns = 0, rows = 0;
  bool sizeMismatch = false;
  double gain[3] = {1, 1, 1};  // applied to `actual` (TileGain::kMatchGlobalMean)
  double worst = 0;            // largest |mean difference| over tiles and RGB channels, /255
  int worstColumn = 0, worstRow = 0;
  double average = 0;          // each tile's largest channel difference, averaged over tiles
  std::string describe() const;
};

TileDifference compareTiles(const engine::Image& actual, const engine::Image& expected, int columns, int rows,
                            TileGain gain = TileGain::kNone);

// The image mirrored left to right, and turned upside down (mirrored top to bottom):
// what a comparison that sees layout must reject.
engine::Image mirroredLeftRight(const engine::Image& image);
engine::Image upsideDown(const engine::Image& image);

// Compares `actual` with PW_GOLDEN_DIR/NAME.png. On failure writes NAME_actual.png and
// NAME_diff.png under PW_BINARY_DIR/test-output and returns a message naming them;
// with PW_UPDATE_GOLDEN=1 writes the golden instead. Empty string: passed.
std::string checkGolden(const engine::Image& actual, const std::string& name);

// Output folder for images tests write (PW_BINARY_DIR/test-output), created on demand.
std::filesystem::path testOutputDir();

}  // namespace pw::test
