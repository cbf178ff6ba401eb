// The document: asset, nodes for shapes, cameras and lights, and the one scene.
#include "engine/gltf/gltf_document.h"

#include <cmath>
#include <set>

#include <glm/gtc/constants.hpp>
#include <glm/gtx/quaternion.hpp>

#include "engine/gltf/gltf_mapping.h"
#include "engine/scene/camera.h"
#include "engine/scene/model_info.h"

namespace pw::engine::gltf {

namespace {

Json floats(const glm::vec3& v) { return Json::array({shortestDouble(v.x), shortestDouble(v.y), shortestDouble(v.z)}); }

// glTF rotations are unit quaternions written x, y, z, w (glTF 2.0, 5.25).
Json rotationJson(glm::quat q) {
  q = glm::normalize(q);
  if (q.w < 0) q = -q;  // the same rotation; a positive w reads better
  return Json::array({double(q.x), double(q.y), double(q.z), double(q.w)});
}

bool isIdentity(const glm::quat& q) { return q.x == 0.0f && q.y == 0.0f && q.z == 0.0f; }

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

std::string quoted(const std::string& kind, size_t index, const std::string& name) {
  return name.empty() ? kind + " " + std::to_string(index) : kind + " '" + name + "'";
}

Status checkTextures(const Scene& scene) {
  for (size_t i = 0; i < scene.shapes.size(); ++i) {
    const Shape& shape = scene.shapes[i];
    if (!shape.appearance || !shape.appearance->texture || !shape.appearance->texture->image) continue;
    const Image& image = *shape.appearance->texture->image;
    if (!image.empty() && image.rgba.size() != static_cast<size_t>(image.width) * image.height * 4) {
      return makeError(quoted("shape", i, shape.name) + ": its texture holds " + std::to_string(image.rgba.size()) +
                       " bytes, not the " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                       "x4 of its size");
    }
  }
  return {};
}

// An upper bound on the binary buffer, reserved at once: growing a buffer of tens of
// megabytes step by step costs more than filling it (bench/gltf_bench.cpp). Address
// space reserved and never written costs nothing.
size_t binaryBytesBound(const Scene& scene) {
  std::set<const void*> seen;
  size_t bytes = 0;
  for (const Shape& shape : scene.shapes) {
    if (shape.mesh && seen.insert(shape.mesh.get()).second) {
      const Mesh& m = *shape.mesh;
      // positions, normals, texture coordinates (maybe generated), colours, indices,
      // and the 4-byte alignment of each view
      bytes += m.positions.size() * (12 + 12 + 8 + 16) + m.indices.size() * 4 + 5 * 4;
    }
    if (shape.appearance && shape.appearance->texture && shape.appearance->texture->image &&
        seen.insert(shape.appearance->texture->image.get()).second) {
      bytes += shape.appearance->texture->image->rgba.size() + 1024;  // PNG of a photo: well under its raw size
    }
  }
  return bytes;
}

}  // namespace

int DocumentBuilder::addRootNode(Json node) {
  doc_["nodes"].push_back(std::move(node));
  rootNodes_.push_back(static_cast<int>(doc_["nodes"].size()) - 1);
  return rootNodes_.back();
}

Status DocumentBuilder::build() {
  doc_["asset"] = Json{{"version", "2.0"}, {"generator", "photowalk"}};
  const std::vector<std::string> info = infoForFile(scene_, [](const Texture& texture) {
    return std::filesystem::path(texture.url).filename().string();  // the image's name (textureFor)
  });
  if (!info.empty()) doc_["asset"]["extras"] = Json{{"info", info}};
  PW_TRY(checkTextures(scene_));
  bin_.reserve(binaryBytesBound(scene_));
  for (size_t i = 0; i < scene_.shapes.size(); ++i) PW_TRY(addShape(i));
  for (size_t i = 0; i < scene_.viewpoints.size(); ++i) PW_TRY(addCamera(scene_.viewpoints[i], i));
  for (size_t i = 0; i < scene_.lights.size(); ++i) PW_TRY(addLight(scene_.lights[i], i));
  PW_TRY(embedImages());

  Json sceneJson = Json::object();
  if (!rootNodes_.empty()) sceneJson["nodes"] = rootNodes_;  // glTF forbids empty arrays
  if (!scene_.title.empty()) sceneJson["name"] = scene_.title;
  doc_["scenes"] = Json::array({std::move(sceneJson)});
  doc_["scene"] = 0;
  if (!bin_.empty()) {
    bin_.resize((bin_.size() + 3) & ~size_t{3}, 0);  // GLB chunks are 4-byte aligned
    doc_["buffers"] = Json::array({Json{{"byteLength", bin_.size()}}});
  }
  return {};
}

Status DocumentBuilder::addShape(size_t shapeIndex) {
  const Shape& shape = scene_.shapes[shapeIndex];
  // Nothing to draw: glTF accessors cannot be empty (count >= 1), so leave it out.
  if (!shape.mesh || shape.mesh->positions.empty()) return {};
  if (shape.mesh->topology != Topology::kPoints && shape.mesh->indices.empty()) return {};
  const std::string label = quoted("shape", shapeIndex, shape.name);

  Json node = Json::object();
  const Mesh* mesh = shape.mesh.get();
  glm::mat4 transform = shape.transform;
  // glTF lets a negative determinant flip the winding (glTF 2.0, 3.7.4), but viewers
  // get it wrong (view3dscene 4.2 draws such shapes inside out), so a mirroring
  // transform is written as a positive one over a mirrored copy of the mesh, made once
  // per mesh and shared by all its mirrored uses: T p = (T S) (S p), S = diag(-1, 1, 1).
  if (glm::determinant(glm::mat3(transform)) < 0.0f) {
    std::unique_ptr<Mesh>& mirrored = mirroredMeshes_[mesh];
    if (!mirrored) mirrored = std::make_unique<Mesh>(mirroredInX(*mesh));
    mesh = mirrored.get();
    transform[0] = -transform[0];
  }
  if (const std::optional<Trs> trs = decomposeTrs(transform)) {
    if (trs->translation != glm::vec3(0.0f)) node["translation"] = floats(trs->translation);
    if (!isIdentity(trs->rotation)) node["rotation"] = rotationJson(trs->rotation);
    if (trs->scale != glm::vec3(1.0f)) node["scale"] = floats(trs->scale);
  } else {
    for (int c = 0; c < 4; ++c) {
      if (!finite(glm::vec3(shape.transform[c])) || !std::isfinite(shape.transform[c][3])) {
        return makeError(label + ": its transform has a non-finite entry");
      }
    }
    std::optional<Mesh> baked = bakeTransform(*shape.mesh, shape.transform);
    if (!baked) return {};  // squashed flat to nothing: invisible
    bakedMeshes_.push_back(std::make_unique<Mesh>(std::move(*baked)));
    mesh = bakedMeshes_.back().get();
  }
  auto meshIndex = meshFor(*mesh, shape.appearance.get(), label);
  if (!meshIndex) return meshIndex.error();
  node["mesh"] = *meshIndex;
  if (!shape.name.empty()) node["name"] = shape.name;
  addRootNode(std::move(node));
  return {};
}

Status DocumentBuilder::addCamera(const Viewpoint& viewpoint, size_t index) {
  const std::string label = quoted("viewpoint", index, viewpoint.description);
  if (!(viewpoint.fieldOfViewRad > 0.0f && viewpoint.fieldOfViewRad < glm::pi<float>())) {
    return makeError(label + ": fieldOfView " + std::to_string(viewpoint.fieldOfViewRad) +
                     " rad is outside (0, pi); VRML97 6.53 allows only that range");
  }
  if (!finite(viewpoint.position) || !finite(glm::vec3(viewpoint.orientation)) ||
      !std::isfinite(viewpoint.orientation.w)) {
    return makeError(label + ": its position or orientation is not a finite number");
  }
  const PerspectiveCamera lens = perspectiveFromViewpoint(viewpoint, scene_.navigation);
  Json perspective = {{"yfov", shortestDouble(lens.yfovRad)},
                      {"znear", shortestDouble(lens.znearM)},
                      {"zfar", shortestDouble(lens.zfarM)}};
  Json camera = {{"type", "perspective"}, {"perspective", std::move(perspective)}};
  if (!viewpoint.description.empty()) camera["name"] = viewpoint.description;
  doc_["cameras"].push_back(std::move(camera));

  // glTF cameras, like VRML viewpoints, look along local -Z with +Y up (glTF 2.0, 3.10.1).
  Json node = {{"camera", static_cast<int>(doc_["cameras"].size()) - 1}};
  node["name"] = viewpoint.description.empty() ? "Viewpoint " + std::to_string(index) : viewpoint.description;
  if (viewpoint.position != glm::vec3(0.0f)) node["translation"] = floats(viewpoint.position);
  const glm::quat rotation = orientationFromAxisAngle(viewpoint.orientation);
  if (!isIdentity(rotation)) node["rotation"] = rotationJson(rotation);
  addRootNode(std::move(node));
  return {};
}

Status DocumentBuilder::addLight(const Light& light, size_t index) {
  static const char* kinds[] = {"DirectionalLight", "PointLight", "SpotLight"};
  const std::string name = std::string(kinds[static_cast<int>(light.type)]) + " " + std::to_string(index);
  const std::string label = "light " + std::to_string(index) + " (" + kinds[static_cast<int>(light.type)] + ")";
  const bool positioned = light.type != LightType::kDirectional;
  const bool aimed = light.type != LightType::kPoint;
  // glTF has no switched-off light, and a zero radius or cut-off angle lights nothing.
  if (!light.on || !(light.intensity > 0.0f)) return {};
  if (positioned && !(light.radius > 0.0f)) return {};
  if (light.type == LightType::kSpot && !(light.cutOffAngle > 0.0f)) return {};
  if (!finite(light.color) || !std::isfinite(light.intensity) || !finite(light.position) ||
      !finite(light.direction) || !finite(light.attenuation) || !std::isfinite(light.radius)) {
    return makeError(label + ": a field is not a finite number");
  }
  if (aimed && !(glm::length(light.direction) > 0.0f)) {
    return makeError(label + ": its direction is (0, 0, 0); give the way it shines");
  }

  static const char* types[] = {"directional", "point", "spot"};
  Json gltfLight = {{"type", types[static_cast<int>(light.type)]},
                    {"color", floats(linearFromSrgb(light.color))},
                    {"intensity", shortestDouble(punctualIntensity(light))}};
  if (positioned) gltfLight["range"] = shortestDouble(light.radius);
  if (light.type == LightType::kSpot) {
    const SpotCone cone = spotCone(light);
    gltfLight["spot"] = Json{{"innerConeAngle", shortestDouble(cone.innerRad)},
                             {"outerConeAngle", shortestDouble(cone.outerRad)}};
  }
  Json& lights = doc_["extensions"]["KHR_lights_punctual"]["lights"];
  lights.push_back(std::move(gltfLight));
  addExtensionUsed("KHR_lights_punctual");

  // Punctual lights shine along their node's local -Z (KHR_lights_punctual).
  Json node = {{"name", name}};
  node["extensions"] = Json{{"KHR_lights_punctual", Json{{"light", static_cast<int>(lights.size()) - 1}}}};
  if (positioned && light.position != glm::vec3(0.0f)) node["translation"] = floats(light.position);
  if (aimed) {
    const glm::quat rotation = glm::rotation(glm::vec3(0, 0, -1), glm::normalize(light.direction));
    if (!isIdentity(rotation)) node["rotation"] = rotationJson(rotation);
  }
  addRootNode(std::move(node));
  return {};
}

}  // namespace pw::engine::gltf
