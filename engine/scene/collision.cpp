#include "engine/scene/collision.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

namespace pw::engine {
namespace {

constexpr uint32_t kLeafSize = 4;

Bounds triangleBounds(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
  Bounds box;
  box.add(a);
  box.add(b);
  box.add(c);
  return box;
}

bool overlaps(const Bounds& x, const Bounds& y) {
  return x.min.x <= y.max.x && x.max.x >= y.min.x && x.min.y <= y.max.y && x.max.y >= y.min.y &&
         x.min.z <= y.max.z && x.max.z >= y.min.z;
}

// Slab test; returns the entry distance or a negative number when missed.
float rayBox(const glm::vec3& origin, const glm::vec3& inverseDir, const Bounds& box, float maxDistance) {
  const glm::vec3 t0 = (box.min - origin) * inverseDir;
  const glm::vec3 t1 = (box.max - origin) * inverseDir;
  const glm::vec3 tNear = glm::min(t0, t1), tFar = glm::max(t0, t1);
  const float enter = std::max({tNear.x, tNear.y, tNear.z, 0.0f});
  const float exit = std::min({tFar.x, tFar.y, tFar.z, maxDistance});
  return enter <= exit ? enter : -1.0f;
}

// Möller-Trumbore, both faces.
std::optional<float> rayTriangle(const glm::vec3& o, const glm::vec3& d, const glm::vec3& a, const glm::vec3& b,
                                 const glm::vec3& c) {
  const glm::vec3 e1 = b - a, e2 = c - a;
  const glm::vec3 p = glm::cross(d, e2);
  const float det = glm::dot(e1, p);
  if (std::abs(det) < 1e-12f) return std::nullopt;
  const float inv = 1.0f / det;
  const glm::vec3 s = o - a;
  const float u = glm::dot(s, p) * inv;
  if (u < 0.0f || u > 1.0f) return std::nullopt;
  const glm::vec3 q = glm::cross(s, e1);
  const float v = glm::dot(d, q) * inv;
  if (v < 0.0f || u + v > 1.0f) return std::nullopt;
  const float t = glm::dot(e2, q) * inv;
  if (t < 0.0f) return std::nullopt;
  return t;
}

}  // namespace

glm::vec3 closestPointOnTriangle(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
  const glm::vec3 ab = b - a, ac = c - a, ap = p - a;
  const float d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const glm::vec3 bp = p - b;
  const float d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const float vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + ab * (d1 / (d1 - d3));
  const glm::vec3 cp = p - c;
  const float d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const float vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + ac * (d2 / (d2 - d6));
  const float va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  const float denom = 1.0f / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

CollisionWorld CollisionWorld::fromScene(const Scene& scene) {
  CollisionWorld world;
  for (const Shape& shape : scene.shapes) {
    if (!shape.mesh || shape.mesh->topology != Topology::kTriangles) continue;
    const Mesh& m = *shape.mesh;
    std::vector<glm::vec3> p(m.positions.size());
    for (size_t i = 0; i < p.size(); ++i) p[i] = glm::vec3(shape.transform * glm::vec4(m.positions[i], 1.0f));
    for (size_t i = 0; i + 2 < m.indices.size(); i += 3) {
      const uint32_t a = m.indices[i], b = m.indices[i + 1], c = m.indices[i + 2];
      if (a >= p.size() || b >= p.size() || c >= p.size()) continue;
      if (glm::length(glm::cross(p[b] - p[a], p[c] - p[a])) < 1e-12f) continue;  // degenerate
      world.triangles_.push_back({p[a], p[b], p[c]});
    }
  }
  world.build();
  return world;
}

void CollisionWorld::build() {
  order_.resize(triangles_.size());
  std::iota(order_.begin(), order_.end(), 0u);
  nodes_.clear();
  if (triangles_.empty()) return;
  nodes_.reserve(2 * triangles_.size() / kLeafSize + 2);
  nodes_.push_back({{}, 0, static_cast<uint32_t>(triangles_.size())});
  // Median split along the longest axis of the centroid bounds, iteratively.
  std::vector<uint32_t> pending{0};
  while (!pending.empty()) {
    const uint32_t index = pending.back();
    pending.pop_back();
    const uint32_t first = nodes_[index].first, count = nodes_[index].count;
    Bounds box, centroids;
    for (uint32_t i = first; i < first + count; ++i) {
      const Triangle& t = triangles_[order_[i]];
      box.add(triangleBounds(t.a, t.b, t.c));
      centroids.add((t.a + t.b + t.c) / 3.0f);
    }
    nodes_[index].bounds = box;
    if (count <= kLeafSize) continue;
    const glm::vec3 extent = centroids.size();
    const int axis = extent.x > extent.y ? (extent.x > extent.z ? 0 : 2) : (extent.y > extent.z ? 1 : 2);
    const uint32_t mid = first + count / 2;
    std::nth_element(order_.begin() + first, order_.begin() + mid, order_.begin() + first + count,
                     [&](uint32_t x, uint32_t y) {
                       const Triangle &tx = triangles_[x], &ty = triangles_[y];
                       return (tx.a + tx.b + tx.c)[axis] < (ty.a + ty.b + ty.c)[axis];
                     });
    const uint32_t left = static_cast<uint32_t>(nodes_.size());
    nodes_.push_back({{}, first, mid - first});
    nodes_.push_back({{}, mid, first + count - mid});
    nodes_[index].first = left;
    nodes_[index].count = 0;
    pending.push_back(left);
    pending.push_back(left + 1);
  }
}

CollisionWorld::TreeStats CollisionWorld::treeStats() const {
  TreeStats stats;
  if (nodes_.empty()) return stats;
  std::vector<std::pair<uint32_t, uint32_t>> pending{{0u, 1u}};  // node, its level
  while (!pending.empty()) {
    const auto [index, level] = pending.back();
    pending.pop_back();
    const Node& node = nodes_[index];
    ++stats.nodes;
    stats.depth = std::max(stats.depth, level);
    if (node.count > 0) {
      ++stats.leaves;
      stats.largestLeaf = std::max(stats.largestLeaf, node.count);
      stats.leafTriangles += node.count;
    } else {
      pending.push_back({node.first, level + 1});
      pending.push_back({node.first + 1, level + 1});
    }
  }
  return stats;
}

template <class Visit>
void CollisionWorld::visitOverlapping(const Bounds& box, Visit&& visit) const {
  if (nodes_.empty()) return;
  uint32_t stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (!overlaps(node.bounds, box)) continue;
    if (node.count > 0) {
      for (uint32_t i = node.first; i < node.first + node.count; ++i) visit(triangles_[order_[i]]);
    } else if (top + 2 <= 64) {
      stack[top++] = node.first;
      stack[top++] = node.first + 1;
    }
  }
}

std::optional<CollisionWorld::Hit> CollisionWorld::raycast(const glm::vec3& origin, const glm::vec3& direction,
                                                          float maxDistance) const {
  const float length = glm::length(direction);
  if (nodes_.empty() || !(length > 0.0f)) return std::nullopt;
  const glm::vec3 d = direction / length;
  const glm::vec3 inverse(1.0f / d.x, 1.0f / d.y, 1.0f / d.z);
  std::optional<Hit> best;
  float bestT = maxDistance;
  uint32_t stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (rayBox(origin, inverse, node.bounds, bestT) < 0.0f) continue;
    if (node.count == 0) {
      if (top + 2 <= 64) {
        stack[top++] = node.first;
        stack[top++] = node.first + 1;
      }
      continue;
    }
    for (uint32_t i = node.first; i < node.first + node.count; ++i) {
      const Triangle& t = triangles_[order_[i]];
      auto hit = rayTriangle(origin, d, t.a, t.b, t.c);
      if (!hit || *hit > bestT) continue;
      bestT = *hit;
      glm::vec3 n = glm::normalize(glm::cross(t.b - t.a, t.c - t.a));
      if (glm::dot(n, d) > 0) n = -n;
      best = Hit{*hit, origin + d * *hit, n};
    }
  }
  return best;
}

