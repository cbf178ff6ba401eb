#include "modeling/layout.h"

#include <cmath>
#include <cstdio>

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>
#include <opencv2/imgproc.hpp>

#include "base/atomic_file.h"
#include "base/input_file.h"

namespace pw::modeling {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

Result<double> finiteNumber(const json& value, const std::string& what) {
  if (!value.is_number() || !std::isfinite(value.get<double>())) return makeError(what + " must be a finite number");
  return value.get<double>();
}

// "an array", "a number"...: what a field of the wrong type holds.
std::string typeOf(const json& value) {
  if (value.is_string()) return "a string";
  if (value.is_number()) return "a number";
  if (value.is_boolean()) return "a boolean";
  if (value.is_null()) return "null";
  if (value.is_array()) return "an array";
  return "an object";
}

Result<Layout> readLayout(const fs::path& path);

}  // namespace

Result<Layout> readLayoutFile(const fs::path& path) {
  try {
    return readLayout(path);
  } catch (const json::exception& e) {
    // Every field is checked before use; this only turns an oversight into an error
    // that names the file (e.what() is "[json.exception.type_error.302] ...").
    std::string what = e.what();
    if (const size_t close = what.find("] "); what.rfind("[json.", 0) == 0 && close != std::string::npos) {
      what = what.substr(close + 2);
    }
    return makeError(path.string() + ": malformed layout (" + what + ")");
  }
}

namespace {

Result<Layout> readLayout(const fs::path& path) {
  const std::string where = path.string();
  auto text = readInputFile(path, kLayoutInput);
  if (!text) return text.error();
  const json doc = json::parse(*text, nullptr, false);
  if (doc.is_discarded()) return makeError(where + ": not valid JSON");
  if (!doc.is_object() || !doc.contains("corridors") || !doc["corridors"].is_array() || doc["corridors"].empty()) {
    return makeError(where + ": a layout file is {\"corridors\": [ ... ]} with at least one corridor");
  }
  Layout layout;
  layout.otherFields = doc;
  layout.otherFields.erase("corridors");
  for (const json& item : doc["corridors"]) {
    const std::string at = where + ": corridor " + std::to_string(layout.corridors.size() + 1);
    if (!item.is_object()) return makeError(at + " must be an object");
    LayoutEntry entry;
    entry.name = "corridor" + std::to_string(layout.corridors.size() + 1);
    if (item.contains("name")) {
      if (!item["name"].is_string() || item["name"].get<std::string>().empty()) {
        return makeError(at + ": field \"name\" must be a non-empty string, not " + typeOf(item["name"]));
      }
      entry.name = item["name"].get<std::string>();
    }
    for (const LayoutEntry& other : layout.corridors) {
      if (other.name == entry.name) return makeError(at + ": the name \"" + entry.name + "\" is used twice");
    }
    if (!item.contains("shot")) return makeError(at + " needs \"shot\": the shot file");
    if (!item["shot"].is_string() || item["shot"].get<std::string>().empty()) {
      return makeError(at + ": field \"shot\" must be the shot file's name (a string), not " + typeOf(item["shot"]));
    }
    if (item["shot"].get<std::string>().find('\0') != std::string::npos) {
      return makeError(at + ": field \"shot\" holds a NUL character; no file has such a name");
    }
    entry.shot = item["shot"].get<std::string>();
    if (entry.shot.is_relative()) entry.shot = (path.parent_path() / entry.shot).lexically_normal();
    if (item.contains("attach")) {
      const json& a = item["attach"];
      if (!a.is_object() || !a.contains("to") || !a["to"].is_string()) {
        return makeError(at + ": attach is {\"to\": NAME, \"side\": \"far\"|\"left\"|\"right\", \"offset_m\": M}");
      }
      Attachment attach;
      const std::string to = a["to"].get<std::string>();
      for (size_t i = 0; i < layout.corridors.size(); ++i) {
        if (layout.corridors[i].name == to) attach.to = static_cast<int>(i);
      }
      if (attach.to < 0) return makeError(at + ": attaches to \"" + to + "\", which is not listed before it");
      if (a.contains("side") && !a["side"].is_string()) {
        return makeError(at + ": field \"attach.side\" must be \"far\", \"left\" or \"right\", not " + typeOf(a["side"]));
      }
      const std::string side = a.contains("side") ? a["side"].get<std::string>() : std::string("far");
      if (side == "far") attach.side = Side::kFar;
      else if (side == "left") attach.side = Side::kLeft;
      else if (side == "right") attach.side = Side::kRight;
      else return makeError(at + ": side must be \"far\", \"left\" or \"right\", not \"" + side + "\"");
      if (a.contains("offset_m")) {
        auto offset = finiteNumber(a["offset_m"], at + ": offset_m");
        if (!offset) return offset.error();
        attach.offsetM = *offset;
      }
      entry.attach = attach;
    } else {
      if (item.contains("position")) {
        const json& p = item["position"];
        if (!p.is_array() || p.size() != 3) return makeError(at + ": position is [x, y, z] in metres");
        for (int i = 0; i < 3; ++i) {
          auto v = finiteNumber(p[i], at + ": position");
          if (!v) return v.error();
          entry.position[i] = *v;
        }
      }
      if (item.contains("rotation_deg")) {
        auto r = finiteNumber(item["rotation_deg"], at + ": rotation_deg");
        if (!r) return r.error();
        entry.rotationDeg = *r;
      }
    }
    entry.otherFields = item;
    for (const char* key : {"name", "shot", "position", "rotation_deg", "attach"}) entry.otherFields.erase(key);
    layout.corridors.push_back(std::move(entry));
  }
  return layout;
}

}  // namespace

