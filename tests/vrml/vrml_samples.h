// The VRML97 files of tests/data/vrml-samples (Castle Game Engine demo models, GPL-2+,
// with view3dscene's screenshots), sorted.
#pragma once

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <vector>

namespace pw::engine {

// The samples share a textures folder beside theirs ("../textures/x.png"): the folder a
// reader is told it may read besides a model's own (README: What photowalk reads).
inline std::vector<std::filesystem::path> samplesFolders() { return {PW_TEST_DATA_DIR "/vrml-samples"}; }

// Every .wrl / .wrl.gz under the samples folder whose content is VRML97 (plain text
// starting with "#VRML V2.0", or gzip data).
inline std::vector<std::filesystem::path> vrmlSamples() {
  namespace fs = std::filesystem;
  std::vector<fs::path> out;
  const fs::path root = PW_TEST_DATA_DIR "/vrml-samples";
  std::error_code ec;
  if (!fs::is_directory(root, ec)) return out;
  for (const auto& entry : fs::recursive_directory_iterator(root, ec)) {
    const std::string name = entry.path().filename().string();
    const bool wrl = name.size() > 4 && name.compare(name.size() - 4, 4, ".wrl") == 0;
    const bool gz = name.size() > 7 && name.compare(name.size() - 7, 7, ".wrl.gz") == 0;
    if (!entry.is_regular_file() || !(wrl || gz)) continue;
    std::ifstream in(entry.path(), std::ios::binary);
    char head[10] = {};
    in.read(head, sizeof head);
    const bool gzip = static_cast<unsigned char>(head[0]) == 0x1f && static_cast<unsigned char>(head[1]) == 0x8b;
    if (gzip || std::string(head, 10) == "#VRML V2.0") out.push_back(entry.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace pw::engine
