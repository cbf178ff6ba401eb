// The reader's scene layer: the node tree, meshes, cameras and lights of a loaded
// glTF document become the scene model (mappings: gltf_mapping.h).
#include "engine/gltf/gltf_read_scene.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/quaternion.hpp>

#include "engine/gltf/gltf_mapping.h"
#include "engine/scene/camera.h"

namespace pw::engine::gltf {

namespace {

// A light without a range reaches everywhere; VRML needs a radius.
constexpr float kUnboundedRadiusM = 1.0e6f;

// Primitive modes (glTF 2.0, 5.24.4) to the scene model's lists.
Result<std::vector<uint32_t>> listIndices(const Source& source, int mode, std::vector<uint32_t> in, Topology* topology,
                                          const std::string& where) {
  std::vector<uint32_t> out;
  switch (mode) {
    case 0: *topology = Topology::kPoints; return in;
    case 1:
      *topology = Topology::kLines;
      if (in.size() % 2) source.warn(where + ": drops the last index of an odd LINES list");
      in.resize(in.size() / 2 * 2);
      return in;
    case 2:  // LINE_LOOP
    case 3:  // LINE_STRIP
      *topology = Topology::kLines;
      for (size_t i = 0; i + 1 < in.size(); ++i) out.insert(out.end(), {in[i], in[i + 1]});
      if (mode == 2 && in.size() > 2) out.insert(out.end(), {in.back(), in.front()});
      return out;
    case 4:
      *topology = Topology::kTriangles;
      if (in.size() % 3) source.warn(where + ": drops a partial triangle");
      in.resize(in.size() / 3 * 3);
      return in;
    case 5:  // TRIANGLE_STRIP: every other triangle is wound the other way
      *topology = Topology::kTriangles;
      for (size_t i = 0; i + 2 < in.size(); ++i) {
        if (i % 2 == 0) out.insert(out.end(), {in[i], in[i + 1], in[i + 2]});
        else out.insert(out.end(), {in[i + 1], in[i], in[i + 2]});
      }
      return out;
    case 6:  // TRIANGLE_FAN
      *topology = Topology::kTriangles;
      for (size_t i = 1; i + 1 < in.size(); ++i) out.insert(out.end(), {in[0], in[i], in[i + 1]});
      return out;
    default: return source.error(where + ": unknown primitive mode " + std::to_string(mode));
  }
}

}  // namespace

Result<glm::mat4> SceneBuilder::localMatrix(const Json& node, const std::string& where) {
  if (member(node, "matrix")) {
    auto m = numbersOr(source_, node, "matrix", 16, {}, where);
    if (!m) return m.error();
    glm::mat4 matrix;
    for (int i = 0; i < 16; ++i) matrix[i / 4][i % 4] = static_cast<float>((*m)[i]);  // column-major, as glm
    return matrix;
  }
  auto t = numbersOr(source_, node, "translation", 3, {0, 0, 0}, where);
  auto r = numbersOr(source_, node, "rotation", 4, {0, 0, 0, 1}, where);
  auto s = numbersOr(source_, node, "scale", 3, {1, 1, 1}, where);
  if (!t) return t.error();
  if (!r) return r.error();
  if (!s) return s.error();
  glm::quat q{static_cast<float>((*r)[3]), static_cast<float>((*r)[0]), static_cast<float>((*r)[1]), static_cast<float>((*r)[2])};
  q = glm::length(q) > 0.0f ? glm::normalize(q) : glm::quat(1, 0, 0, 0);
  glm::mat4 m = glm::mat4_cast(q);
  const glm::vec3 scale = vec3Of(*s);
  for (int c = 0; c < 3; ++c) m[c] *= scale[c];
  m[3] = glm::vec4(vec3Of(*t), 1.0f);
  return m;
}

Status SceneBuilder::addNode(size_t index, const glm::mat4& parent, size_t depth) {
  const std::string where = indexed("nodes", index);
  auto nodeJson = element(source_, "nodes", Json(index), where);
  if (!nodeJson) return nodeJson.error();
  const Json& node = **nodeJson;
  // glTF nodes form a forest (glTF 2.0, 3.5.3): reaching one twice is a loop or a
  // shared child; either way the file is malformed.
  if (!visited_.insert(index).second || depth > 1000) return source_.error(where + ": is part of a node loop");
  auto local = localMatrix(node, where);
  if (!local) return local.error();
  const glm::mat4 world = parent * *local;
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      if (!std::isfinite(world[c][r])) return source_.error(where + ": its world transform overflows (not finite)");
    }
  }
  std::string name;
  if (const Json* n = member(node, "name"); n && n->is_string()) name = n->get<std::string>();

  if (const Json* mesh = member(node, "mesh")) PW_TRY(addMeshShapes(*mesh, world, name, where));
  if (const Json* camera = member(node, "camera")) PW_TRY(addCamera(*camera, world, name, where));
  if (const Json* ext = member(node, "extensions")) {
    if (const Json* lights = member(*ext, "KHR_lights_punctual")) {
      if (const Json* light = member(*lights, "light")) PW_TRY(addLight(*light, world, where));
    }
  }
  if (member(node, "skin")) source_.warn(where + ": ignores its skin");
  if (const Json* children = member(node, "children")) {
    if (!children->is_array()) return source_.error(where + ": children is not an array");
    for (const Json& child : *children) {
      if (!child.is_number_unsigned()) return source_.error(where + ": a child is not a node index");
      PW_TRY(addNode(child.get<size_t>(), world, depth + 1));
    }
  }
  return {};
}