Status writeLayoutFile(const fs::path& path, const Layout& layout) {
  json doc = layout.otherFields.is_object() ? layout.otherFields : json::object();
  json corridors = json::array();
  std::error_code ec;
  const fs::path base = fs::absolute(path.parent_path().empty() ? fs::path(".") : path.parent_path(), ec);
  for (const LayoutEntry& entry : layout.corridors) {
    json item = entry.otherFields.is_object() ? entry.otherFields : json::object();
    item["name"] = entry.name;
    const fs::path relative = fs::relative(fs::absolute(entry.shot, ec), base, ec);
    item["shot"] = (!ec && !relative.empty()) ? relative.generic_string() : entry.shot.generic_string();
    if (entry.attach) {
      const Attachment& a = *entry.attach;
      if (a.to < 0 || a.to >= static_cast<int>(layout.corridors.size())) {
        return makeError(path.string() + ": corridor \"" + entry.name + "\" attaches to a corridor not in the layout");
      }
      const char* side = a.side == Side::kFar ? "far" : a.side == Side::kLeft ? "left" : "right";
      item["attach"] = {{"to", layout.corridors[a.to].name}, {"side", side}, {"offset_m", a.offsetM + 0.0}};
    } else {
      item["position"] = {entry.position.x + 0.0, entry.position.y + 0.0, entry.position.z + 0.0};
      item["rotation_deg"] = entry.rotationDeg + 0.0;
    }
    corridors.push_back(std::move(item));
  }
  doc["corridors"] = std::move(corridors);
  return writeFileAtomic(path, doc.dump(1) + "\n");
}

glm::dmat4 placedTransform(const LayoutEntry& entry) {
  return glm::rotate(glm::translate(glm::dmat4(1.0), entry.position), glm::radians(entry.rotationDeg),
                     glm::dvec3(0, 1, 0));
}

glm::dmat4 attachedTransform(const glm::dmat4& worldFromHost, const metrology::Dimensions& host,
                             const Attachment& a) {
  glm::dvec3 hostLocal;  // the guest's near-end centre, in the host's frame
  double turnDeg = 0;    // the guest's rotation relative to the host
  if (a.side == Side::kFar) {
    hostLocal = {a.offsetM, 0, -host.lengthM};
  } else {
    const bool left = a.side == Side::kLeft;
    hostLocal = {left ? -host.widthM / 2 : host.widthM / 2, 0, -a.offsetM};
    turnDeg = left ? 90.0 : -90.0;
  }
  return glm::rotate(glm::translate(worldFromHost, hostLocal), glm::radians(turnDeg), glm::dvec3(0, 1, 0));
}

Layout chainLayout(const std::vector<fs::path>& shots) {
  Layout layout;
  for (size_t i = 0; i < shots.size(); ++i) {
    LayoutEntry entry;
    entry.name = shots[i].stem().string();
    entry.shot = shots[i];
    if (i > 0) entry.attach = Attachment{static_cast<int>(i) - 1, Side::kFar, 0.0};
    layout.corridors.push_back(entry);
  }
  // Names must be unique for the model's DEF names.
  for (size_t i = 0; i < layout.corridors.size(); ++i) {
    for (size_t j = 0; j < i; ++j) {
      if (layout.corridors[j].name == layout.corridors[i].name) layout.corridors[i].name += "_" + std::to_string(i + 1);
    }
  }
  return layout;
}

