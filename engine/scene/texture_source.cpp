#include "engine/scene/texture_source.h"

#include "engine/scene/texture_detail.h"

#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <unordered_map>

namespace pw::engine {
namespace {

bool hasTag(const std::string& line, const char* tag) {
  const size_t n = std::char_traits<char>::length(tag);
  return line.size() > n + 1 && line.compare(0, n, tag) == 0 && line[n] == ' ';
}

bool isTextureSourceLine(const std::string& line) { return hasTag(line, kTextureSourceTag); }
bool isTextureDetailLine(const std::string& line) { return hasTag(line, kTextureDetailTag); }

std::optional<std::pair<std::string, glm::mat3>> parseLine(const std::string& line) {
  std::istringstream in(line.substr(std::char_traits<char>::length(kTextureSourceTag)));
  glm::mat3 h;
  for (int c = 0; c < 3; ++c) {
    for (int r = 0; r < 3; ++r) {
      double v = 0;
      if (!(in >> v) || !std::isfinite(v)) return std::nullopt;
      h[c][r] = static_cast<float>(v);
    }
  }
  std::string url;
  std::getline(in >> std::ws, url);
  if (url.empty()) return std::nullopt;
  return std::make_pair(url, h);
}

}  // namespace

std::vector<std::string> infoWithTextureSources(const Scene& scene,
                                                const std::function<std::string(const Texture&)>& urlOf) {
  std::vector<std::string> info;
  for (const std::string& line : scene.info) {
    if (!isTextureSourceLine(line) && !isTextureDetailLine(line)) info.push_back(line);
  }
  std::set<std::string> written;
  for (const Shape& shape : scene.shapes) {
    const Texture* texture = shape.appearance ? shape.appearance->texture.get() : nullptr;
    if (!texture || !texture->sourceFromTexCoord) continue;
    const std::string url = urlOf(*texture);
    if (url.empty() || !written.insert(url).second) continue;
    std::string line = kTextureSourceTag;
    const glm::mat3& h = *texture->sourceFromTexCoord;
    for (int c = 0; c < 3; ++c) {
      for (int r = 0; r < 3; ++r) {
        char number[32];
        std::snprintf(number, sizeof number, " %.9g", static_cast<double>(h[c][r]));
        line += number;
      }
    }
    info.push_back(line + " " + url);
    if (hasDetail(*texture)) info.push_back(std::string(kTextureDetailTag) + " " + url);
  }
  return info;
}

void applyTextureSources(Scene& scene, const ImageLoader& loadDetail) {
  std::map<std::string, glm::mat3> sources;
  std::set<std::string> details;
  std::vector<std::string> kept;
  for (const std::string& line : scene.info) {
    if (isTextureDetailLine(line)) {
      details.insert(line.substr(std::char_traits<char>::length(kTextureDetailTag) + 1));
    } else if (!isTextureSourceLine(line)) {
      kept.push_back(line);
    } else if (auto parsed = parseLine(line)) {
      sources.insert(*parsed);
    }
  }
  scene.info = std::move(kept);
  if (sources.empty()) return;
  // Textures and appearances are shared between shapes: copy each once.
  std::unordered_map<const Texture*, std::shared_ptr<const Texture>> textures;
  std::unordered_map<const Appearance*, std::shared_ptr<const Appearance>> appearances;
  for (Shape& shape : scene.shapes) {
    if (!shape.appearance || !shape.appearance->texture) continue;
    auto done = appearances.find(shape.appearance.get());
    if (done == appearances.end()) {
      const std::shared_ptr<const Texture>& old = shape.appearance->texture;
      auto texture = textures.find(old.get());
      if (texture == textures.end()) {
        std::shared_ptr<const Texture> replacement = old;
        if (auto source = sources.find(old->url); source != sources.end()) {
          auto copy = std::make_shared<Texture>(*old);
          copy->sourceFromTexCoord = source->second;
          if (details.count(old->url) && loadDetail) {
            copy->detail = loadDetail(detailUrl(old->url));
            if (!hasDetail(*copy)) copy->detail.reset();
          }
          replacement = std::move(copy);
        }
        texture = textures.emplace(old.get(), std::move(replacement)).first;
      }
      std::shared_ptr<const Appearance> replacement = shape.appearance;
      if (texture->second != old) {
        auto appearance = std::make_shared<Appearance>(*shape.appearance);
        appearance->texture = texture->second;
        replacement = std::move(appearance);
      }
      done = appearances.emplace(shape.appearance.get(), std::move(replacement)).first;
    }
    shape.appearance = done->second;
  }
}

glm::mat3 withFlippedT(const glm::mat3& sourceFromTexCoord) {
  // (s, t, 1) = flip * (s, v, 1) with t = 1 - v.
  const glm::mat3 flip(glm::vec3(1, 0, 0), glm::vec3(0, -1, 0), glm::vec3(0, 1, 1));
  return sourceFromTexCoord * flip;
}

}  // namespace pw::engine