Status SceneBuilder::addMeshShapes(const Json& meshIndex, const glm::mat4& world, const std::string& nodeName,
                                   const std::string& where) {
  auto meshJson = element(source_, "meshes", meshIndex, where);
  if (!meshJson) return meshJson.error();
  const Json* primitives = member(**meshJson, "primitives");
  if (!primitives || !primitives->is_array()) return source_.error(where + ": its mesh has no primitives array");
  std::string name = nodeName;
  if (const Json* n = member(**meshJson, "name"); name.empty() && n && n->is_string()) name = n->get<std::string>();
  const size_t mesh = meshIndex.get<size_t>();
  for (size_t p = 0; p < primitives->size(); ++p) {
    const std::string at = indexed("meshes", mesh) + ".primitives[" + std::to_string(p) + "]";
    const Json& primitive = (*primitives)[p];
    if (member(primitive, "targets")) source_.warn(at + ": ignores its morph targets");
    auto look = lookFor(member(primitive, "material"), at);
    if (!look) return look.error();
    auto geometry = primitiveMesh(mesh, p, primitive, *look, at);
    if (!geometry) return geometry.error();
    if (!*geometry) continue;  // nothing drawable
    if ((*geometry)->topology == Topology::kTriangles && flattens(world)) {
      source_.warn(at + ": placed by " + where + " with no area (a zero scale); left out");
      continue;
    }
    Shape shape;
    shape.mesh = *geometry;
    shape.appearance = look->appearance;
    shape.transform = world;
    const Bounds bounds = worldBounds(shape);
    if (!std::isfinite(bounds.min.x + bounds.min.y + bounds.min.z + bounds.max.x + bounds.max.y + bounds.max.z) ||
        !std::isfinite(glm::length(bounds.size()))) {
      return source_.error(at + ": placed by " + where + ", its vertices overflow (not finite)");
    }
    shape.name = primitives->size() > 1 && !name.empty() ? name + "_" + std::to_string(p) : name;
    scene_.shapes.push_back(std::move(shape));
  }
  return {};
}

