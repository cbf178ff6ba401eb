// VRML97 geometry nodes to scene meshes (ISO/IEC 14772-1, 6.4 Box, 6.10 Cone, 6.12
// Cylinder, 6.17 ElevationGrid, 6.18 Extrusion, 6.23 IndexedFaceSet, 6.24 IndexedLineSet, 6.36
// PointSet, 6.44 Sphere), in the node's local space, with the standard's texture
// coordinate layouts.
#pragma once

#include <functional>
#include <optional>
#include <span>

#include "base/result.h"
#include "engine/scene/scene.h"
#include "engine/vrml/diagnostics.h"
#include "engine/vrml/polygon_mesh.h"
#include "engine/vrml/vrml_node.h"

namespace pw::engine::vrml {

// Turns a possibly-PROTO node into the built-in node it stands for (or null).
using NodeResolver = std::function<Result<NodePtr>(const NodePtr&)>;

// Work limits on one geometry node (a model beyond them is refused with an error
// that states the limit): so many coordIndex (or colorIndex...) entries, so many
// points of its coord or heights of an ElevationGrid. Extrusion: its spine times its
// cross-section points, at most kMaxExtrusionPoints.
inline constexpr size_t kMaxGeometryIndices = size_t{1} << 24;   // 16,777,216
inline constexpr size_t kMaxGeometryVertices = size_t{1} << 22;  // 4,194,304
inline constexpr size_t kMaxExtrusionPoints = size_t{1} << 26;   // 67,108,864

struct GeometryOptions {
  bool texCoords = false;  // the shape is textured: make texture coordinates
};

// The mesh of a geometry node, or nullopt when it draws nothing (a diagnostic says
// why: no coordinates, an unsupported node such as Text...).
Result<std::optional<Mesh>> buildGeometry(const Node& node, const NodeResolver& resolve, const GeometryOptions& options,
                                          Diagnostics* diagnostics);

// Primitives, exposed for tests. Slices around the axis; stacks along it (sphere).
Mesh makeBox(const glm::vec3& size, bool texCoords);
Mesh makeSphere(float radius, bool texCoords, int slices = 48, int stacks = 24);
Mesh makeCylinder(float radius, float height, bool side, bool top, bool bottom, bool texCoords, int slices = 48);
Mesh makeCone(float bottomRadius, float height, bool side, bool bottom, bool texCoords, int slices = 48);

// The surface fields IndexedFaceSet, ElevationGrid and Extrusion share (ccw, solid,
// creaseAngle, and convex where the node has it) on a soup of `points`.
PolygonSoup surfaceSoup(const Node& node, std::span<const glm::vec3> points);

// IndexedFaceSet, ElevationGrid (vrml_face_set.cpp).
Result<std::optional<Mesh>> buildIndexedFaceSet(const Node& node, const NodeResolver& resolve,
                                                const GeometryOptions& options, Diagnostics* diagnostics);
Result<std::optional<Mesh>> buildElevationGrid(const Node& node, const NodeResolver& resolve,
                                               const GeometryOptions& options, Diagnostics* diagnostics);
// Extrusion (vrml_extrusion.cpp).
Result<std::optional<Mesh>> buildExtrusion(const Node& node, const GeometryOptions& options, Diagnostics* diagnostics);

}  // namespace pw::engine::vrml
