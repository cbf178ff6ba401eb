#include "engine/vrml/vrml_reader.h"

#include <cstdio>
#include <unordered_map>

#include "base/atomic_file.h"
#include "base/input_file.h"
#include "engine/scene/model_info.h"
#include "engine/vrml/gzip.h"
#include "engine/vrml/vrml_parser.h"
#include "engine/vrml/vrml_scene_builder.h"

namespace pw::engine {

namespace fs = std::filesystem;

namespace {

std::shared_ptr<vrml::SourceFile> sourceFile(const fs::path& path, const fs::path& dir, std::string displayName,
                                             std::vector<fs::path> folders) {
  auto file = std::make_shared<vrml::SourceFile>();
  file->path = path;
  file->dir = dir;
  file->displayName = std::move(displayName);
  file->folders = std::move(folders);
  return file;
}

// The folders a model's urls may lead into: its own and those a person named.
std::vector<fs::path> modelFolders(const fs::path& dir, const std::vector<fs::path>& extraFolders) {
  std::vector<fs::path> folders{dir.empty() ? fs::path(".") : dir};
  folders.insert(folders.end(), extraFolders.begin(), extraFolders.end());
  return folders;
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

// Loads files from disk for the main file, Inlines and EXTERNPROTOs, each once.
class FileLoader final : public vrml::DocumentLoader {
 public:
  FileLoader(Diagnostics* diagnostics, std::vector<fs::path> folders)
      : diagnostics_(diagnostics), folders_(std::move(folders)) {}

  Result<std::shared_ptr<vrml::Document>> load(const fs::path& path) override {
    std::error_code ec;
    fs::path canonical = fs::weakly_canonical(path, ec);
    const std::string key = ec ? path.string() : canonical.string();
    auto cached = cache_.find(key);
    if (cached != cache_.end()) return cached->second;
    auto bytes = readInputFile(path, kModelInput);
    if (!bytes) return bytes.error();
    auto document = parseBytes(*bytes, sourceFile(path, path.parent_path(), path.string(), folders_), diagnostics_);
    if (!document) return document.error();
    auto shared = std::make_shared<vrml::Document>(std::move(*document));
    cache_.emplace(key, shared);
    return shared;
  }

 private:
  Diagnostics* diagnostics_;
  std::vector<fs::path> folders_;  // every file it loads keeps the opened model's
  std::unordered_map<std::string, std::shared_ptr<vrml::Document>> cache_;
};

// Detail layers (texture_detail.h): files beside the model, as its textures are.
ImageLoader detailLoader(const fs::path& dir) {
  return [dir](const std::string& url) -> std::shared_ptr<const Image> {
    if (url.find("://") != std::string::npos) return nullptr;
    if (!insideFolders(dir / fs::path(url), {dir.empty() ? fs::path(".") : dir})) return nullptr;
    auto image = loadImage(dir / fs::path(url));
    return image ? std::make_shared<const Image>(std::move(*image)) : nullptr;
  };
}

}  // namespace

Result<Scene> readVrml(const fs::path& path, Diagnostics* diagnostics, const std::vector<fs::path>& extraFolders) {
  FileLoader loader(diagnostics, modelFolders(path.parent_path(), extraFolders));
  auto document = loader.load(path);
  if (!document) return document.error();
  auto scene = vrml::buildScene(*document, loader, diagnostics);
  if (scene) takeModelInfo(*scene, detailLoader(path.parent_path()));
  return scene;
}

Result<Scene> readVrmlString(std::string_view text, const fs::path& baseDir, Diagnostics* diagnostics,
                             std::string_view nameForMessages, const std::vector<fs::path>& extraFolders) {
  const std::vector<fs::path> folders = modelFolders(baseDir, extraFolders);
  auto document = parseBytes(text, sourceFile({}, baseDir, std::string(nameForMessages), folders), diagnostics);
  if (!document) return document.error();
  FileLoader loader(diagnostics, folders);
  auto scene = vrml::buildScene(std::make_shared<vrml::Document>(std::move(*document)), loader, diagnostics);
  if (scene) takeModelInfo(*scene, detailLoader(baseDir));
  return scene;
}

}  // namespace pw::engine