Result<std::shared_ptr<const Mesh>> SceneBuilder::primitiveMesh(size_t meshIndex, size_t primitiveIndex,
                                                                 const Json& primitive, const Look& look,
                                                                 const std::string& where) {
  const auto key = std::make_pair(meshIndex, primitiveIndex);
  if (auto found = meshes_.find(key); found != meshes_.end()) return found->second;
  const Json* attributes = member(primitive, "attributes");
  const Json* position = attributes ? member(*attributes, "POSITION") : nullptr;
  if (!position) {
    source_.warn(where + ": has no POSITION; left out");
    meshes_[key] = nullptr;
    return std::shared_ptr<const Mesh>();
  }
  auto positions = readFloatAccessor(source_, *position, 3, 3, false, where + ".POSITION");
  if (!positions) return positions.error();
  const size_t n = positions->size();
  Mesh mesh;
  mesh.positions.reserve(n);
  for (const glm::vec4& p : *positions) mesh.positions.emplace_back(p);

  auto sameCount = [&](size_t count, const char* what) -> Status {
    if (count != n) {
      return source_.error(where + ": " + what + " has " + std::to_string(count) + " elements for " +
                           std::to_string(n) + " positions");
    }
    return {};
  };
  if (const Json* normal = member(*attributes, "NORMAL")) {
    auto normals = readFloatAccessor(source_, *normal, 3, 3, false, where + ".NORMAL");
    if (!normals) return normals.error();
    PW_TRY(sameCount(normals->size(), "NORMAL"));
    for (const glm::vec4& v : *normals) mesh.normals.emplace_back(v);
  }
  const std::string texCoordName = "TEXCOORD_" + std::to_string(look.texCoordSet);
  if (const Json* uv = member(*attributes, texCoordName.c_str()); uv && look.appearance && look.appearance->texture) {
    auto uvs = readFloatAccessor(source_, *uv, 2, 2, true, where + "." + texCoordName);
    if (!uvs) return uvs.error();
    PW_TRY(sameCount(uvs->size(), texCoordName.c_str()));
    // glTF's v = 0 is the image's top row; VRML's t = 0 its bottom row.
    for (const glm::vec4& v : *uvs) mesh.texCoords.emplace_back(v.x, 1.0f - v.y);
  }
  if (const Json* color = member(*attributes, "COLOR_0")) {
    auto colors = readFloatAccessor(source_, *color, 3, 4, true, where + ".COLOR_0");
    if (!colors) return colors.error();
    PW_TRY(sameCount(colors->size(), "COLOR_0"));
    for (const glm::vec4& c : *colors) mesh.colors.push_back(c);  // linear for now
  }
  // An unlit, untextured material's colour has no VRML home but the vertex colours.
  const bool foldFactor = look.unlit && !(look.appearance && look.appearance->texture) && look.colorFactor != glm::vec4(1.0f);
  if (foldFactor && mesh.colors.empty()) mesh.colors.assign(n, glm::vec4(1.0f));
  for (glm::vec4& c : mesh.colors) {
    if (foldFactor) c *= look.colorFactor;
    c = glm::vec4(srgbFromLinear(glm::vec3(c)), std::clamp(c.w, 0.0f, 1.0f));  // the model holds display colours
  }

  std::vector<uint32_t> indices;
  if (const Json* indexAccessor = member(primitive, "indices")) {
    auto read = readIndexAccessor(source_, *indexAccessor, n, where + ".indices");
    if (!read) return read.error();
    indices = std::move(*read);
  } else {
    indices.resize(n);
    std::iota(indices.begin(), indices.end(), 0u);
  }
  auto mode = numberOr(source_, primitive, "mode", 4, where);
  if (!mode) return mode.error();
  if (!(*mode >= 0 && *mode <= 6 && *mode == std::floor(*mode))) {
    return source_.error(where + ": unknown primitive mode " + std::to_string(*mode));
  }
  auto listed = listIndices(source_, static_cast<int>(*mode), std::move(indices), &mesh.topology, where);
  if (!listed) return listed.error();
  mesh.indices = std::move(*listed);
  mesh.solid = !look.doubleSided;
  if (mesh.indices.empty()) {
    meshes_[key] = nullptr;
    return std::shared_ptr<const Mesh>();
  }
  auto shared = std::make_shared<const Mesh>(std::move(mesh));
  meshes_[key] = shared;
  return shared;
}

Status SceneBuilder::addCamera(const Json& cameraIndex, const glm::mat4& world, const std::string& nodeName,
                               const std::string& where) {
  auto cameraJson = element(source_, "cameras", cameraIndex, where);
  if (!cameraJson) return cameraJson.error();
  const Json* type = member(**cameraJson, "type");
  const Json* perspective = member(**cameraJson, "perspective");
  if (!type || !type->is_string() || type->get<std::string>() != "perspective" || !perspective) {
    source_.warn(where + ": its camera is not perspective; left out");
    return {};
  }
  auto yfov = numberOr(source_, *perspective, "yfov", -1, where);
  auto aspect = numberOr(source_, *perspective, "aspectRatio", 0, where);
  if (!yfov) return yfov.error();
  if (!aspect) return aspect.error();
  if (!(*yfov > 0.0 && *yfov < glm::pi<double>())) return source_.error(where + ": camera yfov must lie in (0, pi)");
  Viewpoint viewpoint;
  // VRML's fieldOfView is the smaller angle: the horizontal one on a portrait view.
  double fov = *yfov;
  if (*aspect > 0.0 && *aspect < 1.0) fov = 2.0 * std::atan(*aspect * std::tan(0.5 * fov));
  viewpoint.fieldOfViewRad = static_cast<float>(fov);
  viewpoint.position = glm::vec3(world[3]);
  // The rotation part of the world matrix, with scale removed (columns normalised).
  glm::mat3 rotation(world);
  for (int c = 0; c < 3; ++c) {
    const float length = glm::length(rotation[c]);
    if (!(length > 0.0f)) return source_.error(where + ": the camera's node is scaled to nothing");
    rotation[c] /= length;
  }
  viewpoint.orientation = axisAngleFromOrientation(glm::quat_cast(rotation));
  std::string name = nodeName;
  if (const Json* n = member(**cameraJson, "name"); name.empty() && n && n->is_string()) name = n->get<std::string>();
  viewpoint.description = name;
  scene_.viewpoints.push_back(std::move(viewpoint));
  return {};
}

