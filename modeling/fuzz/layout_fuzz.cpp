// libFuzzer target for layout files: read, planned, written back and read again.
//
//   cmake --preset fuzz && cmake --build --preset fuzz --target layout_fuzz
//   build-fuzz/fuzz/layout_fuzz -dict=modeling/fuzz/layout.dict -max_len=4096 CORPUS_DIR modeling/fuzz/layout_corpus
//
// Any input gives a layout or a one-line error, never a crash, a hang, an exception
// or a library's message. A layout that was read is planned as `build --layout` does
// (each corridor a 3 x 2.5 x 12 m box: the shots are not read) and written and read
// back with the same corridors.
#include <cmath>
#include <cstdint>
#include <cstdlib>

#include "modeling/fuzz/fuzz_file.h"
#include "modeling/layout.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto path = pw::fuzz::writeInput("layout.json", data, size);
  auto layout = pw::modeling::readLayoutFile(path);
  if (!layout) {
    pw::fuzz::checkError(layout.message());
    return 0;
  }
  const std::vector<pw::metrology::Dimensions> boxes(layout->corridors.size(), pw::metrology::Dimensions{3.0, 2.5, 12.0});
  auto plan = pw::modeling::planBuilding(*layout, boxes);
  if (plan) {
    for (const glm::dmat4& m : plan->worldFromCorridor)
      for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
          if (!std::isfinite(m[c][r])) std::abort();
    for (const auto& overlap : plan->overlaps) pw::fuzz::checkError(pw::modeling::overlapText(*layout, overlap));
  } else {
    pw::fuzz::checkError(plan.message());
  }
  const auto copy = path.parent_path() / "copy.json";
  if (!pw::modeling::writeLayoutFile(copy, *layout)) std::abort();
  auto back = pw::modeling::readLayoutFile(copy);
  if (!back || back->corridors.size() != layout->corridors.size()) std::abort();
  for (size_t i = 0; i < back->corridors.size(); ++i) {
    const auto &a = layout->corridors[i], &b = back->corridors[i];
    if (a.name != b.name || a.attach.has_value() != b.attach.has_value()) std::abort();
  }
  return 0;
}
