// Materials, textures, samplers and embedded PNG images.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <system_error>
#include <thread>

#include "engine/gltf/gltf_document.h"
#include "engine/gltf/gltf_mapping.h"
#include "engine/scene/image.h"
#include "engine/scene/texture_detail.h"

namespace pw::engine::gltf {

namespace {

Json vec4Json(const glm::vec4& v) {
  return Json::array({shortestDouble(v.x), shortestDouble(v.y), shortestDouble(v.z), shortestDouble(v.w)});
}

float unitInterval(float x) { return std::isnan(x) ? 0.0f : std::clamp(x, 0.0f, 1.0f); }

bool hasTexture(const Appearance* appearance, const Mesh& mesh) {
  // VRML97 6.24/6.36: lines and points are never texture-mapped.
  return appearance && appearance->texture && appearance->texture->image && !appearance->texture->image->empty() &&
         mesh.topology == Topology::kTriangles;
}

}  // namespace

int DocumentBuilder::addExtensionUsed(const char* name) {
  Json& used = doc_["extensionsUsed"];
  for (size_t i = 0; i < used.size(); ++i) {
    if (used[i] == name) return static_cast<int>(i);
  }
  used.push_back(name);
  return static_cast<int>(used.size()) - 1;
}

bool DocumentBuilder::imageHasAlpha(const Image& image) {
  if (auto found = imageAlpha_.find(&image); found != imageAlpha_.end()) return found->second;
  bool alpha = false;
  for (size_t i = 3; i < image.rgba.size() && !alpha; i += 4) alpha = image.rgba[i] != 255;
  imageAlpha_.emplace(&image, alpha);
  return alpha;
}

int DocumentBuilder::imageFor(const std::shared_ptr<const Image>& image) {
  if (auto found = images_.find(image.get()); found != images_.end()) return found->second;
  doc_["images"].push_back(Json{{"mimeType", "image/png"}});  // bufferView added by embedImages()
  const int index = static_cast<int>(doc_["images"].size()) - 1;
  images_.emplace(image.get(), index);
  pendingImages_.push_back({image, index});
  return index;
}

int DocumentBuilder::textureFor(const Texture& texture) {
  const int image = imageFor(texture.image);
  if (!texture.url.empty() && !doc_["images"][image].contains("name")) {
    doc_["images"][image]["name"] = std::filesystem::path(texture.url).filename().string();
  }
  // A detail layer (texture_detail.h): an image no texture uses, named as the info line
  // that names its texture says (other viewers show the composite, `image`).
  if (texture.sourceFromTexCoord && hasDetail(texture) && !texture.url.empty() && !images_.count(texture.detail.get())) {
    const int detail = imageFor(texture.detail);
    doc_["images"][detail]["name"] = detailUrl(std::filesystem::path(texture.url).filename().string());
  }
  const auto wraps = std::make_pair(wrapCode(texture.wrapS), wrapCode(texture.wrapT));
  auto sampler = samplers_.find(wraps);
  if (sampler == samplers_.end()) {
    // Trilinear filtering: photo textures are minified strongly down a corridor.
    doc_["samplers"].push_back(Json{{"magFilter", kFilterLinear},
                                    {"minFilter", kFilterLinearMipmapLinear},
                                    {"wrapS", wraps.first},
                                    {"wrapT", wraps.second}});
    sampler = samplers_.emplace(wraps, static_cast<int>(doc_["samplers"].size()) - 1).first;
  }
  const auto key = std::make_pair(image, sampler->second);
  if (auto found = textures_.find(key); found != textures_.end()) return found->second;
  doc_["textures"].push_back(Json{{"sampler", sampler->second}, {"source", image}});
  const int index = static_cast<int>(doc_["textures"].size()) - 1;
  textures_.emplace(key, index);
  return index;
}

int DocumentBuilder::materialFor(const Appearance* appearance, const Mesh& mesh, const MeshData& data) {
  const Material* vrml = appearance && appearance->material ? &*appearance->material : nullptr;
  const bool textured = hasTexture(appearance, mesh);
  const bool vertexColors = data.color >= 0 && !textured;
  // VRML97 4.14.4: only faces are lit, and only with a Material; 6.24: lines and
  // points with a Material are drawn unlit in its emissiveColor.
  const bool lit = vrml && mesh.topology == Topology::kTriangles;
  const float opacity = vrml ? 1.0f - unitInterval(vrml->transparency) : 1.0f;

  // Colour textures and vertex colours replace the diffuse colour (VRML97 4.14.3, table
  // 4.5); a grey (intensity) texture modulates it, as glTF's texture does its factor.
  const bool intensity = textured && appearance->texture->image->grey;
  glm::vec3 base(1.0f);
  if (vrml && (!textured || intensity) && !vertexColors) base = linearFromSrgb(lit ? vrml->diffuseColor : vrml->emissiveColor);

  Json pbr = {{"baseColorFactor", vec4Json(glm::vec4(base, opacity))}, {"metallicFactor", 0.0}};
  if (textured) pbr["baseColorTexture"] = Json{{"index", textureFor(*appearance->texture)}};
  Json material = Json::object();
  if (lit) {
    pbr["roughnessFactor"] = shortestDouble(roughnessFromShininess(vrml->shininess));
    const glm::vec3 emissive = linearFromSrgb(vrml->emissiveColor);
    if (emissive != glm::vec3(0.0f)) {
      material["emissiveFactor"] = Json::array({shortestDouble(emissive.x), shortestDouble(emissive.y),
                                                shortestDouble(emissive.z)});
    }
  } else {
    // KHR_materials_unlit: roughness 1 makes the fallback for viewers without the
    // extension as flat as the PBR model allows.
    pbr["roughnessFactor"] = 1.0;
    material["extensions"] = Json{{"KHR_materials_unlit", Json::object()}};
    addExtensionUsed("KHR_materials_unlit");
  }
  material["pbrMetallicRoughness"] = std::move(pbr);
  const bool translucent = opacity < 1.0f || (textured && imageHasAlpha(*appearance->texture->image)) ||
                           (vertexColors && data.translucentColors);
  if (translucent) material["alphaMode"] = "BLEND";
  if (!mesh.solid && mesh.topology == Topology::kTriangles) material["doubleSided"] = true;

  // Equal content, one material: appearances built separately for each wall of a
  // corridor but alike come out as one glTF material.
  std::string key = material.dump();
  if (auto found = materials_.find(key); found != materials_.end()) return found->second;
  doc_["materials"].push_back(std::move(material));
  const int index = static_cast<int>(doc_["materials"].size()) - 1;
  materials_.emplace(std::move(key), index);
  return index;
}

Status DocumentBuilder::embedImages() {
  std::vector<Result<std::vector<uint8_t>>> encoded(pendingImages_.size(), makeError("not encoded"));
  // JPEG where asked for and the image is opaque (JPEG has no alpha).
  std::vector<char> jpeg(pendingImages_.size(), 0);
  for (size_t i = 0; i < pendingImages_.size(); ++i) {
    jpeg[i] = jpegQuality_ > 0 && !imageHasAlpha(*pendingImages_[i].image);
    if (jpeg[i]) doc_["images"][pendingImages_[i].index]["mimeType"] = "image/jpeg";
  }
  // PNG encoding dominates export time (bench/gltf_bench.cpp); images are independent,
  // so they are encoded on as many threads as there are cores.
  std::atomic<size_t> next{0};
  auto work = [&] {
    for (size_t i = next++; i < pendingImages_.size(); i = next++) {
      const Image& image = *pendingImages_[i].image;
      encoded[i] = jpeg[i] ? encodeJpeg(image, jpegQuality_) : encodePng(image);
    }
  };
  const size_t threadCount =
      std::min<size_t>(pendingImages_.size(), std::max(1u, std::thread::hardware_concurrency())) ;
  std::vector<std::thread> helpers;
  for (size_t t = 1; t < threadCount; ++t) {
    try {
      helpers.emplace_back(work);
    } catch (const std::system_error&) {
      break;  // no more threads to be had: the calling thread does the rest
    }
  }
  work();
  for (std::thread& helper : helpers) helper.join();

  for (size_t i = 0; i < pendingImages_.size(); ++i) {
    if (!encoded[i]) return makeError("texture image " + std::to_string(i) + ": " + encoded[i].message());
    const std::vector<uint8_t>& png = *encoded[i];
    doc_["images"][pendingImages_[i].index]["bufferView"] = addView(png.data(), png.size(), std::nullopt);
  }
  pendingImages_.clear();
  return {};
}

}  // namespace pw::engine::gltf
