#include "engine/vrml/vrml_appearance.h"

#include <algorithm>
#include <cmath>

#include "base/input_file.h"
#include "engine/vrml/vrml_fields.h"

namespace pw::engine::vrml {

namespace fs = std::filesystem;

namespace {

float unit(double v) { return static_cast<float>(std::clamp(v, 0.0, 1.0)); }
glm::vec3 unitColor(const glm::dvec3& c) { return {unit(c.x), unit(c.y), unit(c.z)}; }

int hexValue(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// "%20" and friends, as urls in files written on the web often carry them.
std::string percentDecode(const std::string& s) {
  std::string out;
  for (size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '%' && i + 2 < s.size() && hexValue(s[i + 1]) >= 0 && hexValue(s[i + 2]) >= 0) {
      out += static_cast<char>(hexValue(s[i + 1]) * 16 + hexValue(s[i + 2]));
      i += 2;
    } else {
      out += s[i];
    }
  }
  return out;
}

// PixelTexture's SFImage (5.5): pixels from the bottom-left, 1 to 4 components.
std::shared_ptr<const Image> imageFromPixels(const std::vector<int32_t>& ints) {
  if (ints.size() < 3) return nullptr;
  const int w = ints[0], h = ints[1], components = ints[2];
  if (w <= 0 || h <= 0 || components < 1 || components > 4) return nullptr;
  if (ints.size() < 3 + static_cast<size_t>(w) * h) return nullptr;
  auto image = std::make_shared<Image>(makeImage(w, h));
  image->grey = components <= 2;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const uint32_t p = static_cast<uint32_t>(ints[3 + static_cast<size_t>(y) * w + x]);
      uint8_t* out = image->pixel(x, h - 1 - y);
      switch (components) {
        case 1: out[0] = out[1] = out[2] = p & 0xff; out[3] = 255; break;
        case 2: out[0] = out[1] = out[2] = (p >> 8) & 0xff; out[3] = p & 0xff; break;
        case 3: out[0] = (p >> 16) & 0xff; out[1] = (p >> 8) & 0xff; out[2] = p & 0xff; out[3] = 255; break;
        default: out[0] = (p >> 24) & 0xff; out[1] = (p >> 16) & 0xff; out[2] = (p >> 8) & 0xff; out[3] = p & 0xff;
      }
    }
  }
  return image;
}

}  // namespace

std::optional<fs::path> localPath(const std::string& url, const SourceFile* file, std::string& whyNot) {
  const fs::path dir = file ? file->dir : fs::path();
  std::string u = url;
  const size_t colon = u.find(':');
  const size_t slash = u.find('/');
  if (colon != std::string::npos && colon > 1 && (slash == std::string::npos || colon < slash)) {
    std::string scheme = u.substr(0, colon);
    std::transform(scheme.begin(), scheme.end(), scheme.begin(), [](unsigned char c) { return std::tolower(c); });
    if (scheme != "file") {
      whyNot = "'" + url + "' is not a local file (photowalk does not download)";
      return std::nullopt;
    }
    u = u.substr(colon + 1);
    if (u.rfind("//", 0) == 0) u = u.substr(2);  // file://host/path: empty host expected
  }
  if (u.empty()) {
    whyNot = "the url is empty";
    return std::nullopt;
  }
  fs::path p = fs::path(percentDecode(u));
  p = p.is_absolute() ? p : dir / p;
  std::vector<fs::path> folders = file ? file->folders : std::vector<fs::path>{};
  if (folders.empty()) folders.push_back(dir.empty() ? fs::path(".") : dir);
  if (!insideFolders(p, folders)) {
    whyNot = "'" + url + "' is outside the model's folder " + folders.front().string() +
             " (photowalk reads a model's files only from its own folder)";
    return std::nullopt;
  }
  return p;
}

Material materialFromNode(const Node& node) {
  Material m;
  m.ambientIntensity = unit(getDouble(node, "ambientIntensity"));
  m.diffuseColor = unitColor(getVec3(node, "diffuseColor"));
  m.emissiveColor = unitColor(getVec3(node, "emissiveColor"));
  m.shininess = unit(getDouble(node, "shininess"));
  m.specularColor = unitColor(getVec3(node, "specularColor"));
  m.transparency = unit(getDouble(node, "transparency"));
  return m;
}

glm::dmat3 textureTransformMatrix(const Node& node) {
  const glm::dvec2 c = getVec2(node, "center"), s = getVec2(node, "scale"), t = getVec2(node, "translation");
  const double r = getDouble(node, "rotation");
  auto translate = [](const glm::dvec2& v) {
    glm::dmat3 m(1.0);
    m[2] = glm::dvec3(v, 1.0);
    return m;
  };
  glm::dmat3 scale(1.0);
  scale[0][0] = s.x;
  scale[1][1] = s.y;
  glm::dmat3 rotate(1.0);
  rotate[0] = {std::cos(r), std::sin(r), 0.0};
  rotate[1] = {-std::sin(r), std::cos(r), 0.0};
  return translate(-c) * scale * rotate * translate(c) * translate(t);
}

