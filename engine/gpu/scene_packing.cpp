#include "engine/gpu/scene_packing.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_map>

#include "engine/scene/color_space.h"
#include "engine/scene/texture_source.h"

namespace pw::engine::gpu {
namespace {

std::string shapeLabel(const Shape& shape, size_t index) {
  return shape.name.empty() ? "shape #" + std::to_string(index) : "shape '" + shape.name + "'";
}

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

bool finite(const glm::mat4& m) {
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      if (!std::isfinite(m[c][r])) return false;
    }
  }
  return true;
}

Status checkMesh(const Mesh& mesh, const std::string& label) {
  const size_t n = mesh.positions.size();
  const auto wrongLength = [&](const char* what, size_t size) {
    return makeError(label + ": the mesh has " + std::to_string(size) + " " + what + " for " + std::to_string(n) +
                     " positions; give one per position or none");
  };
  if (!mesh.normals.empty() && mesh.normals.size() != n) return wrongLength("normals", mesh.normals.size());
  if (!mesh.texCoords.empty() && mesh.texCoords.size() != n) return wrongLength("texture coordinates", mesh.texCoords.size());
  if (!mesh.colors.empty() && mesh.colors.size() != n) return wrongLength("colours", mesh.colors.size());
  const size_t perPrimitive = mesh.topology == Topology::kTriangles ? 3 : mesh.topology == Topology::kLines ? 2 : 1;
  if (mesh.indices.size() % perPrimitive != 0) {
    return makeError(label + ": " + std::to_string(mesh.indices.size()) + " indices is not a whole number of " +
                     (perPrimitive == 3 ? "triangles" : "lines"));
  }
  for (size_t i = 0; i < mesh.indices.size(); ++i) {
    if (mesh.indices[i] >= n) {
      return makeError(label + ": index " + std::to_string(mesh.indices[i]) + " (at " + std::to_string(i) +
                       ") is out of range; the mesh has " + std::to_string(n) + " vertices");
    }
  }
  for (const glm::vec3& p : mesh.positions) {
    if (!finite(p)) return makeError(label + ": the mesh has a non-finite vertex position");
  }
  return {};
}

bool anyTransparentTexel(const Image& image) {
  for (size_t i = 3; i < image.rgba.size(); i += 4) {
    if (image.rgba[i] != 255) return true;
  }
  return false;
}

LightGpu packLight(const Light& light) {
  LightGpu out{};
  out.colorIntensity = glm::vec4(srgbToLinear(light.color), std::clamp(light.intensity, 0.0f, 1.0f));
  const uint32_t type = light.type == LightType::kDirectional ? kLightDirectional
                        : light.type == LightType::kPoint     ? kLightPoint
                                                              : kLightSpot;
  out.positionType = glm::vec4(light.position, static_cast<float>(type));
  const float length = glm::length(light.direction);
  const glm::vec3 direction = length > 1e-12f && finite(light.direction) ? light.direction / length : glm::vec3(0, 0, -1);
  out.directionAmbient = glm::vec4(direction, std::clamp(light.ambientIntensity, 0.0f, 1.0f));
  out.attenuationRadius = glm::vec4(glm::max(light.attenuation, glm::vec3(0.0f)), std::max(light.radius, 0.0f));
  // VRML97 6.45: a beamWidth wider than cutOffAngle means a constant spot out to cutOffAngle.
  const float cutOff = std::clamp(light.cutOffAngle, 0.0f, 3.14159265f);
  out.spot = glm::vec4(std::min(light.beamWidth, cutOff), cutOff, 0.0f, 0.0f);
  return out;
}

}  // namespace

std::optional<std::array<glm::vec4, 3>> textureSourceColumns(const Texture& texture) {
  if (!texture.sourceFromTexCoord) return std::nullopt;
  const glm::mat3 h = withFlippedT(*texture.sourceFromTexCoord);
  for (int c = 0; c < 3; ++c) {
    for (int r = 0; r < 3; ++r) {
      if (!std::isfinite(h[c][r])) return std::nullopt;
    }
  }
  // The whole texture must lie in front of the photo's camera (w > 0; w is affine in
  // (u, v), so its corners decide): a file's nonsense must not reach the shader.
  for (const glm::vec2 corner : {glm::vec2(0, 0), glm::vec2(1, 0), glm::vec2(0, 1), glm::vec2(1, 1)}) {
    if (!((h * glm::vec3(corner, 1.0f)).z > 0.0f)) return std::nullopt;
  }
  const float width = texture.image ? static_cast<float>(texture.image->width) : 1.0f;
  const float height = texture.image ? static_cast<float>(texture.image->height) : 1.0f;
  return std::array<glm::vec4, 3>{glm::vec4(h[0], 0.0f), glm::vec4(h[1], width), glm::vec4(h[2], height)};
}

