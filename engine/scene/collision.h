// Spatial queries on a scene's triangles, in world space: ray casts (the tests'
// "is this opening really open", the walkthrough's ground under the feet) and a
// sphere that slides along walls without passing through them (the walkthrough's
// avatar). A bounding-volume hierarchy keeps both fast on large buildings.
#pragma once

#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "engine/scene/scene.h"

namespace pw::engine {

class CollisionWorld {
 public:
  // Takes every triangle of every shape (lines and points are ignored).
  static CollisionWorld fromScene(const Scene& scene);

  struct Hit {
    float distance = 0;     // along the ray, metres
    glm::vec3 point{0.0f};
    glm::vec3 normal{0.0f};  // unit, facing the ray's origin
  };

  // Nearest triangle hit by the ray within maxDistance; `direction` need not be unit.
  std::optional<Hit> raycast(const glm::vec3& origin, const glm::vec3& direction, float maxDistance) const;

  // Moves a sphere of `radius` from `center` by `delta` and returns where it ends:
  // touching triangles it slides along them, and it never crosses a triangle, however
  // thin the wall and however long the step (the move is split into sub-steps
  // shorter than half the radius).
  glm::vec3 slideSphere(const glm::vec3& center, float radius, const glm::vec3& delta) const;

  size_t triangleCount() const { return triangles_.size(); }

  // The shape of the bounding-volume hierarchy, read-only, for tests and statistics.
  // depth counts levels (a lone leaf is 1, an empty world 0). The traversals keep a
  // fixed stack of 64 entries, so a tree much deeper than log2(triangles) would skip
  // nodes; the build's median split keeps depth at ceil(log2(triangles / 4)) + 1.
  struct TreeStats {
    uint32_t depth = 0;
    uint32_t nodes = 0;
    uint32_t leaves = 0;
    uint32_t largestLeaf = 0;  // most triangles in one leaf
    uint32_t leafTriangles = 0;  // triangles over all leaves (each triangle in one leaf)
  };
  TreeStats treeStats() const;

 private:
  struct Triangle {
    glm::vec3 a, b, c;
  };
  struct Node {
    Bounds bounds;
    uint32_t first = 0;  // leaf: first triangle index in order_; inner: left child
    uint32_t count = 0;  // leaf: triangle count; inner: 0 (right child = left + 1)
  };

  void build();
  template <class Visit>
  void visitOverlapping(const Bounds& box, Visit&& visit) const;
  // Pushes the sphere out of every triangle it overlaps; true if it moved.
  bool resolvePenetration(glm::vec3& center, float radius) const;

  std::vector<Triangle> triangles_;
  std::vector<uint32_t> order_;
  std::vector<Node> nodes_;
};

// Closest point to p on triangle abc (Ericson, Real-Time Collision Detection, 5.1.5).
glm::vec3 closestPointOnTriangle(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c);

}  // namespace pw::engine
