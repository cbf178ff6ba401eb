// Lens distortion end to end on the ground truth photographed through a distorting lens
// (tests/metrology/make_distorted.py: OpenCV's radial model at k1 = -0.1 and -0.2): the
// exact corners with the true lens measure exactly; detect finds the lens from the
// photo's straight lines and its shot measures within 0.5%; photos without distortion
// get none. Prints the table (ctest -V): each dimension's error without the lens model
// (today's detect and measure) and with it.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "metrology/detect/detect.h"
#include "metrology/measure.h"
#include "modeling/shot_file.h"
#include "tests/support/exif_jpeg.h"
#include "tests/support/groundtruth.h"
#include "tests/support/run_command.h"

namespace pw::metrology::detect {
namespace {
namespace fs = std::filesystem;

struct Case {
  std::string name;  // corridor_a_k010
  double k1 = 0;
  // The largest error of a dimension from the detected shot, percent: the 0.5%.
  // (corridor_a was 1.5% off until the far wall's foot took its innermost edge: the
  // checker floor's next joint lies 1.5-3 px beyond it and the warp's blur merged them.)
  double maxErrorPct = 0.5;
};

std::vector<Case> distortedCases() {
  std::vector<Case> out;
  for (const char* scene :
       {"corridor_a", "corridor_b", "corridor_c", "corridor_d", "corridor_e", "corridor_f", "corridor_g", "corridor_h"}) {
    out.push_back({std::string(scene) + "_k010", -0.1});
    out.push_back({std::string(scene) + "_k020", -0.2});
  }
  return out;
}

fs::path distortedShot(const std::string& name) { return fs::path(PW_BINARY_DIR) / "groundtruth-distorted" / (name + ".json"); }

struct Errors {
  double width = NAN, height = NAN, length = NAN;
  double worst() const { return std::max({std::abs(width), std::abs(height), std::abs(length)}); }
};

Errors errorsOf(const Measurement& m, const groundtruth::GroundTruth& truth) {
  return {100 * (m.size.widthM / truth.widthM - 1), 100 * (m.size.heightM / truth.heightM - 1),
          100 * (m.size.lengthM / truth.lengthM - 1)};
}

// The truth of a distorted photo: the ground truth's answers (its file, read as
// groundtruth.h reads the undistorted one) and the shot with the corners through the lens.
struct DistortedTruth {
  groundtruth::GroundTruth answers;
  modeling::LoadedShot shot;
};

DistortedTruth loadDistorted(const std::string& name) {
  const fs::path path = distortedShot(name);
  if (!fs::exists(path)) throw std::runtime_error("no " + path.string() + " (the build makes it: target groundtruth_distorted)");
  DistortedTruth t;
  t.answers = groundtruth::loadGroundTruth(name.substr(0, name.size() - 5));
  auto shot = modeling::loadShot(path);
  if (!shot) throw std::runtime_error(shot.message());
  t.shot = std::move(*shot);
  return t;
}

class DistortedGroundTruth : public ::testing::TestWithParam<Case> {};

TEST_P(DistortedGroundTruth, ExactCornersWithTheTrueLensMeasureExactly) {
  const DistortedTruth t = loadDistorted(GetParam().name);
  ASSERT_TRUE(t.shot.shot.distortion.has_value());
  auto m = measureCorridor(t.shot.shot);
  ASSERT_TRUE(m.ok()) << m.message();
  const Errors e = errorsOf(*m, t.answers);
  EXPECT_LT(e.worst(), 1e-4) << "width " << e.width << "% height " << e.height << "% length " << e.length << "%";
  // Without the lens (today's measure) the same corners are off by percent.
  Shot pinhole = t.shot.shot;
  pinhole.distortion = RadialDistortion{};
  auto today = measureCorridor(pinhole);
  ASSERT_TRUE(today.ok()) << today.message();
  const Errors before = errorsOf(*today, t.answers);
  std::printf("[distortion] %-18s exact corners: without the lens %+6.2f %+6.2f %+6.2f %%, with it %+.5f %+.5f %+.5f %%\n",
              GetParam().name.c_str(), before.width, before.height, before.length, e.width, e.height, e.length);
}

TEST_P(DistortedGroundTruth, DetectFindsTheLensAndMeasuresWithinHalfAPercent) {
  const DistortedTruth t = loadDistorted(GetParam().name);
  const cv::Mat photo = cv::imread(t.shot.shot.imagePath, cv::IMREAD_COLOR);
  ASSERT_FALSE(photo.empty());
  DetectOptions options;
  options.focalPx = t.answers.focalPx;
  options.principalPointPx = t.answers.principalPointPx;
  options.nearAtMarkedCrossSection = true;  // length to the painted band, as the answers have it
  const auto measureDetected = [&](const DetectOptions& o, Errors& errors, RadialDistortion& lens) -> bool {
    auto d = detectCorridor(photo, o);
    EXPECT_TRUE(d.ok()) << d.message();
    if (!d || !d->found) return false;
    Shot shot = t.shot.shot;
    for (int k = 0; k < kCornerCount; ++k) shot.cornersPx[k] = d->corners[k].px;
    shot.distortion = d->distortion.isNone() ? std::nullopt : std::optional(d->distortion);
    lens = d->distortion;
    auto m = measureCorridor(shot);
    EXPECT_TRUE(m.ok()) << m.message();
    if (!m) return false;
    errors = errorsOf(*m, t.answers);
    return true;
  };
  DetectOptions pinholeOnly = options;
  pinholeOnly.estimateDistortion = false;
  Errors today, now;
  RadialDistortion none, found;
  const bool todayFound = measureDetected(pinholeOnly, today, none);
  ASSERT_TRUE(measureDetected(options, now, found)) << "no corridor found through the lens";
  std::printf("[distortion] %-18s detect+measure: without the lens %s%+6.2f %+6.2f %+6.2f %%, with it %+6.3f %+6.3f %+6.3f %% "
              "(k1 %.4f, true %.2f)\n",
              GetParam().name.c_str(), todayFound ? "" : "(not found) ", today.width, today.height, today.length,
              now.width, now.height, now.length, found.k1, GetParam().k1);
  EXPECT_NEAR(found.k1, GetParam().k1, 0.02);
  EXPECT_LT(now.worst(), GetParam().maxErrorPct) << "width " << now.width << "% height " << now.height << "% length " << now.length << "%";
}

INSTANTIATE_TEST_SUITE_P(Lens, DistortedGroundTruth, ::testing::ValuesIn(distortedCases()),
                         [](const auto& info) { return info.param.name; });

// The same photo three times larger (2400x1800): detection then runs on a working copy
// at half its size, undistorted through the lens scaled to it, and the sub-pixel fits
// read the large photo through the lens. It must measure as the photo does.
TEST(DistortedGroundTruth, ALargePhotoThroughTheLensMeasuresAsTheSmallOne) {
  constexpr double kScale = 3.0;
  for (const char* name : {"corridor_a_k020", "corridor_f_k020"}) {
    const DistortedTruth t = loadDistorted(name);
    const cv::Mat small = cv::imread(t.shot.shot.imagePath, cv::IMREAD_COLOR);
    ASSERT_FALSE(small.empty()) << name;
    cv::Mat large;
    cv::resize(small, large, {}, kScale, kScale, cv::INTER_CUBIC);
    // Pixel centres: u_large = 3 (u + 0.5) - 0.5; k1 is normalised by the focal length.
    const auto toLarge = [&](glm::dvec2 p) { return kScale * (p + 0.5) - 0.5; };
    DetectOptions options;
    options.focalPx = kScale * t.answers.focalPx;
    options.principalPointPx = toLarge(t.answers.principalPointPx);
    options.nearAtMarkedCrossSection = true;
    auto d = detectCorridor(large, options);
    ASSERT_TRUE(d.ok()) << d.message();
    ASSERT_TRUE(d->found) << name;
    Shot shot = t.shot.shot;
    shot.imageWidth = large.cols;
    shot.imageHeight = large.rows;
    shot.focalPx = *options.focalPx;
    shot.principalPointPx = options.principalPointPx;
    for (int k = 0; k < kCornerCount; ++k) shot.cornersPx[k] = d->corners[k].px;
    shot.distortion = d->distortion;
    auto m = measureCorridor(shot);
    ASSERT_TRUE(m.ok()) << m.message();
    const Errors e = errorsOf(*m, t.answers);
    std::printf("[distortion] %-18s x3 (2400x1800) detect+measure: %+6.3f %+6.3f %+6.3f %% (k1 %.4f)\n", name, e.width,
                e.height, e.length, d->distortion.k1);
    EXPECT_NEAR(d->distortion.k1, -0.2, 0.02) << name;
    EXPECT_LT(e.worst(), 0.5) << name << ": width " << e.width << "% height " << e.height << "% length " << e.length << "%";
  }
}

// A rough box on a distorted photo whose lens is known (a shot file's distortion: the
// editor's camera panel, a calibrated camera): detection reads the photo through that
// lens and fits none of its own, and the corners come back where the lens shows them. A
// known pinhole ({0, 0}) is taken as given too: no lens is fitted.
TEST(DistortedGroundTruth, ARoughBoxWithTheLensKnownComesBackThroughIt) {
  for (const char* name : {"corridor_a_k020", "corridor_e_k010"}) {
    const DistortedTruth t = loadDistorted(name);
    const cv::Mat photo = cv::imread(t.shot.shot.imagePath, cv::IMREAD_COLOR);
    ASSERT_FALSE(photo.empty()) << name;
    DetectOptions options;
    options.focalPx = t.answers.focalPx;
    options.principalPointPx = t.answers.principalPointPx;
    std::array<glm::dvec2, 8> rough = t.shot.shot.cornersPx;
    for (int k = 0; k < kCornerCount; ++k) rough[k] += 8.0 * glm::dvec2(std::cos(0.9 * k + 0.2), std::sin(0.9 * k + 0.2));
    options.hintPx = rough;
    options.lens = t.shot.shot.distortion;
    auto known = detectCorridor(photo, options);
    ASSERT_TRUE(known.ok()) << known.message();
    ASSERT_TRUE(known->found) << name << ": " << known->notFoundReason;
    EXPECT_EQ(known->distortion, *t.shot.shot.distortion) << name;
    EXPECT_EQ(known->plumbLineCount, 0) << name;
    double farWorst = 0;
    for (int k = 0; k < 4; ++k) farWorst = std::max(farWorst, glm::length(known->corners[k].px - t.shot.shot.cornersPx[k]));
    std::printf("[distortion] %-18s rough box, the lens known: far wall within %.2f px\n", name, farWorst);
    EXPECT_LT(farWorst, 1.5) << name;

    options.lens = RadialDistortion{};
    auto pinhole = detectCorridor(photo, options);
    ASSERT_TRUE(pinhole.ok()) << pinhole.message();
    EXPECT_TRUE(pinhole->distortion.isNone()) << name << ": k1 " << pinhole->distortion.k1;
    EXPECT_EQ(pinhole->plumbLineCount, 0) << name;

    options.lens = RadialDistortion{std::nan(""), 0};
    auto bad = detectCorridor(photo, options);
    ASSERT_FALSE(bad.ok()) << name;
    EXPECT_NE(bad.message().find("the lens given"), std::string::npos) << bad.message();
  }
}

// The ground truth without distortion: detect sees none, so its shots and everything
// made from them stay what they were (no distortion field).
TEST(UndistortedGroundTruth, DetectFindsNoLensDistortion) {
  for (const groundtruth::GroundTruth& g : groundtruth::loadAllGroundTruth()) {
    const cv::Mat photo = cv::imread(g.image.string(), cv::IMREAD_COLOR);
    ASSERT_FALSE(photo.empty()) << g.name;
    for (const bool focalGiven : {true, false}) {
      DetectOptions options;
      if (focalGiven) options.focalPx = g.focalPx;
      options.principalPointPx = g.principalPointPx;
      options.nearAtMarkedCrossSection = true;
      auto d = detectCorridor(photo, options);
      ASSERT_TRUE(d.ok()) << d.message();
      EXPECT_TRUE(d->distortion.isNone()) << g.name << (focalGiven ? "" : " (focal withheld)") << ": k1 " << d->distortion.k1
                                          << " from " << d->plumbLineCount << " lines";
    }
  }
}

// The commands: detect writes the lens it found into the shot (and nothing for a photo
// without distortion), measure says where its distortion came from.
TEST(DistortionCommands, DetectWritesTheLensAndMeasureUsesIt) {
  const fs::path dir = fs::path(PW_BINARY_DIR) / "test-output" / "distortion_commands";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string photowalk = (fs::path(PW_BINARY_DIR) / "photowalk").string();
  const groundtruth::GroundTruth truth = groundtruth::loadGroundTruth("corridor_f");
  const std::string given = " --focal-px " + std::to_string(truth.focalPx) + " --near-at-marked --camera-height 1.55 -o ";
  const auto slurp = [](const fs::path& path) {
    std::ifstream in(path);
    return nlohmann::json::parse(in, nullptr, false);
  };
  const test::CommandRun distorted =
      test::runCommand(photowalk + " detect " + (fs::path(PW_BINARY_DIR) / "groundtruth-distorted" / "corridor_f_k020.png").string() +
                       given + (dir / "lens.json").string());
  // Written, as a guess: a sure answer needs the room's box fit to agree, and on
  // corridor_f it takes the door for the far wall (34 px off the right one).
  ASSERT_EQ(distorted.exitCode, 3) << distorted.output;
  EXPECT_NE(distorted.output.find("two fits of the room disagree"), std::string::npos) << distorted.output;
  EXPECT_NE(distorted.output.find("lens distortion k1 -0.19"), std::string::npos) << distorted.output;
  const nlohmann::json lens = slurp(dir / "lens.json");
  ASSERT_TRUE(lens.contains("distortion")) << lens.dump();
  EXPECT_NEAR(lens["distortion"]["k1"].get<double>(), -0.2, 0.01);
  EXPECT_EQ(lens["distortion"]["k2"], 0.0);
  EXPECT_EQ(lens["detection"]["distortion"]["method"], "plumb-line");
  const test::CommandRun measured = test::runCommand(photowalk + " measure " + (dir / "lens.json").string() + " 2>/dev/null");
  ASSERT_EQ(measured.exitCode, 0) << measured.output;
  const nlohmann::json m = nlohmann::json::parse(measured.output, nullptr, false);
  EXPECT_EQ(m["camera"]["distortion"]["source"], "shot") << measured.output;

  // A rough shot that carries its lens (here the true one, put in by hand): --hint reads
  // the photo through it, fits none of its own and keeps it.
  nlohmann::json roughShot = lens;
  roughShot["distortion"] = {{"k1", -0.2}, {"k2", 0.0}};
  roughShot["image"] = (fs::path(PW_BINARY_DIR) / "groundtruth-distorted" / "corridor_f_k020.png").string();
  std::ofstream(dir / "rough.json") << roughShot.dump();
  const test::CommandRun hinted =
      test::runCommand(photowalk + " detect --hint " + (dir / "rough.json").string() + " -o " + (dir / "fitted.json").string());
  ASSERT_TRUE(hinted.exitCode == 0 || hinted.exitCode == 3) << hinted.output;
  EXPECT_NE(hinted.output.find("lens distortion k1 -0.2000, k2 0.0000 (the shot's)"), std::string::npos) << hinted.output;
  const nlohmann::json fitted = slurp(dir / "fitted.json");
  ASSERT_TRUE(fitted.contains("distortion")) << fitted.dump();
  EXPECT_EQ(fitted["distortion"]["k1"], -0.2);
  EXPECT_EQ(fitted["detection"]["distortion"]["method"], "given");

  // A calibrated lens given on the command line: read through, not fitted, and kept.
  const std::string distortedPhoto = (fs::path(PW_BINARY_DIR) / "groundtruth-distorted" / "corridor_f_k020.png").string();
  const test::CommandRun calibrated =
      test::runCommand(photowalk + " detect " + distortedPhoto + " --distortion -0.2,0" + given + (dir / "calibrated.json").string());
  ASSERT_TRUE(calibrated.exitCode == 0 || calibrated.exitCode == 3) << calibrated.output;
  EXPECT_NE(calibrated.output.find("lens distortion k1 -0.2000, k2 0.0000 (given)"), std::string::npos) << calibrated.output;
  const nlohmann::json calibratedShot = slurp(dir / "calibrated.json");
  EXPECT_EQ(calibratedShot["distortion"]["k1"], -0.2) << calibratedShot.dump();
  EXPECT_EQ(calibratedShot["detection"]["distortion"]["method"], "given");
  for (const char* bad : {"3", "x", "-0.1,nan"}) {
    const test::CommandRun refused =
        test::runCommand(photowalk + " detect " + distortedPhoto + " --distortion " + bad + given + (dir / "refused.json").string());
    EXPECT_EQ(refused.exitCode, 1) << bad << ": " << refused.output;
    EXPECT_NE(refused.output.find("--distortion"), std::string::npos) << refused.output;
  }
  EXPECT_FALSE(fs::exists(dir / "refused.json"));
  const test::CommandRun noFocal =
      test::runCommand(photowalk + " detect " + distortedPhoto + " --distortion -0.2 -o " + (dir / "refused.json").string());
  EXPECT_EQ(noFocal.exitCode, 1) << noFocal.output;
  EXPECT_NE(noFocal.output.find("normalised by the focal length"), std::string::npos) << noFocal.output;

  const test::CommandRun clean = test::runCommand(photowalk + " detect " + truth.image.string() + given + (dir / "plain.json").string());
  ASSERT_EQ(clean.exitCode, 3) << clean.output;
  EXPECT_EQ(clean.output.find("lens distortion"), std::string::npos) << clean.output;
  const nlohmann::json plain = slurp(dir / "plain.json");
  EXPECT_FALSE(plain.contains("distortion")) << plain.dump();
  EXPECT_FALSE(plain["detection"].contains("distortion"));
}

// The EXIF focal length (issue 15 part 4): a JPEG of the ground truth whose EXIF gives
// FocalLength with FocalPlaneXResolution, measured with no focal length in the shot nor
// on the command line, and detected then measured the same way.
class ExifFocalLength : public ::testing::Test {
 protected:
  void SetUp() override {
    // One folder per test: CTest runs them in parallel.
    dir_ = fs::path(PW_BINARY_DIR) / "test-output" / "exif_focal" /
           ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    truth_ = groundtruth::loadGroundTruth("corridor_d");
    // A 5.0 mm lens on a sensor of 182.8 px/mm: the truth's 914.01 px to 1e-5.
    test::ExifFields f;
    f.focalLength = {500, 100};
    pxPerMm_ = truth_.focalPx / 5.0;
    f.focalPlaneXResolution = f.focalPlaneYResolution = std::pair<unsigned, unsigned>{unsigned(pxPerMm_ * 1000 + 0.5), 100};
    f.focalPlaneResolutionUnit = 3;  // cm
    exifFocalPx_ = 5.0 * double(unsigned(pxPerMm_ * 1000 + 0.5)) / 1000;
    jpeg_ = dir_ / "corridor_d.jpg";
    test::writeBytes(jpeg_, test::jpegWithApp1(cv::imread(truth_.image.string()), test::exifBlock(f)));
  }
  // `photowalk ARGS`, its stdout parsed when it exits 0.
  nlohmann::json photowalk(const std::string& args, int expectExit = 0) {
    const test::CommandRun run = test::runCommand((fs::path(PW_BINARY_DIR) / "photowalk").string() + " " + args);
    EXPECT_EQ(run.exitCode, expectExit) << run.output;
    if (run.exitCode != 0) return {{"output", run.output}};
    const size_t brace = run.output.find('{');
    return brace == std::string::npos ? nlohmann::json() : nlohmann::json::parse(run.output.substr(brace), nullptr, false);
  }
  void expectWithinHalfAPercent(const nlohmann::json& m, const std::string& what) {
    ASSERT_TRUE(m.contains("width_m")) << what << ": " << m.dump();
    const double w = 100 * (m["width_m"].get<double>() / truth_.widthM - 1);
    const double h = 100 * (m["height_m"].get<double>() / truth_.heightM - 1);
    const double l = 100 * (m["length_m"].get<double>() / truth_.lengthM - 1);
    std::printf("[exif] %-28s focal %.2f px (%s): %+.3f %+.3f %+.3f %%\n", what.c_str(), m["camera"]["focal_px"].get<double>(),
                m["camera"]["focal_source"].get<std::string>().c_str(), w, h, l);
    EXPECT_LT(std::max({std::abs(w), std::abs(h), std::abs(l)}), 0.5) << what;
  }
  fs::path dir_, jpeg_;
  groundtruth::GroundTruth truth_;
  double pxPerMm_ = 0, exifFocalPx_ = 0;
};

TEST_F(ExifFocalLength, MeasureTakesItWhenTheShotGivesNone) {
  nlohmann::json shot = {{"image", jpeg_.filename().string()}, {"camera_height_m", truth_.cameraHeightM}};
  for (int k = 0; k < kCornerCount; ++k) shot["corners_px"][cornerName(k)] = {truth_.cornersPx[k].x, truth_.cornersPx[k].y};
  std::ofstream(dir_ / "no_focal.json") << shot.dump();
  const nlohmann::json m = photowalk("measure " + (dir_ / "no_focal.json").string());
  ASSERT_TRUE(m.contains("camera")) << m.dump();
  EXPECT_NEAR(m["camera"]["focal_px"].get<double>(), exifFocalPx_, 1e-6);
  EXPECT_EQ(m["camera"]["focal_source"].get<std::string>().rfind("EXIF FocalLength 5.00 mm with FocalPlaneXResolution", 0), 0u)
      << m["camera"]["focal_source"];
  expectWithinHalfAPercent(m, "measure, exact corners");
  // The command line's focal length comes first.
  const nlohmann::json given = photowalk("measure " + (dir_ / "no_focal.json").string() + " --focal-px 900");
  EXPECT_EQ(given["camera"]["focal_px"], 900.0);
  EXPECT_EQ(given["camera"]["focal_source"], "given");
  // A PNG has no EXIF: the shot is refused, saying what is missing.
  shot["image"] = truth_.image.string();
  std::ofstream(dir_ / "png_no_focal.json") << shot.dump();
  const nlohmann::json refused = photowalk("measure " + (dir_ / "png_no_focal.json").string(), 1);
  const std::string output = refused["output"];
  EXPECT_NE(output.find("no EXIF focal length"), std::string::npos) << output;
  EXPECT_EQ(output.find('\n'), output.size() - 1) << output;
}

TEST_F(ExifFocalLength, DetectThenMeasureWithNoFocalLengthGiven) {
  const fs::path shot = dir_ / "detected.json";
  const test::CommandRun detect = test::runCommand((fs::path(PW_BINARY_DIR) / "photowalk").string() + " detect " +
                                                   jpeg_.string() + " --near-at-marked --camera-height " +
                                                   std::to_string(truth_.cameraHeightM) + " -o " + shot.string());
  ASSERT_EQ(detect.exitCode, 0) << detect.output;
  expectWithinHalfAPercent(photowalk("measure " + shot.string()), "detect then measure");
}

}  // namespace
}  // namespace pw::metrology::detect
