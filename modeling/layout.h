// Buildings of several corridors (the seed paper's figure 14): where each corridor
// stands, and the openings where one corridor opens into another.
//
// Layout file (JSON; README "Layout files"):
//   {"corridors": [
//     {"name": "hall", "shot": "hall.json", "position": [0, 0, 0], "rotation_deg": 0},
//     {"name": "wing", "shot": "wing.json", "attach": {"to": "hall", "side": "left", "offset_m": 3.5}},
//     {"name": "end",  "shot": "end.json",  "attach": {"to": "hall", "side": "far",  "offset_m": 0}}]}
// A corridor is either placed (position of its near-end centre on the floor, rotation
// about +Y in degrees, counter-clockwise seen from above) or attached to one listed
// before it: "far" puts its near end on the other's far wall, offset_m to the side
// (along the other's +x); "left"/"right" put its near end on that side wall, offset_m
// from the other's near end to its centre line. Shot paths are relative to the file.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "base/result.h"
#include "modeling/surfaces.h"

namespace pw::modeling {

enum class Side { kFar, kLeft, kRight };

struct Attachment {
  int to = -1;  // index of an earlier corridor
  Side side = Side::kFar;
  double offsetM = 0;
};

struct LayoutEntry {
  std::string name;
  std::filesystem::path shot;
  glm::dvec3 position{0.0};
  double rotationDeg = 0;
  std::optional<Attachment> attach;
  nlohmann::json otherFields = nlohmann::json::object();  // the corridor's fields photowalk does not read, kept
};

struct Layout {
  std::vector<LayoutEntry> corridors;
  nlohmann::json otherFields = nlohmann::json::object();  // the file's fields besides "corridors", kept
};

Result<Layout> readLayoutFile(const std::filesystem::path& path);

// Writes the layout atomically: each corridor's name, shot (relative to the file's
// folder where possible) and either position and rotation_deg or attach (to: the
// host's name), with the fields photowalk does not read as they were read.
Status writeLayoutFile(const std::filesystem::path& path, const Layout& layout);

// Where a placed corridor stands: position, then rotation_deg about +Y.
glm::dmat4 placedTransform(const LayoutEntry& entry);

// Where an attached corridor stands: its world-from-corridor transform, given its
// host's and the host's box (README "Layout files"). No checks: planBuilding says
// whether the attachment fits.
glm::dmat4 attachedTransform(const glm::dmat4& worldFromHost, const metrology::Dimensions& host,
                             const Attachment& attach);

// The layout used when several shots are given without a layout file: each
// corridor continues from the previous one's far end, centred.
Layout chainLayout(const std::vector<std::filesystem::path>& shots);

// An opening cut into one corridor's surface, in that surface's (s, t) coordinates.
struct Opening {
  int corridor = -1;
  Surface surface = Surface::kFarWall;
  Rect rect;
};

// Two corridors whose floors overlap: they run through each other (a wall of one
// stands inside the other), which no building has. The model is still built; the plan
// and `build` warn (overlapText).
struct CorridorOverlap {
  int a = -1, b = -1;   // corridor indices, a < b
  double areaM2 = 0;    // of floor they share
};
inline constexpr double kOverlapAreaM2 = 0.05;  // less is a corridor touching another's wall

struct BuildingPlan {
  std::vector<glm::dmat4> worldFromCorridor;  // one per corridor
  std::vector<Opening> openings;              // in hosts' walls and in guests' near ends
  std::vector<bool> attached;                 // true: the corridor starts at another's wall
  std::vector<CorridorOverlap> overlaps;      // pairs whose floors overlap by kOverlapAreaM2 or more
};

// One line: 'corridors "hall" and "wing" run through each other (2.4 m² of floor in
// both): move one of them'.
std::string overlapText(const Layout& layout, const CorridorOverlap& overlap);

// Places every corridor and finds the openings. Errors name the corridor and say
// what is wrong (an opening wider than the wall, an offset beyond the wall's end).
Result<BuildingPlan> planBuilding(const Layout& layout, const std::vector<metrology::Dimensions>& boxes);

}  // namespace pw::modeling
