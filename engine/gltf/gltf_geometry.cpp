// Vertex and index data: accessors over the binary buffer, one set per shared Mesh.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "engine/gltf/gltf_document.h"
#include "engine/gltf/gltf_mapping.h"

namespace pw::engine::gltf {

namespace {

bool finite(const glm::vec2& v) { return std::isfinite(v.x) && std::isfinite(v.y); }
bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool finite(const glm::vec4& v) { return finite(glm::vec3(v)) && std::isfinite(v.w); }

template <class V>
Status checkAttribute(const std::vector<V>& values, size_t vertexCount, const char* what, const std::string& label) {
  if (!values.empty() && values.size() != vertexCount) {
    return makeError(label + ": has " + std::to_string(values.size()) + " " + what + " for " +
                     std::to_string(vertexCount) + " vertices; give one per vertex or none");
  }
  for (size_t i = 0; i < values.size(); ++i) {
    if (!finite(values[i])) {
      return makeError(label + ": " + what + " of vertex " + std::to_string(i) + " is not a finite number");
    }
  }
  return {};
}

Status checkMesh(const Mesh& mesh, const std::string& label) {
  const size_t n = mesh.positions.size();
  if (n >= std::numeric_limits<uint32_t>::max()) return makeError(label + ": too many vertices for glTF");
  PW_TRY(checkAttribute(mesh.positions, n, "position", label));
  PW_TRY(checkAttribute(mesh.normals, n, "normal", label));
  PW_TRY(checkAttribute(mesh.texCoords, n, "texture coordinate", label));
  PW_TRY(checkAttribute(mesh.colors, n, "colour", label));
  for (size_t i = 0; i < mesh.indices.size(); ++i) {
    if (mesh.indices[i] >= n) {
      return makeError(label + ": index " + std::to_string(i) + " is " + std::to_string(mesh.indices[i]) +
                       " but the mesh has only " + std::to_string(n) + " vertices");
    }
  }
  const size_t perPrimitive = mesh.topology == Topology::kTriangles ? 3 : mesh.topology == Topology::kLines ? 2 : 1;
  if (mesh.indices.size() % perPrimitive != 0) {
    return makeError(label + ": " + std::to_string(mesh.indices.size()) + " indices is not a whole number of " +
                     (perPrimitive == 3 ? "triangles" : "line segments"));
  }
  return {};
}

// Unit normals, as glTF requires (3.7.2.1). A zero normal (from degenerate input)
// takes the area-weighted normal of the triangles around the vertex instead.
std::vector<glm::vec3> unitNormals(const Mesh& mesh) {
  // Divide by the largest component first: squaring 1e30 would overflow to infinity.
  auto unit = [](glm::vec3 n) -> std::optional<glm::vec3> {
    const float largest = std::max({std::abs(n.x), std::abs(n.y), std::abs(n.z)});
    if (!(largest > 0.0f) || !std::isfinite(largest)) return std::nullopt;
    n /= largest;
    return n / glm::length(n);
  };
  std::vector<glm::vec3> normals(mesh.normals.size());
  std::vector<glm::vec3> smooth;
  for (size_t i = 0; i < normals.size(); ++i) {
    if (const auto n = unit(mesh.normals[i])) {
      normals[i] = *n;
      continue;
    }
    if (smooth.empty()) {
      Mesh copy;
      copy.positions = mesh.positions;
      if (mesh.topology == Topology::kTriangles) copy.indices = mesh.indices;
      computeSmoothNormals(copy);  // (0, 0, 1) where no triangle touches the vertex
      smooth = std::move(copy.normals);
    }
    // Triangles of astronomical size overflow even there: then any unit vector will do.
    normals[i] = unit(smooth[i]).value_or(glm::vec3(0.0f, 0.0f, 1.0f));
  }
  return normals;
}

int modeOf(Topology topology) {
  switch (topology) {
    case Topology::kPoints: return 0;
    case Topology::kLines: return 1;
    case Topology::kTriangles: break;
  }
  return 4;
}

Json vec3Json(const glm::vec3& v) { return Json::array({double(v.x), double(v.y), double(v.z)}); }

}  // namespace

int DocumentBuilder::addView(const void* bytes, size_t size, std::optional<int> target) {
  // Every view starts on a 4-byte boundary: the strictest alignment any accessor
  // needs (glTF 2.0, 3.6.2.4), and vertex attributes must be 4-aligned anyway.
  bin_.resize((bin_.size() + 3) & ~size_t{3}, 0);
  const size_t offset = bin_.size();
  bin_.resize(offset + size);
  if (size > 0) std::memcpy(bin_.data() + offset, bytes, size);
  Json view = {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", size}};
  if (target) view["target"] = *target;
  doc_["bufferViews"].push_back(std::move(view));
  return static_cast<int>(doc_["bufferViews"].size()) - 1;
}

int DocumentBuilder::addAccessor(int view, int componentType, size_t count, const char* type, Json min, Json max) {
  Json accessor = {{"bufferView", view}, {"componentType", componentType}, {"count", count}, {"type", type}};
  if (!min.is_null()) accessor["min"] = std::move(min);
  if (!max.is_null()) accessor["max"] = std::move(max);
  doc_["accessors"].push_back(std::move(accessor));
  return static_cast<int>(doc_["accessors"].size()) - 1;
}

Result<DocumentBuilder::MeshData*> DocumentBuilder::meshDataFor(const Mesh& mesh, const std::string& label) {
  if (auto found = meshData_.find(&mesh); found != meshData_.end()) return &found->second;
  PW_TRY(checkMesh(mesh, label));
  MeshData data;
  const size_t n = mesh.positions.size();

  // POSITION needs min and max (glTF 2.0, 3.7.2.1), equal to the stored floats.
  const Bounds bounds = localBounds(mesh);
  const int positionView = addView(mesh.positions.data(), n * sizeof(glm::vec3), kTargetArrayBuffer);
  data.position = addAccessor(positionView, kComponentFloat, n, "VEC3", vec3Json(bounds.min), vec3Json(bounds.max));

  if (!mesh.normals.empty()) {
    const std::vector<glm::vec3> normals = unitNormals(mesh);
    data.normal = addAccessor(addView(normals.data(), n * sizeof(glm::vec3), kTargetArrayBuffer), kComponentFloat, n,
                              "VEC3");
  }
  if (!mesh.colors.empty()) {
    // COLOR_0 is linear and must lie in [0, 1]; alpha is not gamma-encoded.
    std::vector<glm::vec4> colors(n);
    for (size_t i = 0; i < n; ++i) {
      colors[i] = glm::vec4(linearFromSrgb(glm::vec3(mesh.colors[i])), std::clamp(mesh.colors[i].w, 0.0f, 1.0f));
      data.translucentColors = data.translucentColors || colors[i].w < 1.0f;
    }
    data.color = addAccessor(addView(colors.data(), n * sizeof(glm::vec4), kTargetArrayBuffer), kComponentFloat, n,
                             "VEC4");
  }
  if (!mesh.indices.empty()) {
    // uint16 while every index stays below 65535, the primitive restart value that
    // glTF forbids in index data (3.7.2.1).
    const size_t count = mesh.indices.size();
    if (n <= 65535) {
      std::vector<uint16_t> narrow(mesh.indices.begin(), mesh.indices.end());
      data.indices = addAccessor(addView(narrow.data(), count * sizeof(uint16_t), kTargetElementArrayBuffer),
                                 kComponentUint16, count, "SCALAR");
    } else {
      data.indices = addAccessor(addView(mesh.indices.data(), count * sizeof(uint32_t), kTargetElementArrayBuffer),
                                 kComponentUint32, count, "SCALAR");
    }
  }
  return &meshData_.emplace(&mesh, data).first->second;
}

int DocumentBuilder::texCoordsFor(const Mesh& mesh, MeshData& data) {
  if (data.texCoord >= 0) return data.texCoord;
  std::vector<glm::vec2> uv = mesh.texCoords.empty() ? defaultTexCoords(mesh.positions) : mesh.texCoords;
  // VRML's t = 0 is the bottom row of the image, glTF's v = 0 the top row (3.8.4.1).
  for (glm::vec2& st : uv) st.y = 1.0f - st.y;
  data.texCoord = addAccessor(addView(uv.data(), uv.size() * sizeof(glm::vec2), kTargetArrayBuffer), kComponentFloat,
                              uv.size(), "VEC2");
  return data.texCoord;
}

Result<int> DocumentBuilder::meshFor(const Mesh& mesh, const Appearance* appearance, const std::string& label) {
  auto data = meshDataFor(mesh, label);
  if (!data) return data.error();
  MeshData& meshData = **data;
  const int material = materialFor(appearance, mesh, meshData);
  const auto key = std::make_pair(&mesh, material);
  if (auto found = meshes_.find(key); found != meshes_.end()) return found->second;

  const bool textured = doc_["materials"][material]["pbrMetallicRoughness"].contains("baseColorTexture");
  Json attributes = {{"POSITION", meshData.position}};
  if (meshData.normal >= 0) attributes["NORMAL"] = meshData.normal;
  if (textured) attributes["TEXCOORD_0"] = texCoordsFor(mesh, meshData);
  // VRML97 6.5, table 6.5: an RGB texture replaces the colours; they stay otherwise.
  if (meshData.color >= 0 && !textured) attributes["COLOR_0"] = meshData.color;
  Json primitive = {{"attributes", std::move(attributes)}, {"material", material}, {"mode", modeOf(mesh.topology)}};
  if (meshData.indices >= 0) primitive["indices"] = meshData.indices;
  doc_["meshes"].push_back(Json{{"primitives", Json::array({std::move(primitive)})}});
  const int index = static_cast<int>(doc_["meshes"].size()) - 1;
  meshes_.emplace(key, index);
  return index;
}


Mesh mirroredInX(const Mesh& mesh) {
  Mesh mirrored = mesh;
  for (glm::vec3& p : mirrored.positions) p.x = -p.x;
  for (glm::vec3& n : mirrored.normals) n.x = -n.x;
  if (mirrored.topology == Topology::kTriangles) {
    for (size_t i = 0; i + 2 < mirrored.indices.size(); i += 3) {
      std::swap(mirrored.indices[i + 1], mirrored.indices[i + 2]);
    }
  }
  return mirrored;
}

std::optional<Mesh> bakeTransform(const Mesh& mesh, const glm::mat4& transform) {
  const glm::mat3 linear(transform);
  const float det = glm::determinant(linear);
  const bool singular = flattens(transform);
  if (singular && mesh.topology == Topology::kTriangles) return std::nullopt;
  Mesh baked = mesh;
  for (glm::vec3& p : baked.positions) {
    const glm::vec4 h = transform * glm::vec4(p, 1.0f);
    p = glm::vec3(h) / h.w;  // w != 1 only for a projective transform; w = 0 is caught as non-finite
  }
  if (singular) {
    baked.normals.clear();
  } else {
    // Normals transform by the inverse transpose (they stay perpendicular to surfaces).
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(linear));
    for (glm::vec3& n : baked.normals) n = normalMatrix * n;  // made unit when written
  }
  // A mirroring transform turns counter-clockwise triangles clockwise; a node's
  // negative determinant would have told the viewer (glTF 2.0, 3.7.4), baked vertices
  // cannot, so the winding is reversed instead.
  if (det < 0 && mesh.topology == Topology::kTriangles) {
    for (size_t i = 0; i + 2 < baked.indices.size(); i += 3) std::swap(baked.indices[i + 1], baked.indices[i + 2]);
  }
  return baked;
}

}  // namespace pw::engine::gltf
