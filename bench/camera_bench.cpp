// camera_bench: what the editor's camera adds (issue 13), medians against baselines in
// the same run.
// 1. Opening a 12-megapixel JPEG stored on its side with EXIF (Orientation 6, focal
//    length, sensor): modeling::readPhoto (pixels read without orientation, EXIF read
//    with libexif, the pixels turned) against OpenCV's imread, which turns them itself
//    (the budget: under 1 s to the first frame with corners, detection included).
// 2. One drag step's warnings on the handles (handleWarnings) against the measurement
//    it follows (measureCorridor), on corridor_b's corners scaled to 4000 x 3000.
#include <cstdio>
#include <filesystem>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "bench/bench_timing.h"
#include "editor/edit/handle_warnings.h"
#include "metrology/measure.h"
#include "modeling/exif.h"
#include "tests/support/exif_jpeg.h"
#include "tests/support/groundtruth.h"

namespace {

using namespace pw;
constexpr int kRuns = 7;
constexpr int kSteps = 60;

}  // namespace

int main() {
  const groundtruth::GroundTruth truth = groundtruth::loadGroundTruth("corridor_b");
  const double s = 4000.0 / truth.imageWidth;

  // 1. The photo: corridor_b at 4000 x 3000, stored turned anticlockwise.
  cv::Mat upright, stored;
  cv::resize(cv::imread(truth.image.string()), upright, cv::Size(4000, 3000), 0, 0, cv::INTER_CUBIC);
  cv::rotate(upright, stored, cv::ROTATE_90_COUNTERCLOCKWISE);
  test::ExifFields f;
  f.orientation = 6;
  f.focalLength = {502299, 100000};
  f.focalPlaneXResolution = f.focalPlaneYResolution = std::pair<unsigned, unsigned>{unsigned(1600 * s + 0.5), 1};
  f.focalPlaneResolutionUnit = 3;
  const std::filesystem::path path = std::filesystem::path(PW_BINARY_DIR) / "bench" / "camera_bench_12mp.jpg";
  test::writeBytes(path, test::jpegWithApp1(stored, test::exifBlock(f)));

  double openCvMs = 0, readPhotoMs = 0, exifMs = 0;
  {
    std::vector<double> a, b, c;
    for (int run = 0; run < kRuns; ++run) {  // alternated, so that both see the same machine state
      a.push_back(bench::medianMs(1, [&] { (void)cv::imread(path.string(), cv::IMREAD_COLOR); }));
      b.push_back(bench::medianMs(1, [&] { (void)modeling::readPhoto(path); }));
      c.push_back(bench::medianMs(1, [&] { (void)modeling::readExif(path); }));
    }
    openCvMs = bench::median(a);
    readPhotoMs = bench::median(b);
    exifMs = bench::median(c);
  }
  auto photo = modeling::readPhoto(path);
  if (!photo || !photo->focal || photo->bgr.cols != 4000) {
    std::fprintf(stderr, "error: the 12-megapixel photo did not read back upright with its focal length\n");
    return 1;
  }

  // 2. A drag of P5, as edit_bench's.
  metrology::Shot shot;
  shot.imageWidth = 4000;
  shot.imageHeight = 3000;
  shot.focalPx = truth.focalPx * s;
  shot.cameraHeightM = truth.cameraHeightM;
  for (int k = 0; k < metrology::kCornerCount; ++k) shot.cornersPx[k] = truth.cornersPx[k] * s;
  std::vector<double> measureMs, warningsMs;
  size_t said = 0;
  for (int run = 0; run < kRuns; ++run) {
    for (int step = 0; step < kSteps; ++step) {
      metrology::Shot moved = shot;
      moved.cornersPx[metrology::P5] += glm::dvec2(0.02 * step, -0.01 * step);
      Result<metrology::Measurement> m = makeError("none");
      measureMs.push_back(bench::medianMs(1, [&] { m = metrology::measureCorridor(moved); }));
      if (!m) {
        std::fprintf(stderr, "error: %s\n", m.message().c_str());
        return 1;
      }
      warningsMs.push_back(bench::medianMs(1, [&] { said += edit::handleWarnings(moved, &*m).size(); }));
    }
  }

  std::printf("camera_bench: medians of %d runs (the photo), %d x %d steps (the warnings)\n", kRuns, kRuns, kSteps);
  std::printf("  baseline: cv::imread, 12 MP JPEG, Orientation 6   %8.2f ms\n", openCvMs);
  std::printf("  modeling::readPhoto (EXIF, turned itself)         %8.2f ms  (%+.1f%%)\n", readPhotoMs,
              100.0 * (readPhotoMs / openCvMs - 1.0));
  std::printf("  of which modeling::readExif                       %8.3f ms\n", exifMs);
  std::printf("  baseline: measureCorridor, one drag step          %8.3f ms\n", bench::median(measureMs));
  std::printf("  handleWarnings, one drag step                     %8.3f ms  (%zu warnings in all)\n",
              bench::median(warningsMs), said);
  return 0;
}
