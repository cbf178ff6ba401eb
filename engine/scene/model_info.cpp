#include "engine/scene/model_info.h"

#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

#include "engine/scene/texture_detail.h"
#include "engine/scene/texture_source.h"

namespace pw::engine {
namespace {

// The rest of `line` after "TAG ", or nothing when the line is not tagged so.
std::optional<std::string> afterTag(const std::string& line, const char* tag) {
  const std::string prefix = std::string(tag) + " ";
  if (line.compare(0, prefix.size(), prefix) != 0) return std::nullopt;
  return line.substr(prefix.size());
}

bool isPhotowalkLine(const std::string& line) {
  return afterTag(line, kTourTag) || afterTag(line, kCameraTag) || afterTag(line, kTextureSourceTag) ||
         afterTag(line, kTextureDetailTag);
}

// %.9g: a float's value exactly; %.17g: a double's.
std::string number(double value, int digits) {
  char text[40];
  std::snprintf(text, sizeof text, " %.*g", digits, value);
  return text;
}

}  // namespace

std::string encodeTourLine(const std::vector<glm::vec3>& waypoints) {
  std::string line = kTourTag;
  for (const glm::vec3& p : waypoints) {
    for (int i = 0; i < 3; ++i) line += number(p[i], 9);
  }
  return line;
}

std::optional<std::vector<glm::vec3>> decodeTourLine(const std::string& line) {
  const auto rest = afterTag(line, kTourTag);
  if (!rest) return std::nullopt;
  std::istringstream in(*rest);
  std::vector<double> numbers;
  double v = 0;
  while (in >> v) {
    if (!std::isfinite(v)) return std::nullopt;
    numbers.push_back(v);
  }
  // Every word a number, three per point, two points at least.
  if (!in.eof() || numbers.size() % 3 != 0 || numbers.size() < 6) return std::nullopt;
  std::vector<glm::vec3> points;
  for (size_t i = 0; i < numbers.size(); i += 3) points.emplace_back(numbers[i], numbers[i + 1], numbers[i + 2]);
  return points;
}

std::string encodeCameraLine(const Intrinsics& k, const std::string& description) {
  return std::string(kCameraTag) + number(k.focalXPx, 17) + number(k.focalYPx, 17) + number(k.principalU, 17) +
         number(k.principalV, 17) + " " + std::to_string(k.imageWidth) + " " + std::to_string(k.imageHeight) + " " +
         description;
}

std::optional<std::pair<std::string, Intrinsics>> decodeCameraLine(const std::string& line) {
  const auto rest = afterTag(line, kCameraTag);
  if (!rest) return std::nullopt;
  std::istringstream in(*rest);
  Intrinsics k;
  if (!(in >> k.focalXPx >> k.focalYPx >> k.principalU >> k.principalV >> k.imageWidth >> k.imageHeight)) {
    return std::nullopt;
  }
  for (double v : {k.focalXPx, k.focalYPx, k.principalU, k.principalV}) {
    if (!std::isfinite(v)) return std::nullopt;
  }
  if (!(k.focalXPx > 0 && k.focalYPx > 0) || k.imageWidth < 1 || k.imageHeight < 1) return std::nullopt;
  std::string description;
  std::getline(in >> std::ws, description);
  if (description.empty()) return std::nullopt;
  return std::make_pair(description, k);
}

std::vector<std::string> infoForFile(const Scene& scene, const std::function<std::string(const Texture&)>& urlOf) {
  // The user's lines and the texture sources (which come last), less stray lines of ours.
  std::vector<std::string> info;
  for (std::string& line : infoWithTextureSources(scene, urlOf)) {
    if (afterTag(line, kTextureSourceTag) || afterTag(line, kTextureDetailTag) || !isPhotowalkLine(line)) {
      info.push_back(std::move(line));
    }
  }
  std::vector<std::string> ours;
  if (scene.tour.size() >= 2) ours.push_back(encodeTourLine(scene.tour));
  for (const Viewpoint& v : scene.viewpoints) {
    // A viewpoint without a description cannot be named; it keeps its field of view.
    if (v.intrinsics && !v.description.empty()) ours.push_back(encodeCameraLine(*v.intrinsics, v.description));
  }
  auto sources = info.begin();
  while (sources != info.end() && !afterTag(*sources, kTextureSourceTag)) ++sources;
  info.insert(sources, ours.begin(), ours.end());
  return info;
}

void takeModelInfo(Scene& scene, const ImageLoader& loadDetail) {
  applyTextureSources(scene, loadDetail);  // takes its own lines out first
  std::map<std::string, std::vector<Intrinsics>> cameras;
  std::vector<std::string> kept;
  for (const std::string& line : scene.info) {
    if (!isPhotowalkLine(line)) {
      kept.push_back(line);
    } else if (auto tour = decodeTourLine(line)) {
      if (scene.tour.empty()) scene.tour = std::move(*tour);
    } else if (auto camera = decodeCameraLine(line)) {
      cameras[camera->first].push_back(camera->second);
    }
  }
  scene.info = std::move(kept);
  std::map<std::string, size_t> used;
  for (Viewpoint& v : scene.viewpoints) {
    auto found = cameras.find(v.description);
    if (found == cameras.end()) continue;
    size_t& n = used[v.description];
    if (n < found->second.size()) v.intrinsics = found->second[n++];
  }
}

}  // namespace pw::engine