Result<BuildingPlan> planBuilding(const Layout& layout, const std::vector<metrology::Dimensions>& boxes) {
  BuildingPlan plan;
  const size_t n = layout.corridors.size();
  if (boxes.size() != n) return makeError("layout and measured corridors differ in number");
  plan.worldFromCorridor.resize(n);
  plan.attached.assign(n, false);
  constexpr double kEps = 1e-6;
  for (size_t i = 0; i < n; ++i) {
    const LayoutEntry& entry = layout.corridors[i];
    const metrology::Dimensions& box = boxes[i];
    if (!entry.attach) {
      plan.worldFromCorridor[i] = placedTransform(entry);
      continue;
    }
    const Attachment& a = *entry.attach;
    const metrology::Dimensions& host = boxes[a.to];
    const std::string who = "layout: corridor \"" + entry.name + "\" attached to \"" + layout.corridors[a.to].name + "\"";
    plan.attached[i] = true;
    const double height = std::min(host.heightM, box.heightM);
    Opening inHost{a.to, Surface::kFarWall, {}};
    double guestOverlap0 = 0, guestOverlap1 = box.widthM;  // along the guest's near-end s axis
    if (a.side == Side::kFar) {
      // The guest's x range seen on the host's far wall (s = x + W_host / 2).
      const double x0 = std::max(a.offsetM - box.widthM / 2, -host.widthM / 2);
      const double x1 = std::min(a.offsetM + box.widthM / 2, host.widthM / 2);
      if (x1 - x0 < 0.3) return makeError(who + ": offset_m " + std::to_string(a.offsetM) + " leaves less than 0.3 m of opening");
      inHost.rect = {x0 + host.widthM / 2, 0, x1 + host.widthM / 2, height};
      // Guest near end: s = W_guest/2 - x_guest, x_guest = x_host - offset.
      guestOverlap0 = box.widthM / 2 - (x1 - a.offsetM);
      guestOverlap1 = box.widthM / 2 - (x0 - a.offsetM);
    } else {
      const bool left = a.side == Side::kLeft;
      if (a.offsetM - box.widthM / 2 < -kEps || a.offsetM + box.widthM / 2 > host.lengthM + kEps) {
        return makeError(who + ": an opening " + std::to_string(box.widthM) + " m wide at offset_m " +
                         std::to_string(a.offsetM) + " does not fit in a wall " + std::to_string(host.lengthM) + " m long");
      }
      inHost.surface = left ? Surface::kLeftWall : Surface::kRightWall;
      const double centre = left ? a.offsetM : host.lengthM - a.offsetM;
      inHost.rect = {centre - box.widthM / 2, 0, centre + box.widthM / 2, height};
    }
    plan.worldFromCorridor[i] = attachedTransform(plan.worldFromCorridor[a.to], host, a);
    plan.openings.push_back(inHost);
    plan.openings.push_back(Opening{static_cast<int>(i), Surface::kNearEnd, {guestOverlap0, 0, guestOverlap1, height}});
  }
  // Corridors that run through each other: their floors' footprints (plan x, z)
  // intersected two by two.
  std::vector<std::vector<cv::Point2f>> footprints(n);
  for (size_t i = 0; i < n; ++i) {
    const double w2 = 0.5 * boxes[i].widthM, l = boxes[i].lengthM;
    for (const glm::dvec2 c : {glm::dvec2(-w2, 0), glm::dvec2(w2, 0), glm::dvec2(w2, -l), glm::dvec2(-w2, -l)}) {
      const glm::dvec4 world = plan.worldFromCorridor[i] * glm::dvec4(c.x, 0, c.y, 1);
      footprints[i].emplace_back(static_cast<float>(world.x), static_cast<float>(world.z));
    }
  }
  for (size_t a = 0; a < n; ++a) {
    for (size_t b = a + 1; b < n; ++b) {
      std::vector<cv::Point2f> shared;
      const float area = cv::intersectConvexConvex(footprints[a], footprints[b], shared, true);
      if (area >= kOverlapAreaM2) plan.overlaps.push_back({int(a), int(b), area});
    }
  }
  return plan;
}

std::string overlapText(const Layout& layout, const CorridorOverlap& overlap) {
  char area[32];
  std::snprintf(area, sizeof area, "%.1f", overlap.areaM2);
  return "corridors \"" + layout.corridors[overlap.a].name + "\" and \"" + layout.corridors[overlap.b].name +
         "\" run through each other (" + area + " m² of floor in both): move one of them";
}

}  // namespace pw::modeling
