#include "engine/web/web_page.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include <nlohmann/json.hpp>

#define STB_IMAGE_RESIZE_IMPLEMENTATION
#define STB_IMAGE_RESIZE_STATIC
#include <stb_image_resize.h>

#include "base/base64.h"
#include "engine/gltf/gltf_writer.h"
#include "engine/scene/camera.h"
#include "engine/web/viewer_bundle.h"

namespace pw::engine {
namespace {
using Json = nlohmann::json;

std::shared_ptr<const Image> scaledToAtMost(const Image& image, int maxPx) {
  const double s = static_cast<double>(maxPx) / std::max(image.width, image.height);
  auto out = std::make_shared<Image>();
  out->width = std::max(1, static_cast<int>(std::lround(image.width * s)));
  out->height = std::max(1, static_cast<int>(std::lround(image.height * s)));
  out->grey = image.grey;
  out->rgba.resize(static_cast<size_t>(out->width) * out->height * 4);
  stbir_resize_uint8_srgb(image.rgba.data(), image.width, image.height, 0, out->rgba.data(), out->width, out->height, 0, 4,
                          3, 0);
  return out;
}

// Text inside a <script> element: "</" would end it early (JSON allows "<\/").
std::string scriptSafe(std::string text) {
  for (size_t at = text.find("</"); at != std::string::npos; at = text.find("</", at + 3)) text.replace(at, 2, "<\\/");
  return text;
}

std::string htmlEscaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

// What the page knows beyond the glTF: the viewpoints as photowalk draws them (their
// exact lens), the avatar, the background, the tour, the dimensions.
Json metaOf(const Scene& scene, const WebPageOptions& options, const std::string& title) {
  Json meta;
  meta["title"] = title;
  meta["viewpoints"] = Json::array();
  // A scene without viewpoints is seen whole from +Z, as photowalk render sees it.
  const std::vector<Viewpoint> viewpoints = scene.viewpoints.empty() ? std::vector<Viewpoint>{defaultViewpoint(scene)} : scene.viewpoints;
  for (const Viewpoint& vp : viewpoints) {
    const glm::quat q = orientationFromAxisAngle(vp.orientation);
    Json v{{"description", vp.description},
           {"position", {vp.position.x, vp.position.y, vp.position.z}},
           {"orientation", {q.x, q.y, q.z, q.w}},
           {"fov", vp.fieldOfViewRad}};
    if (vp.intrinsics) {
      const Intrinsics& k = *vp.intrinsics;
      v["intrinsics"] = {{"fx", k.focalXPx}, {"fy", k.focalYPx}, {"cu", k.principalU}, {"cv", k.principalV},
                         {"width", k.imageWidth}, {"height", k.imageHeight}};
    }
    meta["viewpoints"].push_back(std::move(v));
  }
  const NavigationInfo& nav = scene.navigation;
  meta["navigation"] = {{"avatarRadius", nav.avatarRadiusM}, {"avatarHeight", nav.avatarHeightM},
                        {"stepHeight", nav.stepHeightM},    {"speed", nav.speedMps},
                        {"headlight", nav.headlight}};
  meta["background"] = {scene.backgroundColor.r, scene.backgroundColor.g, scene.backgroundColor.b};
  meta["near"] = 0.05;
  meta["far"] = 2000.0;
  meta["dimensions"] = options.dimensions;
  if (options.tourSamples.size() >= 2) {
    Json samples = Json::array();
    for (const auto& s : options.tourSamples) samples.push_back({s[0], s[1], s[2], s[3]});
    meta["tour"] = {{"stepS", options.tourStepS}, {"samples", std::move(samples)}};
  }
  return meta;
}

}  // namespace

bool hasWebViewer() { return !viewerBundle().empty(); }

Scene withTexturesAtMost(const Scene& scene, int maxPx, int* scaled) {
  Scene out = scene;
  std::unordered_map<const Image*, std::shared_ptr<const Image>> images;
  std::unordered_map<const Appearance*, std::shared_ptr<const Appearance>> appearances;
  int count = 0;
  for (Shape& shape : out.shapes) {
    if (!shape.appearance || !shape.appearance->texture || !shape.appearance->texture->image) continue;
    const Image& image = *shape.appearance->texture->image;
    if (std::max(image.width, image.height) <= maxPx || image.empty()) continue;
    auto done = appearances.find(shape.appearance.get());
    if (done == appearances.end()) {
      auto smaller = images.find(&image);
      if (smaller == images.end()) {
        smaller = images.emplace(&image, scaledToAtMost(image, maxPx)).first;
        ++count;
      }
      auto texture = std::make_shared<Texture>(*shape.appearance->texture);
      texture->image = smaller->second;
      texture->detail.reset();  // the page draws the composite (README: the web page)
      auto appearance = std::make_shared<Appearance>(*shape.appearance);
      appearance->texture = std::move(texture);
      done = appearances.emplace(shape.appearance.get(), std::move(appearance)).first;
    }
    shape.appearance = done->second;
  }
  if (scaled) *scaled = count;
  return out;
}

Result<std::string> webPageHtml(const Scene& scene, const WebPageOptions& options, WebPageReport* report) {
  if (!hasWebViewer()) {
    return makeError("this photowalk was built without the web page's viewer: run scripts/install-tools.sh, then build again");
  }
  int scaled = 0;
  const Scene fitted = withTexturesAtMost(scene, std::max(16, options.maxTexturePx), &scaled);
  auto glb = encodeGltf(fitted, GltfContainer::kGlb, std::clamp(options.jpegQuality, 1, 100));
  if (!glb) return glb.error();
  const std::string title = !options.title.empty() ? options.title : !scene.title.empty() ? scene.title : "photowalk";
  std::string html;
  const std::string_view bundle = viewerBundle();
  html.reserve(base64Size(glb->size()) + bundle.size() + 64 * 1024);
  html += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  html += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1, maximum-scale=1, user-scalable=no\">\n";
  html += "<meta name=\"generator\" content=\"photowalk share\">\n<title>" + htmlEscaped(title) + "</title>\n</head>\n<body>\n";
  html += "<script type=\"application/json\" id=\"pw-meta\">" +
          scriptSafe(metaOf(scene, options, title).dump(-1, ' ', false, Json::error_handler_t::replace)) + "</script>\n";
  html += "<script type=\"application/octet-stream\" id=\"pw-model\">";
  html += base64(*glb);
  html += "</script>\n<script>";
  html += bundle;
  html += "</script>\n</body>\n</html>\n";
  if (report) {
    report->pageBytes = html.size();
    report->modelBytes = glb->size();
    report->texturesScaled = scaled;
  }
  return html;
}

}  // namespace pw::engine
