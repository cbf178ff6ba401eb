#include "editor/edit/plan.h"

#include <algorithm>
#include <cmath>

namespace pw::edit {
using modeling::Attachment;
using modeling::Layout;
using modeling::Side;

namespace {

double normalizedDeg(double deg) {
  double r = std::fmod(deg, 360.0);
  if (r <= -180.0) r += 360.0;
  if (r > 180.0) r -= 360.0;
  if (std::abs(r - std::round(r)) < 1e-9) r = std::round(r);  // 90-degree turns stay whole numbers
  return r + 0.0;
}

}  // namespace

std::vector<glm::dmat4> placeCorridors(const Layout& layout, const std::vector<metrology::Dimensions>& boxes) {
  std::vector<glm::dmat4> world(layout.corridors.size(), glm::dmat4(1.0));
  for (size_t i = 0; i < layout.corridors.size(); ++i) {
    const modeling::LayoutEntry& entry = layout.corridors[i];
    const bool attached = entry.attach && entry.attach->to >= 0 && size_t(entry.attach->to) < i && i < boxes.size();
    world[i] = attached ? modeling::attachedTransform(world[entry.attach->to], boxes[entry.attach->to], *entry.attach)
                        : modeling::placedTransform(entry);
  }
  return world;
}

PlanPose poseOf(const glm::dmat4& m) {
  return {{m[3].x, m[3].z}, normalizedDeg(glm::degrees(std::atan2(-m[0].z, m[0].x)))};
}

std::array<glm::dvec2, 4> footprintCorners(const glm::dmat4& m, const metrology::Dimensions& box) {
  const double w = box.widthM / 2, l = box.lengthM;
  const auto at = [&](double x, double z) {
    const glm::dvec4 p = m * glm::dvec4(x, 0, z, 1);
    return glm::dvec2(p.x, p.z);
  };
  return {at(-w, 0), at(w, 0), at(w, -l), at(-w, -l)};
}

glm::dvec2 toCorridor(const glm::dmat4& m, const glm::dvec2& p) {
  const glm::dvec4 local = glm::inverse(m) * glm::dvec4(p.x, 0, p.y, 1);
  return {local.x, local.z};
}

int corridorAt(const std::vector<glm::dmat4>& world, const std::vector<metrology::Dimensions>& boxes,
               const glm::dvec2& p) {
  for (int i = int(std::min(world.size(), boxes.size())) - 1; i >= 0; --i) {
    const glm::dvec2 local = toCorridor(world[i], p);
    if (std::abs(local.x) <= boxes[i].widthM / 2 && local.y <= 0 && local.y >= -boxes[i].lengthM) return i;
  }
  return -1;
}

std::vector<bool> movesWith(const Layout& layout, int corridor) {
  std::vector<bool> moves(layout.corridors.size(), false);
  if (corridor < 0 || size_t(corridor) >= moves.size()) return moves;
  moves[corridor] = true;
  // Hosts are listed before their guests, so one pass in order finds every descendant.
  for (size_t i = 0; i < moves.size(); ++i) {
    const auto& attach = layout.corridors[i].attach;
    if (attach && attach->to >= 0 && size_t(attach->to) < moves.size() && moves[attach->to]) moves[i] = true;
  }
  return moves;
}

std::optional<Snap> findSnap(const Layout& layout, const std::vector<metrology::Dimensions>& boxes,
                             const std::vector<glm::dmat4>& world, int guest, const PlanPose& guestPose,
                             double snapDistanceM) {
  const size_t n = std::min({layout.corridors.size(), boxes.size(), world.size()});
  if (guest < 0 || size_t(guest) >= n) return std::nullopt;
  const std::vector<bool> moving = movesWith(layout, guest);
  const metrology::Dimensions& g = boxes[guest];
  std::optional<Snap> best;
  const auto consider = [&](int host, Side side, double offsetM, const glm::dvec2& fromLocal, const glm::dvec2& toLocal) {
    const double distance = glm::length(toLocal - fromLocal);
    if (distance > snapDistanceM || (best && best->distanceM <= distance)) return;
    const Attachment attach{host, side, offsetM + 0.0};
    best = Snap{attach, poseOf(modeling::attachedTransform(world[host], boxes[host], attach)), distance};
  };
  for (size_t h = 0; h < n; ++h) {
    if (moving[h]) continue;
    const metrology::Dimensions& box = boxes[h];
    const glm::dvec2 p = toCorridor(world[h], guestPose.nearCentre);  // (x, z) in the host's frame
    // The far wall, z = -length: the near-end centre anywhere along it.
    double offset = std::clamp(p.x, -box.widthM / 2, box.widthM / 2);
    if (std::abs(offset) < kCentreSnapM) offset = 0;
    consider(int(h), Side::kFar, offset, p, {offset, -box.lengthM});
    // The side walls, x = -+width/2: the guest's opening must fit between the ends.
    if (box.lengthM >= g.widthM) {
      const double along = std::clamp(-p.y, g.widthM / 2, box.lengthM - g.widthM / 2);
      consider(int(h), Side::kLeft, along, p, {-box.widthM / 2, -along});
      consider(int(h), Side::kRight, along, p, {box.widthM / 2, -along});
    }
  }
  return best;
}

std::optional<std::array<glm::dvec2, 2>> openingInHost(const Layout& layout,
                                                       const std::vector<metrology::Dimensions>& boxes,
                                                       const std::vector<glm::dmat4>& world, int i) {
  const size_t n = std::min({layout.corridors.size(), boxes.size(), world.size()});
  if (i < 0 || size_t(i) >= n || !layout.corridors[i].attach) return std::nullopt;
  const Attachment& a = *layout.corridors[i].attach;
  if (a.to < 0 || size_t(a.to) >= n) return std::nullopt;
  const metrology::Dimensions& host = boxes[a.to];
  const double half = boxes[i].widthM / 2;
  glm::dvec3 p0, p1;  // in the host's frame
  if (a.side == Side::kFar) {
    const double x0 = std::max(a.offsetM - half, -host.widthM / 2), x1 = std::min(a.offsetM + half, host.widthM / 2);
    if (x1 <= x0) return std::nullopt;
    p0 = {x0, 0, -host.lengthM};
    p1 = {x1, 0, -host.lengthM};
  } else {
    const double x = a.side == Side::kLeft ? -host.widthM / 2 : host.widthM / 2;
    p0 = {x, 0, -std::clamp(a.offsetM - half, 0.0, host.lengthM)};
    p1 = {x, 0, -std::clamp(a.offsetM + half, 0.0, host.lengthM)};
  }
  const glm::dvec4 w0 = world[a.to] * glm::dvec4(p0, 1), w1 = world[a.to] * glm::dvec4(p1, 1);
  return std::array<glm::dvec2, 2>{glm::dvec2(w0.x, w0.z), glm::dvec2(w1.x, w1.z)};
}

Layout removeCorridor(Layout layout, const std::vector<glm::dmat4>& world, int i) {
  const int n = int(layout.corridors.size());
  if (i < 0 || i >= n || n < 2 || size_t(n) > world.size()) return layout;  // a layout keeps one corridor
  for (int k = 0; k < n; ++k) {
    modeling::LayoutEntry& entry = layout.corridors[k];
    if (!entry.attach) continue;
    if (entry.attach->to == i) {
      const PlanPose pose = poseOf(world[k]);
      entry.attach.reset();
      entry.position = {pose.nearCentre.x, entry.position.y, pose.nearCentre.y};
      entry.rotationDeg = pose.rotationDeg;
    } else if (entry.attach->to > i) {
      --entry.attach->to;
    }
  }
  layout.corridors.erase(layout.corridors.begin() + i);
  return layout;
}

Layout placeCorridor(Layout layout, int i, const PlanPose& pose) {
  if (i < 0 || size_t(i) >= layout.corridors.size()) return layout;
  modeling::LayoutEntry& entry = layout.corridors[i];
  entry.attach.reset();
  entry.position = {pose.nearCentre.x + 0.0, entry.position.y, pose.nearCentre.y + 0.0};
  entry.rotationDeg = normalizedDeg(pose.rotationDeg);
  return layout;
}

Layout attachCorridor(Layout layout, int i, const Attachment& attach, int* newIndex) {
  const size_t n = layout.corridors.size();
  if (newIndex) *newIndex = i;
  if (i < 0 || size_t(i) >= n || attach.to < 0 || size_t(attach.to) >= n || movesWith(layout, i)[attach.to]) {
    return layout;
  }
  layout.corridors[i].attach = attach;
  // A stable topological order: again and again, the first corridor not yet listed
  // whose host is.
  std::vector<int> order;
  std::vector<bool> listed(n, false);
  while (order.size() < n) {
    bool found = false;
    for (size_t k = 0; k < n && !found; ++k) {
      const auto& a = layout.corridors[k].attach;
      if (!listed[k] && (!a || listed[a->to])) {
        order.push_back(int(k));
        listed[k] = true;
        found = true;
      }
    }
    if (!found) return layout;  // a cycle: movesWith rules it out
  }
  std::vector<int> newFromOld(n);
  for (size_t j = 0; j < n; ++j) newFromOld[order[j]] = int(j);
  Layout sorted;
  sorted.otherFields = layout.otherFields;
  for (size_t j = 0; j < n; ++j) {
    modeling::LayoutEntry entry = layout.corridors[order[j]];
    if (entry.attach) entry.attach->to = newFromOld[entry.attach->to];
    sorted.corridors.push_back(std::move(entry));
  }
  if (newIndex) *newIndex = newFromOld[i];
  return sorted;
}

Layout rotateCorridor(Layout layout, const std::vector<glm::dmat4>& world, int i, double deltaDeg) {
  if (i < 0 || size_t(i) >= layout.corridors.size() || size_t(i) >= world.size()) return layout;
  // An attached corridor keeps its attachment: the placed corridor it hangs from turns,
  // and every corridor attached to that one with it.
  int root = i;
  for (size_t steps = 0; layout.corridors[root].attach && steps < layout.corridors.size(); ++steps) {
    root = layout.corridors[root].attach->to;
  }
  if (layout.corridors[root].attach) return layout;  // a cycle (the file's order rule forbids it)
  const modeling::LayoutEntry& entry = layout.corridors[root];
  const PlanPose pose{{entry.position.x, entry.position.z}, entry.rotationDeg + deltaDeg};  // exact, as written
  return placeCorridor(std::move(layout), root, pose);
}

bool sameLayout(const Layout& a, const Layout& b) {
  if (a.corridors.size() != b.corridors.size() || a.otherFields != b.otherFields) return false;
  for (size_t i = 0; i < a.corridors.size(); ++i) {
    const modeling::LayoutEntry& x = a.corridors[i];
    const modeling::LayoutEntry& y = b.corridors[i];
    if (x.name != y.name || x.shot != y.shot || x.otherFields != y.otherFields || x.attach.has_value() != y.attach.has_value()) {
      return false;
    }
    if (x.attach) {
      if (x.attach->to != y.attach->to || x.attach->side != y.attach->side || x.attach->offsetM != y.attach->offsetM) {
        return false;
      }
    } else if (x.position != y.position || x.rotationDeg != y.rotationDeg) {
      return false;
    }
  }
  return true;
}

PlanTransform fitPlan(const std::vector<glm::dvec2>& points, const glm::dvec2& min, const glm::dvec2& max) {
  PlanTransform t;
  glm::dvec2 lo(-2.0), hi(2.0);
  if (!points.empty()) {
    lo = hi = points.front();
    for (const glm::dvec2& p : points) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
  }
  const glm::dvec2 extent = glm::max(hi - lo, glm::dvec2(1.0));
  const glm::dvec2 room = glm::max(max - min, glm::dvec2(1.0));
  t.scale = std::clamp(0.85 * std::min(room.x / extent.x, room.y / extent.y), 1.0, 400.0);
  t.offset = 0.5 * (min + max) - t.scale * 0.5 * (lo + hi);
  return t;
}

}  // namespace pw::edit
