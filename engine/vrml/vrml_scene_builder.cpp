#include "engine/vrml/vrml_scene_builder.h"

#include <cmath>
#include <unordered_map>
#include <unordered_set>

#include "engine/vrml/vrml_appearance.h"
#include "engine/vrml/vrml_fields.h"
#include "engine/vrml/vrml_geometry.h"
#include "engine/vrml/vrml_text.h"
#include "engine/vrml/vrml_proto.h"
#include "engine/vrml/vrml_transform.h"

namespace pw::engine::vrml {

namespace fs = std::filesystem;

namespace {

// The Inline files above a node, to refuse a file that inlines itself.
struct InlineChain {
  std::string canonicalPath;
  std::shared_ptr<const InlineChain> parent;
  int depth = 0;
};

struct Visit {
  NodePtr node;
  glm::dmat4 transform{1.0};
  const std::string* nameHint = nullptr;  // nearest DEF name above
  std::shared_ptr<const InlineChain> inlines;
};

struct MeshKey {
  const Node* geometry;
  const Node* textureTransform;
  bool texCoords;
  bool operator==(const MeshKey&) const = default;
};

struct MeshKeyHash {
  size_t operator()(const MeshKey& k) const {
    return std::hash<const void*>()(k.geometry) * 31 + std::hash<const void*>()(k.textureTransform) * 7 + k.texCoords;
  }
};

// A key naming a primitive by its field values (and texture mapping), or "" for other
// geometry.
std::string primitiveKey(const Node& node, bool textured, const Node* textureTransform) {
  const std::string& type = node.typeName();
  if (type != "Box" && type != "Sphere" && type != "Cylinder" && type != "Cone") return {};
  std::string key = type + (textured ? "+t" : "");
  auto add = [&](double v) { key += ' ' + std::to_string(v); };
  for (const FieldDecl& decl : node.type->fields) {
    const FieldValue& v = node.field(node.type->findField(decl.name));
    for (double d : v.doubles) add(d);
    for (int32_t i : v.ints) add(i);
  }
  if (textureTransform) {
    const glm::dmat3 t = textureTransformMatrix(*textureTransform);
    for (int c = 0; c < 3; ++c) {
      for (int r = 0; r < 3; ++r) add(t[c][r]);
    }
  }
  return key;
}

bool isIdentity(const glm::dmat4& m) { return m == glm::dmat4(1.0); }

glm::vec4 rotationToAxisAngle(const glm::dmat3& r) { return glm::vec4(axisAngle(r)); }

// Everything numeric in the scene must be finite: a file whose numbers are each in
// range can still multiply to infinity through nested scales.
bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

bool sceneIsFinite(const Scene& scene) {
  std::unordered_set<const Mesh*> checked;
  for (const Shape& s : scene.shapes) {
    for (int c = 0; c < 4; ++c) {
      for (int r = 0; r < 4; ++r) {
        if (!std::isfinite(s.transform[c][r])) return false;
      }
    }
    if (!s.mesh || !checked.insert(s.mesh.get()).second) continue;
    for (const glm::vec3& p : s.mesh->positions) {
      if (!finite(p)) return false;
    }
    for (const glm::vec3& n : s.mesh->normals) {
      if (!finite(n)) return false;
    }
    for (const glm::vec2& t : s.mesh->texCoords) {
      if (!std::isfinite(t.x) || !std::isfinite(t.y)) return false;
    }
  }
  for (const Light& l : scene.lights) {
    if (!finite(l.position) || !finite(l.direction) || !std::isfinite(l.radius)) return false;
  }
  for (const Viewpoint& v : scene.viewpoints) {
    if (!finite(v.position) || !std::isfinite(v.orientation.w)) return false;
  }
  return true;
}

class Builder {
 public:
  Builder(DocumentLoader& loader, Diagnostics* diagnostics, const BuildLimits& limits)
      : loader_(loader),
        diagnostics_(diagnostics),
        limits_(limits),
        expander_([this](const Proto& p) { return resolveExternProto(p); }, limits.maxProtoCopies),
        resolve_([this](const NodePtr& n) { return resolveNode(n); }),
        appearances_(resolve_, diagnostics) {}

  Result<Scene> build(const std::shared_ptr<Document>& document);

