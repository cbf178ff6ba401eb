// IndexedFaceSet (ISO/IEC 14772-1, 6.23) and ElevationGrid (6.17) to polygon soups.
#include <algorithm>
#include <cmath>

#include "engine/vrml/polygon_mesh.h"
#include "engine/vrml/vrml_fields.h"
#include "engine/vrml/vrml_geometry.h"

namespace pw::engine::vrml {

namespace {

template <class Vec>
std::vector<Vec> toVectors(const std::vector<float>& floats) {
  constexpr int n = Vec::length();
  std::vector<Vec> out(floats.size() / n);
  for (size_t i = 0; i < out.size(); ++i) {
    for (int k = 0; k < n; ++k) out[i][k] = floats[i * n + k];
  }
  return out;
}

// Unit normals as 6.30 asks; ones that already are (to float precision) are left
// exactly as written, so that files written by photowalk read back bit for bit.
void normalizeAll(std::vector<glm::vec3>& normals) {
  for (glm::vec3& n : normals) {
    const float length = glm::length(n);
    if (!(length > 0.0f) || !std::isfinite(length)) n = glm::vec3(0, 1, 0);
    else if (std::fabs(length - 1.0f) > 1e-5f) n /= length;
  }
}

// The array of a Coordinate / Normal / TextureCoordinate / Color node in an SFNode
// field, or empty (with `present` false) when the field is NULL or holds another type.
struct Attribute {
  bool present = false;
  const std::vector<float>* floats = nullptr;
};

Result<Attribute> attribute(const Node& owner, const char* field, const char* nodeType, const char* arrayField,
                            const NodeResolver& resolve, Diagnostics* diagnostics) {
  const NodePtr& raw = getNode(owner, field);
  if (!raw) return Attribute{};
  auto resolved = resolve(raw);
  if (!resolved) return resolved.error();
  const NodePtr& node = *resolved;
  if (!node) return Attribute{};
  if (node->typeName() != nodeType) {
    if (diagnostics) {
      diagnostics->warn(node->where() + ": " + owner.typeName() + "." + field + " wants a " + nodeType + ", not a " +
                        node->typeName() + "; ignored");
    }
    return Attribute{};
  }
  return Attribute{true, &getFloats(*node, arrayField)};
}

// Default texture coordinates of 6.23: s along the bounding box's longest side from 0
// to 1, t along the second longest from 0 to its length over the longest.
std::vector<glm::vec2> boxTexCoords(const std::vector<glm::vec3>& points) {
  Bounds b;
  for (const glm::vec3& p : points) b.add(p);
  std::vector<glm::vec2> out(points.size(), glm::vec2(0.0f));
  if (b.empty()) return out;
  const glm::vec3 size = b.size();
  // Ties go to X, then Y, then Z.
  int axes[3] = {0, 1, 2};
  std::stable_sort(axes, axes + 3, [&](int a, int c) { return size[a] > size[c]; });
  const int sAxis = axes[0], tAxis = axes[1];
  const float longest = size[sAxis];
  if (!(longest > 0.0f)) return out;
  for (size_t i = 0; i < points.size(); ++i) {
    out[i] = {(points[i][sAxis] - b.min[sAxis]) / longest, (points[i][tAxis] - b.min[tAxis]) / longest};
  }
  return out;
}

// Per-corner indices of an attribute from its index list, following 6.23: per vertex
// with an index list laid out like coordIndex, per vertex by coordIndex, per face with
// an index list (one per face) or per face in order. False if an index is out of range.
bool cornerIndices(const std::vector<int32_t>& index, bool perVertex, size_t arraySize,
                   const std::vector<uint32_t>& cornerListPos, const std::vector<uint32_t>& cornerCoord,
                   const std::vector<uint32_t>& cornerFace, const std::vector<uint32_t>& faceListIndex,
                   std::vector<uint32_t>& out, std::string& problem) {
  out.resize(cornerCoord.size());
  for (size_t c = 0; c < cornerCoord.size(); ++c) {
    int64_t i;
    if (perVertex) {
      if (index.empty()) i = cornerCoord[c];
      else if (cornerListPos[c] < index.size()) i = index[cornerListPos[c]];
      else {
        problem = "its index list is shorter than coordIndex";
        return false;
      }
    } else {
      const uint32_t face = faceListIndex[cornerFace[c]];
      if (index.empty()) i = face;
      else if (face < index.size()) i = index[face];
      else {
        problem = "its index list has fewer entries than there are faces";
        return false;
      }
    }
    if (i < 0 || static_cast<uint64_t>(i) >= arraySize) {
      problem = "index " + std::to_string(i) + " is out of range (it has " + std::to_string(arraySize) + " values)";
      return false;
    }
    out[c] = static_cast<uint32_t>(i);
  }
  return true;
}

}  // namespace

PolygonSoup surfaceSoup(const Node& node, std::span<const glm::vec3> points) {
  PolygonSoup soup;
  soup.points = points;
  soup.ccw = getBool(node, "ccw");
  // ElevationGrid has no convex field: its cells are quads, convex.
  soup.convex = node.typeName() == "ElevationGrid" || getBool(node, "convex");
  soup.solid = getBool(node, "solid");
  soup.creaseAngle = getDouble(node, "creaseAngle");
  return soup;
}

Result<std::optional<Mesh>> buildIndexedFaceSet(const Node& node, const NodeResolver& resolve,
                                                const GeometryOptions& options, Diagnostics* diagnostics) {
  auto coordAttr = attribute(node, "coord", "Coordinate", "point", resolve, diagnostics);
  if (!coordAttr) return coordAttr.error();
  if (!coordAttr->present || coordAttr->floats->empty()) {
    if (diagnostics) diagnostics->note(node.where() + ": IndexedFaceSet without coordinates draws nothing");
    return std::optional<Mesh>{};
  }
  const std::vector<glm::vec3> points = toVectors<glm::vec3>(*coordAttr->floats);
  const std::vector<int32_t>& coordIndex = getInts(node, "coordIndex");

  PolygonSoup soup = surfaceSoup(node, points);

  // Faces: runs of coordIndex ended by -1 (or the end of the list).
  std::vector<uint32_t> cornerListPos, cornerFace, faceListIndex;
  uint32_t listFace = 0;  // face number counting every run, also the skipped ones
  size_t badFaces = 0;
  size_t runStart = 0;
  for (size_t i = 0; i <= coordIndex.size(); ++i) {
    if (i < coordIndex.size() && coordIndex[i] != -1) continue;
    const size_t count = i - runStart;
    if (count > 0) {
      bool valid = count >= 3;
      for (size_t k = runStart; k < i && valid; ++k) {
        valid = coordIndex[k] >= 0 && static_cast<size_t>(coordIndex[k]) < points.size();
      }
      if (valid) {
        for (size_t k = runStart; k < i; ++k) {
          soup.coord.push_back(static_cast<uint32_t>(coordIndex[k]));
          cornerListPos.push_back(static_cast<uint32_t>(k));
          cornerFace.push_back(static_cast<uint32_t>(soup.faceCount()));
        }
        soup.addFace();
        faceListIndex.push_back(listFace);
      } else {
        ++badFaces;
      }
      ++listFace;
    }
    runStart = i + 1;
  }
  if (badFaces > 0 && diagnostics) {
    diagnostics->warn(node.where() + ": " + std::to_string(badFaces) +
                      " face(s) of the IndexedFaceSet have fewer than 3 corners or an index outside its " +
                      std::to_string(points.size()) + " points; skipped");
  }
  if (soup.faceCount() == 0) return std::optional<Mesh>{};

  std::string problem;
  auto warnDropped = [&](const char* what) {
    if (diagnostics) diagnostics->warn(node.where() + ": IndexedFaceSet " + what + " ignored: " + problem);
  };

  std::vector<glm::vec3> normals;
  auto normalAttr = attribute(node, "normal", "Normal", "vector", resolve, diagnostics);
  if (!normalAttr) return normalAttr.error();
  if (normalAttr->present) {
    normals = toVectors<glm::vec3>(*normalAttr->floats);
    normalizeAll(normals);
    if (cornerIndices(getInts(node, "normalIndex"), getBool(node, "normalPerVertex"), normals.size(), cornerListPos,
                      soup.coord, cornerFace, faceListIndex, soup.normalIndex, problem)) {
      soup.normals = normals;
    } else {
      soup.normalIndex.clear();
      warnDropped("normals");
    }
  }

  std::vector<glm::vec3> colors;
  auto colorAttr = attribute(node, "color", "Color", "color", resolve, diagnostics);
  if (!colorAttr) return colorAttr.error();
  if (colorAttr->present) {
    colors = toVectors<glm::vec3>(*colorAttr->floats);
    if (cornerIndices(getInts(node, "colorIndex"), getBool(node, "colorPerVertex"), colors.size(), cornerListPos,
                      soup.coord, cornerFace, faceListIndex, soup.colorIndex, problem)) {
      soup.colors = colors;
    } else {
      soup.colorIndex.clear();
      warnDropped("colors");
    }
  }

  std::vector<glm::vec2> texCoords;
  if (options.texCoords) {
    auto texAttr = attribute(node, "texCoord", "TextureCoordinate", "point", resolve, diagnostics);
    if (!texAttr) return texAttr.error();
    if (texAttr->present) {
      texCoords = toVectors<glm::vec2>(*texAttr->floats);
      if (!cornerIndices(getInts(node, "texCoordIndex"), true, texCoords.size(), cornerListPos, soup.coord, cornerFace,
                         faceListIndex, soup.texCoordIndex, problem)) {
        soup.texCoordIndex.clear();
        warnDropped("texture coordinates");
      }
    }
    if (soup.texCoordIndex.empty()) {
      texCoords = boxTexCoords(points);
      soup.texCoordIndex = soup.coord;
    }
    soup.texCoords = texCoords;
  }
  return std::optional<Mesh>(buildPolygonMesh(soup));
}

Result<std::optional<Mesh>> buildElevationGrid(const Node& node, const NodeResolver& resolve,
                                               const GeometryOptions& options, Diagnostics* diagnostics) {
  const int32_t xDim = getInt(node, "xDimension"), zDim = getInt(node, "zDimension");
  const std::vector<float>& height = getFloats(node, "height");
  if (xDim < 2 || zDim < 2) {
    if (diagnostics) diagnostics->note(node.where() + ": ElevationGrid smaller than 2x2 draws nothing");
    return std::optional<Mesh>{};
  }
  const int64_t count = int64_t{xDim} * zDim;
  if (static_cast<int64_t>(height.size()) < count) {
    if (diagnostics) {
      diagnostics->warn(node.where() + ": ElevationGrid " + std::to_string(xDim) + "x" + std::to_string(zDim) +
                        " needs " + std::to_string(count) + " heights but has " + std::to_string(height.size()) +
                        "; skipped");
    }
    return std::optional<Mesh>{};
  }
  const float dx = static_cast<float>(getDouble(node, "xSpacing")), dz = static_cast<float>(getDouble(node, "zSpacing"));
  std::vector<glm::vec3> points(static_cast<size_t>(count));
  std::vector<glm::vec2> grid(static_cast<size_t>(count));
  for (int32_t j = 0; j < zDim; ++j) {
    for (int32_t i = 0; i < xDim; ++i) {
      const size_t k = static_cast<size_t>(j) * xDim + i;
      points[k] = {dx * i, height[k], dz * j};
      grid[k] = {static_cast<float>(i) / (xDim - 1), static_cast<float>(j) / (zDim - 1)};
    }
  }
  PolygonSoup soup = surfaceSoup(node, points);
  std::vector<uint32_t> cornerFace;
  for (int32_t j = 0; j + 1 < zDim; ++j) {
    for (int32_t i = 0; i + 1 < xDim; ++i) {
      const uint32_t a = static_cast<uint32_t>(j * xDim + i);
      // Counter-clockwise seen from above (+Y): (i,j) (i,j+1) (i+1,j+1) (i+1,j).
      for (uint32_t c : {a, a + static_cast<uint32_t>(xDim), a + static_cast<uint32_t>(xDim) + 1, a + 1}) {
        soup.coord.push_back(c);
        cornerFace.push_back(static_cast<uint32_t>(soup.faceCount()));
      }
      soup.addFace();
    }
  }
  auto perCorner = [&](bool perVertex, size_t arraySize, std::vector<uint32_t>& out, const char* what) {
    const size_t needed = perVertex ? points.size() : soup.faceCount();
    if (arraySize < needed) {
      if (diagnostics) {
        diagnostics->warn(node.where() + ": ElevationGrid has " + std::to_string(arraySize) + " " + what + " for " +
                          std::to_string(needed) + (perVertex ? " points" : " cells") + "; ignored");
      }
      return false;
    }
    out.resize(soup.coord.size());
    for (size_t c = 0; c < soup.coord.size(); ++c) out[c] = perVertex ? soup.coord[c] : cornerFace[c];
    return true;
  };
  std::vector<glm::vec3> normals, colors;
  std::vector<glm::vec2> texCoords;
  auto normalAttr = attribute(node, "normal", "Normal", "vector", resolve, diagnostics);
  if (!normalAttr) return normalAttr.error();
  if (normalAttr->present) {
    normals = toVectors<glm::vec3>(*normalAttr->floats);
    normalizeAll(normals);
    if (perCorner(getBool(node, "normalPerVertex"), normals.size(), soup.normalIndex, "normals")) soup.normals = normals;
  }
  auto colorAttr = attribute(node, "color", "Color", "color", resolve, diagnostics);
  if (!colorAttr) return colorAttr.error();
  if (colorAttr->present) {
    colors = toVectors<glm::vec3>(*colorAttr->floats);
    if (perCorner(getBool(node, "colorPerVertex"), colors.size(), soup.colorIndex, "colors")) soup.colors = colors;
  }
  if (options.texCoords) {
    auto texAttr = attribute(node, "texCoord", "TextureCoordinate", "point", resolve, diagnostics);
    if (!texAttr) return texAttr.error();
    if (texAttr->present) {
      texCoords = toVectors<glm::vec2>(*texAttr->floats);
      if (!perCorner(true, texCoords.size(), soup.texCoordIndex, "texture coordinates")) texCoords.clear();
    }
    if (texCoords.empty()) {
      texCoords = grid;
      soup.texCoordIndex = soup.coord;
    }
    soup.texCoords = texCoords;
  }
  return std::optional<Mesh>(buildPolygonMesh(soup));
}

}  // namespace pw::engine::vrml
