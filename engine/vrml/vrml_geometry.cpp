#include "engine/vrml/vrml_geometry.h"

#include <cmath>
#include <unordered_map>

#include "engine/vrml/vrml_fields.h"

namespace pw::engine::vrml {

namespace {

Result<const std::vector<float>*> arrayOf(const Node& owner, const char* field, const char* nodeType,
                                          const char* arrayField, const NodeResolver& resolve,
                                          Diagnostics* diagnostics) {
  const NodePtr& raw = getNode(owner, field);
  if (!raw) return static_cast<const std::vector<float>*>(nullptr);
  auto node = resolve(raw);
  if (!node) return node.error();
  if (!*node) return static_cast<const std::vector<float>*>(nullptr);
  if ((*node)->typeName() != nodeType) {
    if (diagnostics) {
      diagnostics->warn((*node)->where() + ": " + owner.typeName() + "." + field + " wants a " + nodeType +
                        ", not a " + (*node)->typeName() + "; ignored");
    }
    return static_cast<const std::vector<float>*>(nullptr);
  }
  return &getFloats(**node, arrayField);
}

glm::vec3 vec3At(const std::vector<float>& f, size_t i) { return {f[3 * i], f[3 * i + 1], f[3 * i + 2]}; }

// IndexedLineSet (6.24): polylines ended by -1, drawn as line segments. The points are
// the vertices as they are unless colours are per polyline or separately indexed;
// then a vertex is made per distinct (point, colour).
Result<std::optional<Mesh>> buildLineSet(const Node& node, const NodeResolver& resolve, Diagnostics* diagnostics) {
  auto coords = arrayOf(node, "coord", "Coordinate", "point", resolve, diagnostics);
  if (!coords) return coords.error();
  auto colors = arrayOf(node, "color", "Color", "color", resolve, diagnostics);
  if (!colors) return colors.error();
  if (!*coords || (*coords)->empty()) return std::optional<Mesh>{};
  const std::vector<float>& points = **coords;
  const size_t pointCount = points.size() / 3;
  const std::vector<int32_t>& coordIndex = getInts(node, "coordIndex");
  const std::vector<int32_t>& colorIndex = getInts(node, "colorIndex");
  const bool perVertex = getBool(node, "colorPerVertex");
  const size_t colorCount = *colors ? (*colors)->size() / 3 : 0;
  const bool direct = colorCount == 0 || (perVertex && colorIndex.empty() && colorCount >= pointCount);

  Mesh mesh;
  mesh.topology = Topology::kLines;
  mesh.solid = false;
  std::unordered_map<uint64_t, uint32_t> vertexOf;  // (point << 32 | colour) -> vertex
  if (direct) {
    for (size_t i = 0; i < pointCount; ++i) mesh.positions.push_back(vec3At(points, i));
    for (size_t i = 0; colorCount && i < pointCount; ++i) mesh.colors.emplace_back(vec3At(**colors, i), 1.0f);
  }
  size_t skipped = 0, badColors = 0;
  uint32_t polyline = 0;
  uint32_t previous = UINT32_MAX;
  for (size_t i = 0; i <= coordIndex.size(); ++i) {
    if (i == coordIndex.size() || coordIndex[i] == -1) {
      if (i > 0 && coordIndex[i - 1] != -1) ++polyline;
      previous = UINT32_MAX;
      continue;
    }
    const int32_t p = coordIndex[i];
    if (p < 0 || static_cast<size_t>(p) >= pointCount) {
      ++skipped;
      previous = UINT32_MAX;
      continue;
    }
    uint32_t v = static_cast<uint32_t>(p);
    if (!direct) {
      const int64_t c = perVertex ? (colorIndex.empty() ? p : (i < colorIndex.size() ? colorIndex[i] : -1))
                                  : (colorIndex.empty() ? polyline
                                                        : (polyline < colorIndex.size() ? colorIndex[polyline] : -1));
      const bool validColor = c >= 0 && static_cast<size_t>(c) < colorCount;
      badColors += validColor ? 0 : 1;
      const uint32_t color = validColor ? static_cast<uint32_t>(c) : 0;
      auto [it, inserted] = vertexOf.try_emplace((uint64_t{v} << 32) | color, static_cast<uint32_t>(mesh.positions.size()));
      if (inserted) {
        mesh.positions.push_back(vec3At(points, v));
        mesh.colors.emplace_back(vec3At(**colors, color), 1.0f);
      }
      v = it->second;
    }
    if (previous != UINT32_MAX) mesh.indices.insert(mesh.indices.end(), {previous, v});
    previous = v;
  }
  if (skipped && diagnostics) {
    diagnostics->warn(node.where() + ": " + std::to_string(skipped) + " IndexedLineSet index(es) outside its " +
                      std::to_string(pointCount) + " points; skipped");
  }
  if (badColors && diagnostics) {
    diagnostics->warn(node.where() + ": " + std::to_string(badColors) +
                      " IndexedLineSet colour index(es) out of range; the first colour is used");
  }
  if (mesh.indices.empty()) return std::optional<Mesh>{};
  return std::optional<Mesh>(std::move(mesh));
}

// PointSet (6.36): every point, coloured per point.
Result<std::optional<Mesh>> buildPointSet(const Node& node, const NodeResolver& resolve, Diagnostics* diagnostics) {
  auto coords = arrayOf(node, "coord", "Coordinate", "point", resolve, diagnostics);
  if (!coords) return coords.error();
  auto colors = arrayOf(node, "color", "Color", "color", resolve, diagnostics);
  if (!colors) return colors.error();
  if (!*coords || (*coords)->empty()) return std::optional<Mesh>{};
  Mesh mesh;
  mesh.topology = Topology::kPoints;
  mesh.solid = false;
  const size_t count = (*coords)->size() / 3;
  for (size_t i = 0; i < count; ++i) {
    mesh.positions.push_back(vec3At(**coords, i));
    mesh.indices.push_back(static_cast<uint32_t>(i));
  }
  if (*colors) {
    if ((*colors)->size() / 3 >= count) {
      for (size_t i = 0; i < count; ++i) mesh.colors.emplace_back(vec3At(**colors, i), 1.0f);
    } else if (diagnostics) {
      diagnostics->warn(node.where() + ": PointSet has fewer colours than points; colours ignored");
    }
  }
  return std::optional<Mesh>(std::move(mesh));
}

// The work limits of vrml_geometry.h, before any of the work: index lists, points,
// an ElevationGrid's grid.
Status checkGeometrySize(const Node& node, const NodeResolver& resolve) {
  const std::string& type = node.typeName();
  const auto tooMany = [&](const std::string& what, size_t count, size_t limit) {
    return makeError(node.where() + ": " + type + " has " + std::to_string(count) + " " + what +
                     ", more than photowalk accepts (at most " + std::to_string(limit) + ")");
  };
  if (type == "IndexedFaceSet" || type == "IndexedLineSet") {
    const bool faces = type == "IndexedFaceSet";
    for (const char* field : {"coordIndex", "colorIndex", "normalIndex", "texCoordIndex"}) {
      if (!faces && (field[0] == 'n' || field[0] == 't')) continue;  // IndexedLineSet has neither
      const size_t count = getInts(node, field).size();
      if (count > kMaxGeometryIndices) return tooMany(std::string(field) + " entries", count, kMaxGeometryIndices);
    }
  }
  if (type == "IndexedFaceSet" || type == "IndexedLineSet" || type == "PointSet") {
    if (const NodePtr& raw = getNode(node, "coord")) {
      auto coord = resolve(raw);
      if (coord && *coord && (*coord)->typeName() == "Coordinate") {
        const size_t points = getFloats(**coord, "point").size() / 3;
        if (points > kMaxGeometryVertices) return tooMany("coord points", points, kMaxGeometryVertices);
      }
    }
  }
  if (type == "ElevationGrid") {
    const int64_t x = getInt(node, "xDimension"), z = getInt(node, "zDimension");
    if (x > 0 && z > 0 && static_cast<uint64_t>(x) * static_cast<uint64_t>(z) > kMaxGeometryVertices) {
      return makeError(node.where() + ": ElevationGrid of " + std::to_string(x) + " x " + std::to_string(z) +
                       " heights is more than photowalk accepts (at most " + std::to_string(kMaxGeometryVertices) + ")");
    }
    const size_t heights = getFloats(node, "height").size();
    if (heights > kMaxGeometryVertices) return tooMany("heights", heights, kMaxGeometryVertices);
  }
  return {};
}

float positive(double value) { return std::isfinite(value) ? static_cast<float>(value) : 0.0f; }

}  // namespace

Result<std::optional<Mesh>> buildGeometry(const Node& node, const NodeResolver& resolve, const GeometryOptions& options,
                                          Diagnostics* diagnostics) {
  const std::string& type = node.typeName();
  const bool tex = options.texCoords;
  PW_TRY(checkGeometrySize(node, resolve));
  if (type == "IndexedFaceSet") return buildIndexedFaceSet(node, resolve, options, diagnostics);
  if (type == "Box") {
    const glm::dvec3 size = getVec3(node, "size");
    return std::optional<Mesh>(makeBox(glm::vec3(positive(size.x), positive(size.y), positive(size.z)), tex));
  }
  if (type == "Sphere") return std::optional<Mesh>(makeSphere(positive(getDouble(node, "radius")), tex));
  if (type == "Cylinder") {
    return std::optional<Mesh>(makeCylinder(positive(getDouble(node, "radius")), positive(getDouble(node, "height")),
                                            getBool(node, "side"), getBool(node, "top"), getBool(node, "bottom"), tex));
  }
  if (type == "Cone") {
    return std::optional<Mesh>(makeCone(positive(getDouble(node, "bottomRadius")), positive(getDouble(node, "height")),
                                        getBool(node, "side"), getBool(node, "bottom"), tex));
  }
  if (type == "IndexedLineSet") return buildLineSet(node, resolve, diagnostics);
  if (type == "PointSet") return buildPointSet(node, resolve, diagnostics);
  if (type == "ElevationGrid") return buildElevationGrid(node, resolve, options, diagnostics);
  if (type == "Extrusion") return buildExtrusion(node, options, diagnostics);
  if (diagnostics) {
    if (type == "Text") {
      diagnostics->warn(node.where() + ": Text is drawn by the scene builder (vrml_text.h), not as a mesh");
    } else {
      diagnostics->warn(node.where() + ": a " + type + " is not a geometry node; the shape is skipped");
    }
  }
  return std::optional<Mesh>{};
}

}  // namespace pw::engine::vrml
