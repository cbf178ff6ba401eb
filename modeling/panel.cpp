#include "modeling/panel.h"

#include <algorithm>
#include <cmath>

namespace pw::modeling {

Rect intersect(const Rect& a, const Rect& b) {
  return {std::max(a.s0, b.s0), std::max(a.t0, b.t0), std::min(a.s1, b.s1), std::min(a.t1, b.t1)};
}

namespace {

std::vector<double> breaks(double lo, double hi, const std::vector<Rect>& openings, bool alongS, double maxCell) {
  std::vector<double> out{lo, hi};
  for (const Rect& o : openings) {
    const double edges[2] = {alongS ? o.s0 : o.t0, alongS ? o.s1 : o.t1};
    for (double v : edges) {
      if (v > lo && v < hi) out.push_back(v);
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end(), [](double x, double y) { return std::abs(x - y) < 1e-9; }), out.end());
  if (maxCell <= 0) return out;
  std::vector<double> fine;
  for (size_t i = 0; i + 1 < out.size(); ++i) {
    const int pieces = std::max(1, static_cast<int>(std::ceil((out[i + 1] - out[i]) / maxCell - 1e-9)));
    for (int k = 0; k < pieces; ++k) fine.push_back(out[i] + (out[i + 1] - out[i]) * k / pieces);
  }
  fine.push_back(out.back());
  return fine;
}

bool insideAnOpening(const std::vector<Rect>& openings, double s, double t) {
  return std::any_of(openings.begin(), openings.end(),
                     [&](const Rect& o) { return s > o.s0 && s < o.s1 && t > o.t0 && t < o.t1; });
}

}  // namespace

engine::Mesh panelMesh(const Panel& panel, const std::optional<glm::vec4>& color) {
  engine::Mesh mesh;
  if (panel.extent.empty()) return mesh;
  std::vector<Rect> openings;
  for (const Rect& o : panel.openings) {
    const Rect clipped = intersect(o, panel.extent);
    if (!clipped.empty()) openings.push_back(clipped);
  }
  const std::vector<double> ss = breaks(panel.extent.s0, panel.extent.s1, openings, true, panel.maxCellM);
  const std::vector<double> ts = breaks(panel.extent.t0, panel.extent.t1, openings, false, panel.maxCellM);
  const glm::vec3 normal(panel.normal());

  // One vertex per grid point, shared by the cells around it.
  const size_t columns = ss.size();
  for (double t : ts) {
    for (double s : ss) {
      mesh.positions.push_back(glm::vec3(panel.point(s, t)));
      mesh.normals.push_back(normal);
      if (panel.textureRect) {
        const Rect& r = *panel.textureRect;
        mesh.texCoords.push_back({static_cast<float>((s - r.s0) / (r.s1 - r.s0)),
                                  static_cast<float>((t - r.t0) / (r.t1 - r.t0))});
      }
      if (color) mesh.colors.push_back(*color);
    }
  }
  for (size_t j = 0; j + 1 < ts.size(); ++j) {
    for (size_t i = 0; i + 1 < ss.size(); ++i) {
      if (insideAnOpening(openings, 0.5 * (ss[i] + ss[i + 1]), 0.5 * (ts[j] + ts[j + 1]))) continue;
      const auto v = [&](size_t col, size_t row) { return static_cast<uint32_t>(row * columns + col); };
      // Counter-clockwise seen from the front (cross(sAxis, tAxis)).
      mesh.indices.insert(mesh.indices.end(), {v(i, j), v(i + 1, j), v(i + 1, j + 1), v(i, j), v(i + 1, j + 1), v(i, j + 1)});
    }
  }
  // Drop grid points no cell uses (inside openings) so bounds stay honest.
  std::vector<uint32_t> remap(mesh.positions.size(), UINT32_MAX);
  engine::Mesh compact;
  compact.solid = true;
  for (uint32_t& index : mesh.indices) {
    if (remap[index] == UINT32_MAX) {
      remap[index] = static_cast<uint32_t>(compact.positions.size());
      compact.positions.push_back(mesh.positions[index]);
      compact.normals.push_back(mesh.normals[index]);
      if (!mesh.texCoords.empty()) compact.texCoords.push_back(mesh.texCoords[index]);
      if (!mesh.colors.empty()) compact.colors.push_back(mesh.colors[index]);
    }
    compact.indices.push_back(remap[index]);
  }
  return compact;
}

}  // namespace pw::modeling
