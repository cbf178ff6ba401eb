// The reader's material layer: glTF materials, textures and images become VRML-style
// Appearances (mappings: gltf_mapping.h).
#include <algorithm>
#include <atomic>
#include <system_error>
#include <thread>

#include "engine/gltf/gltf_mapping.h"
#include "engine/gltf/gltf_read_scene.h"
#include "engine/scene/image.h"

namespace pw::engine::gltf {

std::map<size_t, DecodedImage> decodeUsedImages(const Source& source) {
  std::set<size_t> used;
  const Json* materials = member(source.doc, "materials");
  const Json* textures = member(source.doc, "textures");
  if (materials && materials->is_array() && textures && textures->is_array()) {
    for (const Json& material : *materials) {
      const Json* pbr = member(material, "pbrMetallicRoughness");
      const Json* info = pbr ? member(*pbr, "baseColorTexture") : nullptr;
      const Json* index = info ? member(*info, "index") : nullptr;
      if (!index || !index->is_number_unsigned() || index->get<size_t>() >= textures->size()) continue;
      const Json* image = member((*textures)[index->get<size_t>()], "source");
      if (image && image->is_number_unsigned()) used.insert(image->get<size_t>());
    }
  }
  return decodeImages(source, used);
}

std::map<size_t, DecodedImage> decodeImages(const Source& source, const std::set<size_t>& used) {
  struct Job {
    size_t index;
    std::string where;
    std::vector<uint8_t> owned;
    std::span<const uint8_t> bytes;
    Result<Image> result = makeError("not decoded");
  };
  std::vector<Job> jobs;
  std::map<size_t, DecodedImage> out;
  for (size_t index : used) {
    Job job{index, indexed("images", index), {}, {}};
    DecodedImage& entry = out[index];
    auto imageJson = element(source, "images", Json(index), "a texture");
    if (!imageJson) {
      source.warn(imageJson.message() + "; drawn without it");
      continue;
    }
    if (const Json* uri = member(**imageJson, "uri"); uri && uri->is_string()) {
      auto bytes = resolveUri(source, uri->get<std::string>(), job.where);
      if (!bytes) {
        source.warn(bytes.message() + "; drawn without the texture");
        continue;
      }
      job.owned = std::move(*bytes);
      job.bytes = job.owned;
      if (uri->get<std::string>().rfind("data:", 0) != 0) entry.url = uri->get<std::string>();
    } else if (const Json* view = member(**imageJson, "bufferView")) {
      auto bytes = bufferViewBytes(source, *view, job.where);
      if (!bytes) {
        source.warn(bytes.message() + "; drawn without the texture");
        continue;
      }
      job.bytes = *bytes;
    } else {
      source.warn(job.where + ": has neither uri nor bufferView; drawn without it");
      continue;
    }
    if (const Json* n = member(**imageJson, "name"); entry.url.empty() && n && n->is_string()) entry.url = n->get<std::string>();
    jobs.push_back(std::move(job));
  }
  std::atomic<size_t> next{0};
  auto work = [&] {
    for (size_t i = next++; i < jobs.size(); i = next++) {
      jobs[i].result = decodeImage(jobs[i].bytes.data(), jobs[i].bytes.size(), source.name + ": " + jobs[i].where);
    }
  };
  std::vector<std::thread> helpers;
  const size_t threads = std::min<size_t>(jobs.size(), std::max(1u, std::thread::hardware_concurrency()));
  for (size_t t = 1; t < threads; ++t) {
    try {
      helpers.emplace_back(work);
    } catch (const std::system_error&) {
      break;  // the calling thread does the rest
    }
  }
  work();
  for (std::thread& helper : helpers) helper.join();
  for (Job& job : jobs) {
    if (job.result) {
      out[job.index].image = std::make_shared<const Image>(std::move(*job.result));
    } else {
      source.warn(job.result.message() + "; drawn without it");
    }
  }
  return out;
}

Result<SceneBuilder::Look> SceneBuilder::lookFor(const Json* materialIndex, const std::string& where) {
  if (materialIndex && !materialIndex->is_number_unsigned()) {
    return source_.error(where + ": material " + materialIndex->dump() + " is not an index");
  }
  const int key = materialIndex ? static_cast<int>(std::min<size_t>(materialIndex->get<size_t>(), INT32_MAX)) : -1;
  if (auto found = looks_.find(key); found != looks_.end()) return found->second;
  Look look;
  auto appearance = std::make_shared<Appearance>();
  if (!materialIndex) {
    // The default material (glTF 2.0, 3.9.6) is lit, white.
    appearance->material = Material{};
    appearance->material->diffuseColor = glm::vec3(1.0f);
    look.appearance = appearance;
    looks_[key] = look;
    return look;
  }
  auto materialJson = element(source_, "materials", *materialIndex, where);
  if (!materialJson) return materialJson.error();
  const Json& material = **materialJson;
  const std::string at = indexed("materials", static_cast<size_t>(key));
  const Json* pbr = member(material, "pbrMetallicRoughness");
  static const Json kEmpty = Json::object();
  if (!pbr) pbr = &kEmpty;
  auto base = numbersOr(source_, *pbr, "baseColorFactor", 4, {1, 1, 1, 1}, at);
  auto metallic = numberOr(source_, *pbr, "metallicFactor", 1, at);
  auto roughness = numberOr(source_, *pbr, "roughnessFactor", 1, at);
  auto emissive = numbersOr(source_, material, "emissiveFactor", 3, {0, 0, 0}, at);
  if (!base) return base.error();
  if (!metallic) return metallic.error();
  if (!roughness) return roughness.error();
  if (!emissive) return emissive.error();
  std::string alphaMode = "OPAQUE";
  if (const Json* mode = member(material, "alphaMode"); mode && mode->is_string()) alphaMode = mode->get<std::string>();
  if (const Json* ds = member(material, "doubleSided"); ds && ds->is_boolean()) look.doubleSided = ds->get<bool>();
  const Json* ext = member(material, "extensions");
  look.unlit = ext && member(*ext, "KHR_materials_unlit");
  const glm::vec4 factor{static_cast<float>((*base)[0]), static_cast<float>((*base)[1]), static_cast<float>((*base)[2]),
                       static_cast<float>((*base)[3])};
  const float opacity = alphaMode == "OPAQUE" ? 1.0f : std::clamp(factor.w, 0.0f, 1.0f);
  if (const Json* textureInfo = member(*pbr, "baseColorTexture")) {
    appearance->texture = textureFor(*textureInfo, alphaMode == "OPAQUE", at);
    if (const Json* set = member(*textureInfo, "texCoord"); set && set->is_number_unsigned()) {
      look.texCoordSet = static_cast<int>(std::min<size_t>(set->get<size_t>(), 8));
    }
  }
  if (look.unlit) {
    look.colorFactor = glm::vec4(glm::vec3(factor), opacity);
  } else {
    // Metals have no diffuse term and a specular highlight in their own colour
    // (glTF 2.0, Appendix B.3.5); VRML's Material is the dielectric case.
    const float m = std::clamp(float(*metallic), 0.0f, 1.0f);
    const glm::vec3 baseDisplay = srgbFromLinear(glm::vec3(factor));
    Material vrml;
    vrml.diffuseColor = baseDisplay * (1.0f - m);
    vrml.specularColor = glm::mix(glm::vec3(srgbFromLinear(0.04f)), baseDisplay, m);
    vrml.shininess = shininessFromRoughness(float(*roughness));
    vrml.emissiveColor = srgbFromLinear(vec3Of(*emissive));
    vrml.transparency = 1.0f - opacity;
    vrml.ambientIntensity = 0.0f;  // glTF has no ambient term
    // VRML: a colour texture replaces the diffuse colour; a grey one multiplies it, as
    // glTF's texture multiplies the factor.
    if (appearance->texture && !appearance->texture->image->grey) vrml.diffuseColor = glm::vec3(1.0f);
    appearance->material = vrml;
  }
  if (ext && member(*ext, "KHR_texture_transform")) source_.warn(at + ": ignores KHR_texture_transform");
  look.appearance = appearance;
  looks_[key] = look;
  return look;
}

std::shared_ptr<const Texture> SceneBuilder::textureFor(const Json& textureInfo, bool opaque, const std::string& where) {
  const Json* index = member(textureInfo, "index");
  if (!index || !index->is_number_unsigned()) {
    source_.warn(where + ": baseColorTexture has no index; drawn without it");
    return nullptr;
  }
  const auto key = std::make_pair(index->get<size_t>(), opaque);
  if (auto found = textures_.find(key); found != textures_.end()) return found->second;
  std::shared_ptr<Texture> texture;
  auto textureJson = element(source_, "textures", *index, where);
  if (!textureJson) {
    source_.warn(textureJson.message() + "; drawn without it");
    textures_[key] = nullptr;
    return nullptr;
  }
  const Json* imageIndex = member(**textureJson, "source");
  if (!imageIndex || !imageIndex->is_number_unsigned()) {
    source_.warn(where + ": its texture has no image (or only an extension's); drawn without it");
    textures_[key] = nullptr;
    return nullptr;
  }
  const auto imageKey = std::make_pair(imageIndex->get<size_t>(), opaque);
  std::string url;
  if (auto found = decoded_.find(imageIndex->get<size_t>()); found != decoded_.end()) url = found->second.url;
  if (!images_.count(imageKey)) {
    std::shared_ptr<const Image> decoded;
    if (auto found = decoded_.find(imageIndex->get<size_t>()); found != decoded_.end()) decoded = found->second.image;
    // OPAQUE ignores the alpha channel (glTF 2.0, 3.9.4); VRML would blend with it.
    if (decoded && opaque) {
      bool translucent = false;
      for (size_t i = 3; i < decoded->rgba.size() && !translucent; i += 4) translucent = decoded->rgba[i] != 255;
      if (translucent) {
        Image copy = *decoded;
        for (size_t i = 3; i < copy.rgba.size(); i += 4) copy.rgba[i] = 255;
        decoded = std::make_shared<const Image>(std::move(copy));
      }
    }
    images_[imageKey] = decoded;
  }
  const std::shared_ptr<const Image> image = images_[imageKey];
  if (image) {
    texture = std::make_shared<Texture>();
    texture->image = image;
    texture->url = url;
    if (const Json* samplerIndex = member(**textureJson, "sampler")) {
      if (auto sampler = element(source_, "samplers", *samplerIndex, where)) {
        // Mirrored repeat has no VRML form; plain repeat is nearest.
        if (const Json* s = member(**sampler, "wrapS"); s && s->is_number_unsigned() && s->get<size_t>() == kWrapClampToEdge) {
          texture->wrapS = TextureWrap::kClamp;
        }
        if (const Json* t = member(**sampler, "wrapT"); t && t->is_number_unsigned() && t->get<size_t>() == kWrapClampToEdge) {
          texture->wrapT = TextureWrap::kClamp;
        }
      }
    }
  }
  textures_[key] = texture;
  return texture;
}

}  // namespace pw::engine::gltf