bool CollisionWorld::resolvePenetration(glm::vec3& center, float radius) const {
  bool moved = false;
  Bounds box;
  box.add(center - glm::vec3(radius));
  box.add(center + glm::vec3(radius));
  visitOverlapping(box, [&](const Triangle& t) {
    const glm::vec3 closest = closestPointOnTriangle(center, t.a, t.b, t.c);
    const glm::vec3 away = center - closest;
    const float distance = glm::length(away);
    if (distance >= radius) return;
    glm::vec3 normal;
    if (distance > 1e-6f) {
      normal = away / distance;
    } else {  // centre exactly on the triangle: leave along its normal
      normal = glm::normalize(glm::cross(t.b - t.a, t.c - t.a));
    }
    center = closest + normal * (radius + 1e-4f);
    moved = true;
  });
  return moved;
}

glm::vec3 CollisionWorld::slideSphere(const glm::vec3& center, float radius, const glm::vec3& delta) const {
  glm::vec3 position = center;
  const float length = glm::length(delta);
  if (!(length > 0.0f) || !(radius > 0.0f)) return position;
  const int steps = std::max(1, static_cast<int>(std::ceil(length / (0.5f * radius))));
  const glm::vec3 step = delta / static_cast<float>(steps);
  for (int i = 0; i < steps; ++i) {
    position += step;
    // A few passes settle corners where two walls push at once.
    for (int pass = 0; pass < 4 && resolvePenetration(position, radius); ++pass) {
    }
  }
  return position;
}

}  // namespace pw::engine
