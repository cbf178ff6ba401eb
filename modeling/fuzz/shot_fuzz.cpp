// libFuzzer target for shot files: read, measured, written back and read again.
//
//   cmake --preset fuzz && cmake --build --preset fuzz --target shot_fuzz
//   build-fuzz/fuzz/shot_fuzz -dict=modeling/fuzz/shot.dict -max_len=4096 CORPUS_DIR modeling/fuzz/shot_corpus
//
// Any input gives a shot or a one-line error, never a crash, a hang, an exception or
// a library's message. A shot that was read is measured as `measure` does (its photo
// taken as 1280x720 when the file gives no size; every number of an answer must be
// finite), and written and read back as the same shot.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "metrology/measure.h"
#include "modeling/fuzz/fuzz_file.h"
#include "modeling/shot_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto path = pw::fuzz::writeInput("shot.json", data, size);
  for (bool allowNoScale : {false, true}) {
    nlohmann::json other;
    auto shot = pw::modeling::readShotFile(path, &other, allowNoScale);
    if (!shot) {
      pw::fuzz::checkError(shot.message());
      continue;
    }
    if (allowNoScale) break;  // what it adds was read once already
    pw::metrology::Shot measured = *shot;
    if (measured.imageWidth == 0) measured.imageWidth = 1280, measured.imageHeight = 720;
    if (measured.focalPx <= 0 && !measured.focalMm) measured.focalPx = 1000;
    auto m = pw::metrology::measureCorridor(measured);
    if (m) {
      for (double v : {m->size.widthM, m->size.heightM, m->size.lengthM, m->sigma.widthM, m->sigma.heightM,
                       m->sigma.lengthM, m->reprojectionRmsPx})
        if (!std::isfinite(v)) std::abort();
      auto json = pw::modeling::measurementJson(*m);
      if (!json) pw::fuzz::checkError(json.message());
    } else {
      pw::fuzz::checkError(m.message());
    }
    const auto copy = path.parent_path() / "copy.json";
    auto written = pw::modeling::writeShotFile(copy, *shot, other);
    if (!written) std::abort();  // a shot that was read is writable
    auto back = pw::modeling::readShotFile(copy, nullptr, false);
    if (!back) {
      std::fprintf(stderr, "written back, not read: %s\n", back.message().c_str());
      std::abort();
    }
    if (*back != *shot) {
      std::fprintf(stderr, "written back, read as another shot\n");
      std::abort();
    }
  }
  return 0;
}