 private:
  Result<NodePtr> resolveNode(const NodePtr& node) {
    if (!node) return NodePtr{};
    return expander_.expand(node);
  }
  const Proto* resolveExternProto(const Proto& proto);
  Status visit(const Visit& item);
  Status addShape(const Node& node, const Visit& item);
  Status addText(const Node& shapeNode, const Node& text, const ShapeLook& look, const Visit& item);
  void addLight(const Node& node, const glm::dmat4& m);
  void addViewpoint(const Node& node, const glm::dmat4& m);
  void addInline(const Node& node, const Visit& item);
  void pushChildren(const std::vector<NodePtr>& children, const Visit& parent, const glm::dmat4& transform);
  void note(const std::string& message) {
    if (diagnostics_) diagnostics_->note(message);
  }
  void warn(const std::string& message) {
    if (diagnostics_) diagnostics_->warn(message);
  }

  DocumentLoader& loader_;
  Diagnostics* diagnostics_;
  BuildLimits limits_;
  ProtoExpander expander_;
  NodeResolver resolve_;
  AppearanceBuilder appearances_;
  std::vector<Visit> stack_;
  std::vector<std::shared_ptr<Document>> documents_;  // keeps Inline / EXTERNPROTO files alive
  std::unordered_map<MeshKey, std::shared_ptr<const Mesh>, MeshKeyHash> meshes_;
  std::unordered_map<std::string, std::shared_ptr<const Mesh>> primitives_;
  std::unordered_set<const Node*> emptyGeometry_;
  Scene scene_;
  bool navigationSeen_ = false, backgroundSeen_ = false, worldInfoSeen_ = false;
  size_t visited_ = 0;
};

const Proto* Builder::resolveExternProto(const Proto& proto) {
  if (proto.resolved) return proto.resolved;
  if (proto.resolveFailed) return nullptr;
  std::string reasons;
  for (const std::string& url : proto.urls) {
    const size_t hash = url.find('#');
    const std::string file = url.substr(0, hash);
    const std::string name = hash == std::string::npos ? proto.interface.name : url.substr(hash + 1);
    std::string whyNot;
    const auto path = file.empty() ? std::optional<fs::path>(proto.file->path)
                                   : localPath(file, proto.file, whyNot);
    if (!path) {
      reasons += (reasons.empty() ? "" : "; ") + whyNot;
      continue;
    }
    auto document = loader_.load(*path);
    if (!document) {
      reasons += (reasons.empty() ? "" : "; ") + document.message();
      continue;
    }
    documents_.push_back(*document);
    auto found = (*document)->topLevelProtos.find(name);
    if (found == (*document)->topLevelProtos.end() || found->second->external) {
      reasons += (reasons.empty() ? "" : "; ") + path->string() + " has no PROTO " + name;
      continue;
    }
    const Proto* target = found->second;
    std::string mismatch;
    for (const FieldDecl& decl : proto.interface.fields) {
      const int i = target->interface.findMember(decl.name);
      if (i < 0 || target->interface.fields[static_cast<size_t>(i)].type != decl.type) {
        mismatch = "its PROTO " + name + " lacks " + std::string(fieldTypeName(decl.type)) + " " + decl.name;
        break;
      }
    }
    if (!mismatch.empty()) {
      reasons += (reasons.empty() ? "" : "; ") + mismatch;
      continue;
    }
    proto.resolved = target;
    return target;
  }
  proto.resolveFailed = true;
  warn(proto.file->displayName + ":" + std::to_string(proto.pos.line) + ":" + std::to_string(proto.pos.column) +
       ": EXTERNPROTO " + proto.interface.name + " is not resolved (" +
       (reasons.empty() ? std::string("no url") : reasons) + "); its instances are skipped");
  return nullptr;
}

void Builder::pushChildren(const std::vector<NodePtr>& children, const Visit& parent, const glm::dmat4& transform) {
  // Reverse, so that the stack pops them in document order.
  for (auto it = children.rbegin(); it != children.rend(); ++it) {
    if (*it) stack_.push_back(Visit{*it, transform, parent.nameHint, parent.inlines});
  }
}

void Builder::addLight(const Node& node, const glm::dmat4& m) {
  Light light;
  const std::string& type = node.typeName();
  light.type = type == "DirectionalLight" ? LightType::kDirectional
               : type == "PointLight"     ? LightType::kPoint
                                          : LightType::kSpot;
  light.on = getBool(node, "on");
  light.color = glm::vec3(glm::clamp(getVec3(node, "color"), 0.0, 1.0));
  light.intensity = static_cast<float>(glm::clamp(getDouble(node, "intensity"), 0.0, 1.0));
  light.ambientIntensity = static_cast<float>(glm::clamp(getDouble(node, "ambientIntensity"), 0.0, 1.0));
  const bool identity = isIdentity(m);
  if (light.type != LightType::kPoint) {
    glm::dvec3 d = getVec3(node, "direction");
    if (!(glm::length(d) > 0.0)) {
      warn(node.where() + ": " + type + " direction 0 0 0 points nowhere; using 0 0 -1");
      d = {0.0, 0.0, -1.0};
    }
    light.direction = identity ? glm::vec3(d) : glm::vec3(glm::dmat3(m) * d);
  }
  if (light.type != LightType::kDirectional) {
    const glm::dvec3 p = getVec3(node, "location");
    light.position = identity ? glm::vec3(p) : glm::vec3(m * glm::dvec4(p, 1.0));
    light.attenuation = glm::vec3(glm::max(getVec3(node, "attenuation"), 0.0));
    // A radius in local units scales with the transform (by its mean scale).
    const TransformFields f = decomposeTransform(m);
    const double scale = identity ? 1.0 : std::cbrt(std::fabs(f.scale.x * f.scale.y * f.scale.z));
    light.radius = static_cast<float>(std::max(getDouble(node, "radius"), 0.0) * scale);
  }
  if (light.type == LightType::kSpot) {
    light.beamWidth = static_cast<float>(getDouble(node, "beamWidth"));
    light.cutOffAngle = static_cast<float>(getDouble(node, "cutOffAngle"));
  }
  if (type == "DirectionalLight" && !identity) {
    // 6.16: a DirectionalLight lights only its siblings; photowalk's lights are global.
    note("DirectionalLights inside groups light the whole scene in photowalk, not only their group");
  }
  scene_.lights.push_back(light);
}

void Builder::addViewpoint(const Node& node, const glm::dmat4& m) {
  Viewpoint v;
  v.description = getString(node, "description");
  const glm::dvec3 p = getVec3(node, "position");
  glm::dvec4 o = getVec4(node, "orientation");
  if (!(glm::length(glm::dvec3(o)) > 0.0)) {
    // A zero axis has no rotation to give; viewers read it as none.
    if (o.w != 0.0) warn(node.where() + ": Viewpoint orientation has a zero axis; treated as no rotation");
    o = {0.0, 0.0, 1.0, 0.0};
  }
  v.fieldOfViewRad = static_cast<float>(getDouble(node, "fieldOfView"));
  if (!(v.fieldOfViewRad > 0.0f && v.fieldOfViewRad < 3.14159f)) {
    warn(node.where() + ": Viewpoint fieldOfView " + std::to_string(v.fieldOfViewRad) +
         " is outside (0, pi); using the default " + std::to_string(kDefaultFieldOfViewRad));
    v.fieldOfViewRad = kDefaultFieldOfViewRad;
  }
  if (isIdentity(m)) {
    v.position = glm::vec3(p);
    v.orientation = glm::vec4(o);
  } else {
    v.position = glm::vec3(m * glm::dvec4(p, 1.0));
    v.orientation = rotationToAxisAngle(rotationPart(m) * rotationMatrix(o));
  }
  scene_.viewpoints.push_back(v);
}

void Builder::addInline(const Node& node, const Visit& item) {
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
    fs::path canonical = fs::weakly_canonical(*path, ec);
    const std::string key = ec ? path->string() : canonical.string();
    for (const InlineChain* c = item.inlines.get(); c; c = c->parent.get()) {
      if (c->canonicalPath == key) {
        warn(node.where() + ": Inline " + url + " includes itself (through " + c->canonicalPath + "); skipped");
        return;
      }
    }
    const int depth = item.inlines ? item.inlines->depth + 1 : 1;
    if (depth > limits_.maxInlineDepth) {
      warn(node.where() + ": Inlines nest deeper than " + std::to_string(limits_.maxInlineDepth) + "; skipped");
      return;
    }
    auto document = loader_.load(*path);
    if (!document) {
      reasons += (reasons.empty() ? "" : "; ") + document.message();
      continue;
    }
    documents_.push_back(*document);
    Visit child = item;
    child.inlines = std::make_shared<const InlineChain>(InlineChain{key, item.inlines, depth});
    pushChildren((*document)->roots, child, item.transform);
    return;
  }
  warn(node.where() + ": Inline not loaded (" + (reasons.empty() ? std::string("no url") : reasons) + "); skipped");
}

Status Builder::addShape(const Node& node, const Visit& item) {
  if (scene_.shapes.size() >= limits_.maxShapes) {
    return makeError(node.where() + ": the scene has more than " + std::to_string(limits_.maxShapes) +
                     " shapes once DEF/USE and Inlines are multiplied out; photowalk refuses it");
  }
  auto look = appearances_.look(getNode(node, "appearance"));
  if (!look) return look.error();
  auto geometry = resolveNode(getNode(node, "geometry"));
  if (!geometry) return geometry.error();
  if (!*geometry || emptyGeometry_.count(geometry->get())) return {};
  if ((*geometry)->typeName() == "Text") return addText(node, **geometry, *look, item);
  const bool textured = look->appearance && look->appearance->texture;
  const MeshKey key{geometry->get(), textured ? look->textureTransform : nullptr, textured};
  std::shared_ptr<const Mesh> mesh;
  auto cached = meshes_.find(key);
  // Equal primitives share one mesh even without DEF/USE (PROTO copies make many).
  const std::string primitive =
      cached == meshes_.end() ? primitiveKey(**geometry, textured, key.textureTransform) : std::string();
  auto cachedPrimitive = primitive.empty() ? primitives_.end() : primitives_.find(primitive);
  if (cached != meshes_.end()) {
    mesh = cached->second;
  } else if (cachedPrimitive != primitives_.end()) {
    mesh = cachedPrimitive->second;
    meshes_.emplace(key, mesh);
  } else {
    auto built = buildGeometry(**geometry, resolve_, GeometryOptions{textured}, diagnostics_);
    if (!built) return built.error();
    if (!*built) {
      emptyGeometry_.insert(geometry->get());
      return {};
    }
    Mesh& m = **built;
    if (key.textureTransform) {
      const glm::dmat3 t = textureTransformMatrix(*key.textureTransform);
      for (glm::vec2& tc : m.texCoords) tc = glm::vec2(t * glm::dvec3(tc, 1.0));
    }
    mesh = std::make_shared<const Mesh>(std::move(m));
    meshes_.emplace(key, mesh);
    if (!primitive.empty()) primitives_.emplace(primitive, mesh);
  }
  Shape shape;
  shape.mesh = std::move(mesh);
  shape.appearance = look->appearance;
  shape.transform = toFloatMatrix(item.transform);
  shape.name = !node.defName.empty() ? node.defName : item.nameHint ? *item.nameHint : std::string();
  scene_.shapes.push_back(std::move(shape));
  return {};
}

// Text (6.47): quads textured with the glyphs (vrml_text.h), coloured by the shape's
// Material; the Appearance's own texture, if any, gives way to the glyphs.
Status Builder::addText(const Node& shapeNode, const Node& text, const ShapeLook& look, const Visit& item) {
  auto built = buildText(text, resolve_, diagnostics_);
  if (!built) return built.error();
  if (!*built) return {};
  auto texture = std::make_shared<Texture>();
  texture->image = (*built)->glyphs;
  texture->wrapS = texture->wrapT = TextureWrap::kClamp;
  auto appearance = look.appearance ? std::make_shared<Appearance>(*look.appearance) : std::make_shared<Appearance>();
  appearance->texture = std::move(texture);
  Shape shape;
  shape.mesh = std::make_shared<const Mesh>(std::move((*built)->mesh));
  shape.appearance = std::move(appearance);
  shape.transform = toFloatMatrix(item.transform);
  shape.name = !shapeNode.defName.empty() ? shapeNode.defName : item.nameHint ? *item.nameHint : std::string();
  scene_.shapes.push_back(std::move(shape));
  return {};
}

Status Builder::visit(const Visit& item) {
  auto resolved = resolveNode(item.node);
  if (!resolved) return resolved.error();
  if (!*resolved) return {};
  const Node& node = **resolved;
  const std::string& type = node.typeName();
  Visit self = item;
  if (!item.node->defName.empty()) self.nameHint = &item.node->defName;
  if (!node.defName.empty()) self.nameHint = &node.defName;

  if (type == "Transform") {
    TransformFields f;
    f.translation = getVec3(node, "translation");
    f.rotation = getVec4(node, "rotation");
    f.scale = getVec3(node, "scale");
    f.scaleOrientation = getVec4(node, "scaleOrientation");
    f.center = getVec3(node, "center");
    pushChildren(getNodes(node, "children"), self, item.transform * composeTransform(f));
  } else if (type == "Group" || type == "Anchor" || type == "Collision" || type == "Billboard") {
    if (type == "Billboard") note("Billboard nodes are drawn unrotated, like Groups");
    pushChildren(getNodes(node, "children"), self, item.transform);
  } else if (type == "Switch") {
    const int32_t which = getInt(node, "whichChoice");
    const std::vector<NodePtr>& choice = getNodes(node, "choice");
    if (which >= 0 && static_cast<size_t>(which) < choice.size()) {
      pushChildren({choice[static_cast<size_t>(which)]}, self, item.transform);
    }
  } else if (type == "LOD") {
    const std::vector<NodePtr>& levels = getNodes(node, "level");
    if (!levels.empty()) {
      if (levels.size() > 1) note("LOD nodes show their first (most detailed) level");
      pushChildren({levels.front()}, self, item.transform);
    }
  } else if (type == "Shape") {
    return addShape(node, self);
  } else if (type == "Inline") {
    addInline(node, self);
  } else if (type == "DirectionalLight" || type == "PointLight" || type == "SpotLight") {
    addLight(node, item.transform);
  } else if (type == "Viewpoint") {
    addViewpoint(node, item.transform);
  } else if (type == "NavigationInfo") {
    if (!navigationSeen_) {
      navigationSeen_ = true;
      NavigationInfo& nav = scene_.navigation;
      nav.headlight = getBool(node, "headlight");
      const std::vector<float>& avatar = getFloats(node, "avatarSize");
      if (avatar.size() > 0) nav.avatarRadiusM = avatar[0];
      if (avatar.size() > 1) nav.avatarHeightM = avatar[1];
      if (avatar.size() > 2) nav.stepHeightM = avatar[2];
      nav.speedMps = static_cast<float>(getDouble(node, "speed"));
      nav.type = getStrings(node, "type");
      nav.visibilityLimitM = static_cast<float>(getDouble(node, "visibilityLimit"));
    }
  } else if (type == "Background") {
    if (!backgroundSeen_) {
      backgroundSeen_ = true;
      const std::vector<float>& sky = getFloats(node, "skyColor");
      if (sky.size() >= 3) scene_.backgroundColor = glm::clamp(glm::vec3(sky[0], sky[1], sky[2]), 0.0f, 1.0f);
      if (sky.size() > 3 || !getFloats(node, "groundColor").empty()) {
        note("Background gradients are drawn as their first sky colour");
      }
    }
  } else if (type == "WorldInfo") {
    if (!worldInfoSeen_) {
      worldInfoSeen_ = true;
      scene_.title = getString(node, "title");
      scene_.info = getStrings(node, "info");
    }
  } else if (type == "Script" || type == "TimeSensor" || type == "TouchSensor" || type == "ProximitySensor" ||
             type == "PlaneSensor" || type == "CylinderSensor" || type == "SphereSensor" ||
             type == "VisibilitySensor" || type.find("Interpolator") != std::string::npos) {
    note(type + " nodes are ignored (photowalk shows static scenes)");
  } else if (type == "Fog" || type == "Sound" || type == "AudioClip") {
    note(type + " nodes are ignored (not supported yet)");
  } else {
    warn(node.where() + ": a " + type + " cannot be a child of a grouping node; ignored");
  }
  return {};
}

Result<Scene> Builder::build(const std::shared_ptr<Document>& document) {
  documents_.push_back(document);
  Visit root;
  if (!document->file->path.empty()) {
    // The file itself heads the Inline chain, so that a file inlining itself is caught
    // at once.
    std::error_code ec;
    const fs::path canonical = fs::weakly_canonical(document->file->path, ec);
    root.inlines = std::make_shared<const InlineChain>(
        InlineChain{ec ? document->file->path.string() : canonical.string(), nullptr, 0});
  }
  pushChildren(document->roots, root, glm::dmat4(1.0));
  while (!stack_.empty()) {
    if (++visited_ > limits_.maxVisitedNodes) {
      return makeError(document->file->displayName + ": the scene graph has more than " +
                       std::to_string(limits_.maxVisitedNodes) +
                       " nodes once DEF/USE and Inlines are multiplied out; photowalk refuses it");
    }
    const Visit item = std::move(stack_.back());
    stack_.pop_back();
    PW_TRY(visit(item));
  }
  if (!sceneIsFinite(scene_)) {
    return makeError(document->file->displayName +
                     ": the scene has numbers too large to represent once transforms are applied");
  }
  return std::move(scene_);
}

}  // namespace

Result<Scene> buildScene(const std::shared_ptr<Document>& document, DocumentLoader& loader, Diagnostics* diagnostics,
                         const BuildLimits& limits) {
  Builder builder(loader, diagnostics, limits);
  return builder.build(document);
}

}  // namespace pw::engine::vrml
