// The building's plan, seen from above: where each corridor of a layout stands, the
// snapping that attaches one corridor's near end to another's far wall or side wall
// (the layout's `attach` entries, which make the openings), and the plan's edits.
// Pure geometry on modeling::Layout, tested headless (tests/edit/plan_test.cpp).
//
// Plan coordinates are the world's floor (x, z) in metres (README "Coordinate
// conventions"): a corridor's near-end centre is its `position`, it runs along its
// local -z to the far wall, and rotation_deg turns it counter-clockwise seen from above.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "metrology/measure.h"
#include "modeling/layout.h"

namespace pw::edit {

// A corridor as the plan shows it: its near-end centre (world x, z) and its rotation.
struct PlanPose {
  glm::dvec2 nearCentre{0.0};
  double rotationDeg = 0;
};

// Every corridor's world-from-corridor transform, placed ones from their position and
// attached ones from their host (modeling::attachedTransform), whether or not the
// attachment fits (modeling::planBuilding says so). `boxes`: one per corridor.
std::vector<glm::dmat4> placeCorridors(const modeling::Layout& layout, const std::vector<metrology::Dimensions>& boxes);

PlanPose poseOf(const glm::dmat4& worldFromCorridor);

// The footprint's corners in plan (x, z): near left, near right, far right, far left.
std::array<glm::dvec2, 4> footprintCorners(const glm::dmat4& worldFromCorridor, const metrology::Dimensions& box);
// A plan point in the corridor's own frame (x across, z along: 0 at the near end,
// -length at the far wall).
glm::dvec2 toCorridor(const glm::dmat4& worldFromCorridor, const glm::dvec2& planPoint);
// The corridor whose footprint holds `planPoint` (the last listed, drawn on top), or -1.
int corridorAt(const std::vector<glm::dmat4>& world, const std::vector<metrology::Dimensions>& boxes,
               const glm::dvec2& planPoint);

// True for `corridor` and every corridor attached to it, directly or through others:
// what moves with it.
std::vector<bool> movesWith(const modeling::Layout& layout, int corridor);

struct Snap {
  modeling::Attachment attach;
  PlanPose pose;      // where the guest stands once attached
  double distanceM = 0;  // how far its near-end centre moves to get there
};

// Within this of the far wall's centre, a far attachment is centred (offset 0).
inline constexpr double kCentreSnapM = 0.25;

// The attachment nearest to `guestPose` for corridor `guest`: its near-end centre
// within `snapDistanceM` of another corridor's far wall (offset along that wall,
// centred within kCentreSnapM) or of one of its side walls (offset from that
// corridor's near end, kept so the guest's opening fits in the wall). Corridors that
// move with the guest are not candidates. None when nothing is near enough.
std::optional<Snap> findSnap(const modeling::Layout& layout, const std::vector<metrology::Dimensions>& boxes,
                             const std::vector<glm::dmat4>& world, int guest, const PlanPose& guestPose,
                             double snapDistanceM);

// Where an attached corridor opens into its host, in plan (x, z): the two ends of the
// opening in the host's wall (modeling::planBuilding's opening, seen from above); none
// for a placed corridor.
std::optional<std::array<glm::dvec2, 2>> openingInHost(const modeling::Layout& layout,
                                                       const std::vector<metrology::Dimensions>& boxes,
                                                       const std::vector<glm::dmat4>& world, int corridor);

// The plan's edits, each returning the new layout.
// Places corridor `i` at `pose` (detaching it; its position's height is kept).
modeling::Layout placeCorridor(modeling::Layout layout, int i, const PlanPose& pose);
// Attaches corridor `i` as `attach` says, then lists the corridors so that each comes
// after the one it attaches to (the file's rule), keeping their order otherwise.
// `attach.to` must not move with `i`. Returns the layout and where `i` now is.
modeling::Layout attachCorridor(modeling::Layout layout, int i, const modeling::Attachment& attach, int* newIndex);
// Removes corridor `i`; the corridors attached to it stay where they are, placed. The
// last corridor stays (a layout has one at least).
modeling::Layout removeCorridor(modeling::Layout layout, const std::vector<glm::dmat4>& world, int i);
// Turns corridor `i` by `deltaDeg` about its near-end centre, the rotation kept in
// (-180, 180]. An attached corridor keeps its attachment: the placed corridor it hangs
// from (through others) turns about its own near end, and all attached to it with it.
modeling::Layout rotateCorridor(modeling::Layout layout, const std::vector<glm::dmat4>& world, int i, double deltaDeg);

// Every field writeLayoutFile writes, equal.
bool sameLayout(const modeling::Layout& a, const modeling::Layout& b);

// Where the plan lies in a window: plan point (x, z) at window offset + scale * (x, z).
struct PlanTransform {
  double scale = 20;  // window pixels per metre
  glm::dvec2 offset{0.0};
  glm::dvec2 toWindow(const glm::dvec2& planPoint) const { return offset + scale * planPoint; }
  glm::dvec2 toPlan(const glm::dvec2& windowPx) const { return (windowPx - offset) / scale; }
};

// The transform that shows all of `points` in the window rectangle [min, max), centred,
// with a margin.
PlanTransform fitPlan(const std::vector<glm::dvec2>& points, const glm::dvec2& min, const glm::dvec2& max);

}  // namespace pw::edit