std::shared_ptr<const Image> AppearanceBuilder::loadImageFile(const Node& node, std::string& usedUrl) {
  const std::vector<std::string>& urls = getStrings(node, "url");
  std::string reasons;
  for (const std::string& url : urls) {
    std::string whyNot;
    const auto path = localPath(url, node.file, whyNot);
    if (!path) {
      reasons += (reasons.empty() ? "" : "; ") + whyNot;
      continue;
    }
    std::error_code ec;
    fs::path key = fs::weakly_canonical(*path, ec);
    if (ec) key = *path;
    auto cached = images_.find(key.string());
    if (cached != images_.end()) {
      if (!cached->second) continue;
      usedUrl = url;
      return cached->second;
    }
    auto image = loadImage(*path);
    if (image) {
      auto shared = std::make_shared<const Image>(std::move(*image));
      images_[key.string()] = shared;
      usedUrl = url;
      return shared;
    }
    images_[key.string()] = nullptr;
    reasons += (reasons.empty() ? "" : "; ") + image.message();
  }
  if (diagnostics_) {
    diagnostics_->warn(node.where() + ": " + node.typeName() + " has no loadable image (" +
                       (urls.empty() ? std::string("no url") : reasons) + "); the shape is drawn untextured");
  }
  return nullptr;
}

Result<std::shared_ptr<const Texture>> AppearanceBuilder::texture(const Node& node) {
  auto cached = textures_.find(&node);
  if (cached != textures_.end()) return cached->second;
  std::shared_ptr<const Texture> result;
  const std::string& type = node.typeName();
  if (type == "ImageTexture" || type == "PixelTexture") {
    Texture t;
    if (type == "ImageTexture") {
      t.image = loadImageFile(node, t.url);
    } else {
      t.image = imageFromPixels(getInts(node, "image"));
      if (!t.image && diagnostics_) {
        diagnostics_->warn(node.where() + ": PixelTexture has an empty or incomplete image; the shape is drawn untextured");
      }
    }
    t.wrapS = getBool(node, "repeatS") ? TextureWrap::kRepeat : TextureWrap::kClamp;
    t.wrapT = getBool(node, "repeatT") ? TextureWrap::kRepeat : TextureWrap::kClamp;
    if (t.image) result = std::make_shared<const Texture>(std::move(t));
  } else if (diagnostics_) {
    diagnostics_->warn(node.where() + ": " + type +
                       (type == "MovieTexture" ? " is not supported" : " is not a texture node") +
                       "; the shape is drawn untextured");
  }
  textures_.emplace(&node, result);
  return result;
}

Result<ShapeLook> AppearanceBuilder::look(const NodePtr& field) {
  if (!field) return ShapeLook{};
  auto resolved = resolve_(field);
  if (!resolved) return resolved.error();
  const NodePtr node = *resolved;
  if (!node) return ShapeLook{};
  auto cached = looks_.find(node.get());
  if (cached != looks_.end()) return cached->second;
  ShapeLook look;
  if (node->typeName() != "Appearance") {
    if (diagnostics_) {
      diagnostics_->warn(node->where() + ": Shape.appearance wants an Appearance, not a " + node->typeName() +
                         "; ignored");
    }
    looks_.emplace(node.get(), look);
    return look;
  }
  Appearance appearance;
  auto material = resolve_(getNode(*node, "material"));
  if (!material) return material.error();
  if (*material) {
    if ((*material)->typeName() == "Material") {
      appearance.material = materialFromNode(**material);
    } else if (diagnostics_) {
      diagnostics_->warn((*material)->where() + ": Appearance.material wants a Material, not a " +
                         (*material)->typeName() + "; ignored");
    }
  }
  auto textureNode = resolve_(getNode(*node, "texture"));
  if (!textureNode) return textureNode.error();
  if (*textureNode) {
    auto tex = texture(**textureNode);
    if (!tex) return tex.error();
    appearance.texture = *tex;
  }
  if (appearance.texture) {
    auto transform = resolve_(getNode(*node, "textureTransform"));
    if (!transform) return transform.error();
    if (*transform && (*transform)->typeName() == "TextureTransform") {
      look.textureTransform = transform->get();
    } else if (*transform && diagnostics_) {
      diagnostics_->warn((*transform)->where() + ": Appearance.textureTransform wants a TextureTransform, not a " +
                         (*transform)->typeName() + "; ignored");
    }
  }
  look.appearance = std::make_shared<const Appearance>(std::move(appearance));
  looks_.emplace(node.get(), look);
  return look;
}

}  // namespace pw::engine::vrml
