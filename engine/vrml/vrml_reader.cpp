#include "engine/vrml/vrml_reader.h"

#include <cstdio>
#include <unordered_map>

#include "base/atomic_file.h"
#include "engine/scene/model_info.h"
#include "engine/vrml/gzip.h"
#include "engine/vrml/vrml_parser.h"
#include "engine/vrml/vrml_scene_builder.h"

namespace pw::engine {

namespace fs = std::filesystem;

namespace {

std::shared_ptr<vrml::SourceFile> sourceFile(const fs::path& path, const fs::path& dir, std::string displayName) {
  auto file = std::make_shared<vrml::SourceFile>();
  file->path = path;
  file->dir = dir;
  file->displayName = std::move(displayName);
  return file;
}

Result<vrml::Document> parseBytes(std::string_view bytes, std::shared_ptr<vrml::SourceFile> file,
                                  Diagnostics* diagnostics) {
  if (isGzip(bytes)) {
    auto text = gunzip(bytes, file->displayName, kMaxVrmlBytes);
    if (!text) return text.error();
    return vrml::parseDocument(*text, std::move(file), diagnostics);
  }
  if (bytes.size() > kMaxVrmlBytes) {
    return makeError(file->displayName + ": larger than " + std::to_string(kMaxVrmlBytes >> 20) +
                     " MiB; photowalk refuses it");
  }
  return vrml::parseDocument(bytes, std::move(file), diagnostics);
}

// The file's bytes in one read into a buffer of its size (models are tens of MB;
// a stream copy would double the time to get them).
Result<std::string> readWholeFile(const fs::path& path) {
  std::error_code ec;
  const auto size = fs::file_size(path, ec);
  if (ec || !fs::is_regular_file(path, ec)) return readFile(path);  // its messages name the problem
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) return readFile(path);
  std::string bytes(static_cast<size_t>(size), '\0');
  const size_t got = std::fread(bytes.data(), 1, bytes.size(), file);
  const bool failed = std::ferror(file) != 0;
  std::fclose(file);
  if (failed) return makeError(path.string() + ": read failed");
  bytes.resize(got);
  return bytes;
}

// Loads files from disk for the main file, Inlines and EXTERNPROTOs, each once.
class FileLoader final : public vrml::DocumentLoader {
 public:
  explicit FileLoader(Diagnostics* diagnostics) : diagnostics_(diagnostics) {}

  Result<std::shared_ptr<vrml::Document>> load(const fs::path& path) override {
    std::error_code ec;
    fs::path canonical = fs::weakly_canonical(path, ec);
    const std::string key = ec ? path.string() : canonical.string();
    auto cached = cache_.find(key);
    if (cached != cache_.end()) return cached->second;
    if (fs::is_regular_file(path, ec) && fs::file_size(path, ec) > kMaxVrmlBytes) {
      return makeError(path.string() + ": larger than " + std::to_string(kMaxVrmlBytes >> 20) +
                       " MiB; photowalk refuses it");
    }
    auto bytes = readWholeFile(path);
    if (!bytes) return bytes.error();
    auto document = parseBytes(*bytes, sourceFile(path, path.parent_path(), path.string()), diagnostics_);
    if (!document) return document.error();
    auto shared = std::make_shared<vrml::Document>(std::move(*document));
    cache_.emplace(key, shared);
    return shared;
  }

 private:
  Diagnostics* diagnostics_;
  std::unordered_map<std::string, std::shared_ptr<vrml::Document>> cache_;
};

// Detail layers (texture_detail.h): files beside the model, as its textures are.
ImageLoader detailLoader(const fs::path& dir) {
  return [dir](const std::string& url) -> std::shared_ptr<const Image> {
    if (url.find("://") != std::string::npos) return nullptr;
    auto image = loadImage(dir / fs::path(url));
    return image ? std::make_shared<const Image>(std::move(*image)) : nullptr;
  };
}

}  // namespace

Result<Scene> readVrml(const fs::path& path, Diagnostics* diagnostics) {
  FileLoader loader(diagnostics);
  auto document = loader.load(path);
  if (!document) return document.error();
  auto scene = vrml::buildScene(*document, loader, diagnostics);
  if (scene) takeModelInfo(*scene, detailLoader(path.parent_path()));
  return scene;
}

Result<Scene> readVrmlString(std::string_view text, const fs::path& baseDir, Diagnostics* diagnostics,
                             std::string_view nameForMessages) {
  auto document = parseBytes(text, sourceFile({}, baseDir, std::string(nameForMessages)), diagnostics);
  if (!document) return document.error();
  FileLoader loader(diagnostics);
  auto scene = vrml::buildScene(std::make_shared<vrml::Document>(std::move(*document)), loader, diagnostics);
  if (scene) takeModelInfo(*scene, detailLoader(baseDir));
  return scene;
}

}  // namespace pw::engine