Status SceneBuilder::addLight(const Json& lightIndex, const glm::mat4& world, const std::string& where) {
  const Json* ext = member(source_.doc, "extensions");
  const Json* punctual = ext ? member(*ext, "KHR_lights_punctual") : nullptr;
  const Json* lights = punctual ? member(*punctual, "lights") : nullptr;
  if (!lights || !lights->is_array() || !lightIndex.is_number_unsigned() || lightIndex.get<size_t>() >= lights->size()) {
    return source_.error(where + ": refers to a KHR_lights_punctual light that does not exist");
  }
  const Json& json = (*lights)[lightIndex.get<size_t>()];
  const std::string at = "KHR_lights_punctual.lights[" + lightIndex.dump() + "]";
  const Json* type = member(json, "type");
  Light light;
  const std::string kind = type && type->is_string() ? type->get<std::string>() : "";
  if (kind == "directional") light.type = LightType::kDirectional;
  else if (kind == "point") light.type = LightType::kPoint;
  else if (kind == "spot") light.type = LightType::kSpot;
  else return source_.error(at + ": unknown light type " + (type ? type->dump() : "(none)"));
  auto color = numbersOr(source_, json, "color", 3, {1, 1, 1}, at);
  auto intensity = numberOr(source_, json, "intensity", 1, at);
  auto range = numberOr(source_, json, "range", kUnboundedRadiusM, at);
  if (!color) return color.error();
  if (!intensity) return intensity.error();
  if (!range) return range.error();
  light.color = srgbFromLinear(vec3Of(*color));
  setIntensityFromPunctual(light, static_cast<float>(*intensity));
  light.radius = static_cast<float>(std::clamp(*range, 0.0, double(kUnboundedRadiusM)));
  light.position = glm::vec3(world[3]);
  const glm::vec3 direction = glm::mat3(world) * glm::vec3(0, 0, -1);
  light.direction = glm::length(direction) > 0.0f ? glm::normalize(direction) : glm::vec3(0, 0, -1);
  if (light.type == LightType::kSpot) {
    const Json* spot = member(json, "spot");
    static const Json kEmpty = Json::object();
    auto inner = numberOr(source_, spot ? *spot : kEmpty, "innerConeAngle", 0, at);
    auto outer = numberOr(source_, spot ? *spot : kEmpty, "outerConeAngle", glm::quarter_pi<double>(), at);
    if (!inner) return inner.error();
    if (!outer) return outer.error();
    light.cutOffAngle = static_cast<float>(std::clamp(*outer, 0.0, glm::half_pi<double>()));
    light.beamWidth = static_cast<float>(std::clamp(*inner, 0.0, double(light.cutOffAngle)));
  }
  scene_.lights.push_back(light);
  return {};
}

Result<Scene> SceneBuilder::build() {
  // The scene to show: "scene", else the first; a file without scenes shows every
  // root node.
  std::vector<size_t> roots;
  const Json* scenes = member(source_.doc, "scenes");
  if (scenes && scenes->is_array() && !scenes->empty()) {
    static const Json kFirst = size_t{0};
    const Json* chosen = member(source_.doc, "scene");
    auto sceneJson = element(source_, "scenes", chosen ? *chosen : kFirst, "scene");
    if (!sceneJson) return sceneJson.error();
    if (const Json* name = member(**sceneJson, "name"); name && name->is_string()) scene_.title = name->get<std::string>();
    if (const Json* nodes = member(**sceneJson, "nodes")) {
      if (!nodes->is_array()) return source_.error("the scene's nodes is not an array");
      for (const Json& n : *nodes) {
        if (!n.is_number_unsigned()) return source_.error("the scene lists something that is not a node index");
        roots.push_back(n.get<size_t>());
      }
    }
  } else if (const Json* nodes = member(source_.doc, "nodes"); nodes && nodes->is_array()) {
    std::set<size_t> children;
    for (const Json& node : *nodes) {
      if (const Json* c = member(node, "children"); c && c->is_array()) {
        for (const Json& child : *c) {
          if (child.is_number_unsigned()) children.insert(child.get<size_t>());
        }
      }
    }
    for (size_t i = 0; i < nodes->size(); ++i) {
      if (!children.count(i)) roots.push_back(i);
    }
  }
  decoded_ = decodeUsedImages(source_);
  for (size_t root : roots) PW_TRY(addNode(root, glm::mat4(1.0f), 0));
  if (const Json* asset = member(source_.doc, "asset")) {
    const Json* extras = member(*asset, "extras");
    if (const Json* info = extras ? member(*extras, "info") : nullptr; info && info->is_array()) {
      for (const Json& line : *info) {
        if (line.is_string()) scene_.info.push_back(line.get<std::string>());
      }
    }
  }
  return std::move(scene_);
}

Result<Scene> buildScene(const Source& source) { return SceneBuilder(source).build(); }

}  // namespace pw::engine::gltf