glm::mat3 normalMatrix(const glm::mat4& model) {
  const glm::mat3 m(model);
  const glm::mat3 cofactor(glm::cross(m[1], m[2]), glm::cross(m[2], m[0]), glm::cross(m[0], m[1]));
  return glm::determinant(m) < 0.0f ? -cofactor : cofactor;  // cofactor = det * inverse transpose
}

Result<PackedScene> packScene(const Scene& scene) {
  PackedScene out;
  out.backgroundLinear = srgbToLinear(scene.backgroundColor);
  // Sorted by kind: the shader runs one loop per kind (see FrameUniforms::lightCounts).
  for (const LightType type : {LightType::kDirectional, LightType::kPoint, LightType::kSpot}) {
    for (const Light& light : scene.lights) {
      if (!light.on || light.type != type) continue;
      if (!finite(light.position) || !finite(light.color) || !std::isfinite(light.intensity)) {
        return makeError("a light has a non-finite position, colour or intensity");
      }
      out.lights.push_back(packLight(light));
      ++out.lightCounts[static_cast<int>(type)];
    }
  }

  struct MeshRange {
    uint32_t firstIndex;
    int32_t vertexOffset;
    bool hasTransparentColor;
  };
  std::unordered_map<const Mesh*, MeshRange> packedMeshes;
  std::unordered_map<const Texture*, uint32_t> textureSlots;

  for (size_t s = 0; s < scene.shapes.size(); ++s) {
    const Shape& shape = scene.shapes[s];
    if (!shape.mesh || shape.mesh->indices.empty()) continue;
    const Mesh& mesh = *shape.mesh;
    const std::string label = shapeLabel(shape, s);
    if (!finite(shape.transform)) return makeError(label + ": its transform has a non-finite number");

    auto packed = packedMeshes.find(&mesh);
    if (packed == packedMeshes.end()) {
      PW_TRY(checkMesh(mesh, label));
      if (out.vertices.size() + mesh.positions.size() > static_cast<size_t>(INT32_MAX)) {
        return makeError(label + ": the scene has more than 2^31 vertices");
      }
      MeshRange range{static_cast<uint32_t>(out.indices.size()), static_cast<int32_t>(out.vertices.size()), false};
      std::vector<glm::vec3> generatedNormals;
      if (mesh.normals.empty() && mesh.topology == Topology::kTriangles) {
        Mesh copy = mesh;  // a mesh without normals gets smooth ones rather than none
        computeSmoothNormals(copy);
        generatedNormals = std::move(copy.normals);
      }
      const std::vector<glm::vec3>& normals = mesh.normals.empty() ? generatedNormals : mesh.normals;
      for (size_t v = 0; v < mesh.positions.size(); ++v) {
        Vertex vertex{};
        vertex.position = mesh.positions[v];
        vertex.normal = normals.empty() ? glm::vec3(0, 0, 1) : normals[v];
        vertex.texCoord = mesh.texCoords.empty() ? glm::vec2(0.0f) : mesh.texCoords[v];
        if (mesh.colors.empty()) {
          vertex.color = glm::vec4(1.0f);
        } else {
          const glm::vec4 c = mesh.colors[v];
          vertex.color = glm::vec4(srgbToLinear(glm::vec3(c)), std::clamp(c.a, 0.0f, 1.0f));
          if (c.a < 1.0f) range.hasTransparentColor = true;
        }
        out.vertices.push_back(vertex);
      }
      out.indices.insert(out.indices.end(), mesh.indices.begin(), mesh.indices.end());
      packed = packedMeshes.emplace(&mesh, range).first;
    }

    const Appearance* appearance = shape.appearance.get();
    const Material* material = appearance && appearance->material ? &*appearance->material : nullptr;
    const Texture* texture = appearance ? appearance->texture.get() : nullptr;
    const bool surface = mesh.topology == Topology::kTriangles;
    // VRML97 6.23, 6.36: lines and points are unlit and untextured, drawn in the
    // emissive colour (or the per-vertex colours).
    if (!surface) texture = nullptr;

    MaterialGpu m{};
    uint32_t flags = 0;
    if (material && surface) {
      m.diffuseAmbient = glm::vec4(srgbToLinear(material->diffuseColor), std::clamp(material->ambientIntensity, 0.0f, 1.0f));
      m.emissiveAlpha = glm::vec4(srgbToLinear(material->emissiveColor), 1.0f - std::clamp(material->transparency, 0.0f, 1.0f));
      m.specularShininess = glm::vec4(srgbToLinear(material->specularColor), std::clamp(material->shininess, 0.0f, 1.0f) * 128.0f);
    } else {
      flags |= kMaterialUnlit;
      const glm::vec3 color = material ? srgbToLinear(material->emissiveColor) : glm::vec3(1.0f);
      m.diffuseAmbient = glm::vec4(color, 0.0f);
      m.emissiveAlpha = glm::vec4(0.0f, 0.0f, 0.0f, material ? 1.0f - std::clamp(material->transparency, 0.0f, 1.0f) : 1.0f);
    }
    uint32_t textureSlot = 0;
    bool textureAlpha = false;
    if (texture) {
      const std::string name = texture->url.empty() ? label + "'s texture" : "texture " + texture->url;
      if (!texture->image || texture->image->empty()) return makeError(name + ": has no pixels (the image is missing or empty)");
      const Image& image = *texture->image;
      if (image.rgba.size() != static_cast<size_t>(image.width) * image.height * 4) {
        return makeError(name + ": pixel data does not match its " + std::to_string(image.width) + "x" +
                         std::to_string(image.height) + " size");
      }
      auto [slot, inserted] = textureSlots.emplace(texture, static_cast<uint32_t>(out.textures.size() + 1));
      if (inserted) {
        const bool transparent = anyTransparentTexel(image);
        out.textures.push_back({texture, transparent, !transparent && textureSourceColumns(*texture).has_value()});
      }
      textureSlot = slot->second;
      textureAlpha = out.textures[textureSlot - 1].hasAlpha;
      flags |= kMaterialTextured | (textureAlpha ? kMaterialTextureAlpha : 0u) |
               (image.grey ? kMaterialIntensityTexture : 0u);
    }
    if (!mesh.colors.empty()) flags |= kMaterialVertexColor;
    if (surface && !mesh.solid) flags |= kMaterialTwoSided;
    const bool specular = glm::any(glm::greaterThan(glm::vec3(m.specularShininess), glm::vec3(0.0f)));
    m.flags = glm::uvec4(flags, specular ? 1u : 0u, 0, 0);

    ShapeGpu gpuShape{};
    gpuShape.model = shape.transform;
    gpuShape.normalMatrix = glm::mat4(normalMatrix(shape.transform));

    DrawItem draw;
    draw.shapeIndex = static_cast<uint32_t>(out.shapes.size());
    draw.material = m;
    draw.firstIndex = packed->second.firstIndex;
    draw.indexCount = static_cast<uint32_t>(mesh.indices.size());
    draw.vertexOffset = packed->second.vertexOffset;
    draw.textureSlot = textureSlot;
    const auto source = texture ? textureSourceColumns(*texture) : std::nullopt;
    if (source) draw.textureSource = *source;
    draw.variant.topology = mesh.topology;
    draw.variant.textured = textureSlot != 0;
    // A texture cut from a photo is drawn as the photo was seen (scene.frag's
    // samplePhotoTexture): an opaque one's alpha holds the detail layer; one with
    // transparent texels (a cut-out standing in the model) keeps its alpha as coverage.
    draw.variant.photoTexture = source.has_value() && mesh.topology == Topology::kTriangles;
    draw.variant.lit = (flags & kMaterialUnlit) == 0;
    // The texture's alpha replaces the material's transparency (VRML97 4.14.3, table 4.5).
    const bool alphaFromTexture = textureAlpha;
    draw.variant.blended = alphaFromTexture || m.emissiveAlpha.a < 1.0f ||
                           (!mesh.colors.empty() && packed->second.hasTransparentColor);
    draw.cullBackFaces = surface && mesh.solid;
    draw.clockwiseFront = glm::determinant(glm::mat3(shape.transform)) < 0.0f;
    draw.worldBounds = worldBounds(shape);
    if (draw.variant.lit) {
      // Point and spot lights light nothing beyond their radius (VRML97 6.36, 6.45):
      // a shape gets those whose radius meets its bounds, not all of a building's.
      draw.lightListOffset = static_cast<uint32_t>(out.lightLists.size());
      const uint32_t firstPoint = out.lightCounts.x, firstSpot = firstPoint + out.lightCounts.y;
      for (uint32_t i = firstPoint; i < firstSpot + out.lightCounts.z; ++i) {
        const LightGpu& light = out.lights[i];
        const glm::vec3 p(light.positionType);
        const glm::vec3 nearest = glm::clamp(p, draw.worldBounds.min, draw.worldBounds.max);
        if (glm::length(p - nearest) > light.attenuationRadius.w) continue;
        out.lightLists.push_back(i);
        ++(i < firstSpot ? draw.pointLightCount : draw.spotLightCount);
      }
    }
    out.shapes.push_back(gpuShape);
    (draw.variant.blended ? out.transparent : out.opaque).push_back(draw);
  }

  // Fewest state changes: group by pipeline, then texture, then cull state.
  std::stable_sort(out.opaque.begin(), out.opaque.end(), [](const DrawItem& a, const DrawItem& b) {
    if (a.variant.index() != b.variant.index()) return a.variant.index() < b.variant.index();
    if (a.textureSlot != b.textureSlot) return a.textureSlot < b.textureSlot;
    return std::pair(a.cullBackFaces, a.clockwiseFront) < std::pair(b.cullBackFaces, b.clockwiseFront);
  });
  return out;
}

}  // namespace pw::engine::gpu
