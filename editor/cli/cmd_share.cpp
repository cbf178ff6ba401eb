// photowalk share: a model, a shot or a building as one web page anyone can open.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "base/atomic_file.h"
#include "base/staging.h"
#include "editor/cli/command.h"
#include "editor/edit/building.h"
#include "editor/edit/file_browser.h"
#include "editor/edit/model_export.h"
#include "engine/io/model_io.h"
#include "engine/web/web_page.h"
#include "modeling/layout.h"
#include "modeling/pipeline.h"

namespace pw::editor {
namespace {
namespace fs = std::filesystem;

constexpr const char* kUsage =
    "usage: photowalk share MODEL|SHOT.json|LAYOUT.json -o OUT.html [--max-texture PX] [--quality Q]\n\n"
    "Writes one self-contained web page: the model (binary glTF, textures as JPEG), the\n"
    "viewer (three.js) and what photowalk knows beyond glTF (each viewpoint's exact lens,\n"
    "the avatar, the tour, the dimensions), all inside OUT.html: it opens by double-click\n"
    "in a web browser, from file:// or any static web server, with no network.\n"
    "A shot or a layout is built first, as `photowalk build` does.\n\n"
    "In the page: click the view to look with the mouse (Esc frees it), W A S D or the\n"
    "arrows to walk, Shift to run, PageUp/PageDown or the list for the viewpoints, T or\n"
    "the button for the tour; on a phone, drag to look and the thumb pad to walk.\n\n"
    "  -o, --output OUT.html  the page (written atomically)\n"
    "  --max-texture PX       a texture's longer side at most PX (default 2048; 256-8192)\n"
    "  --quality Q            the textures' JPEG quality (default 85; 10-100)\n";

struct Shared {
  engine::Scene scene;
  std::vector<modeling::CorridorModel> corridors;  // none for a model read from a file
  std::vector<NamedInput> inputs;
};

// A shot or layout built as `build` builds it, or a model read.
Result<Shared> sceneToShare(const std::string& input) {
  Shared out;
  if (!edit::matchesEndings(fs::path(input).filename().string(), {".json"})) {
    std::vector<std::string> warnings;
    auto scene = engine::loadModel(input, &warnings);
    if (!scene) return scene.error();
    for (const std::string& w : warnings) printWarning(w);
    out.scene = std::move(*scene);
    if (input != engine::kSampleSceneName) out.inputs.push_back({"the model", input});
    return out;
  }
  modeling::Layout layout;
  if (edit::isLayoutFile(input)) {
    auto read = modeling::readLayoutFile(input);
    if (!read) return read.error();
    layout = std::move(*read);
    out.inputs.push_back({"the layout", input});
  } else {
    layout = modeling::chainLayout({fs::path(input)});
  }
  for (const modeling::LayoutEntry& entry : layout.corridors) out.inputs.push_back({"a shot", entry.shot.string()});
  auto model = modeling::buildModel(layout, modeling::ModelOptions{});
  if (!model) return model.error();
  out.corridors = std::move(model->corridors);
  out.scene = std::move(model->scene);
  return out;
}

int runShare(Args& args) {
  const auto output = args.value("--output", "-o");
  const auto maxText = args.value("--max-texture");
  const auto qualityText = args.value("--quality");
  const std::vector<std::string> positionals = args.positionals();
  if (auto finished = args.finish(); !finished) return fail(finished.message());
  if (positionals.size() != 1) return fail("share takes one model, shot or layout; see photowalk share --help");
  if (!output) return fail("share needs -o OUT.html");
  if (!edit::matchesEndings(fs::path(*output).filename().string(), {".html", ".htm"})) return fail(*output + ": the page is HTML: name it .html");
  int maxTexturePx = engine::WebPageOptions{}.maxTexturePx, jpegQuality = engine::WebPageOptions{}.jpegQuality;
  if (maxText) {
    auto v = parseNumber(*maxText, "--max-texture");
    if (!v) return fail(v.message());
    if (*v < 256 || *v > 8192) return fail("--max-texture must be between 256 and 8192");
    maxTexturePx = static_cast<int>(*v);
  }
  if (qualityText) {
    auto v = parseNumber(*qualityText, "--quality");
    if (!v) return fail(v.message());
    if (*v < 10 || *v > 100) return fail("--quality must be between 10 and 100");
    jpegQuality = static_cast<int>(*v);
  }
  removeLeftoversOf(*output);

  auto shared = sceneToShare(positionals[0]);
  if (!shared) return fail(shared.message());
  if (auto distinct = checkNotAnInput(*output, "-o", shared->inputs); !distinct) return fail(distinct.message());
  engine::WebPageOptions options = edit::webPageOptionsFor(shared->scene, shared->corridors);
  options.maxTexturePx = maxTexturePx;
  options.jpegQuality = jpegQuality;
  engine::WebPageReport report;
  auto html = engine::webPageHtml(shared->scene, options, &report);
  if (!html) return fail(*output + ": " + html.message());
  if (Status written = writeFileAtomic(*output, *html); !written) return fail(written.message());
  for (const std::string& line : options.dimensions) std::printf("%s\n", line.c_str());
  std::printf("wrote %s: %.1f MB (the model %.1f MB: %zu shapes, %zu viewpoints; textures JPEG q%d, at most %d px%s)\n",
              output->c_str(), report.pageBytes / 1e6, report.modelBytes / 1e6, shared->scene.shapes.size(),
              shared->scene.viewpoints.size(), options.jpegQuality, options.maxTexturePx,
              report.texturesScaled ? (", " + std::to_string(report.texturesScaled) + " made smaller").c_str() : "");
  return kExitOk;
}

}  // namespace

PW_COMMAND(share, "share", "a model, shot or building as one web page anyone can open (no server, no network)", kUsage,
           runShare);

}  // namespace pw::editor
