// What the editor draws over the photo with ImGui's draw lists, in window pixels: the
// five planes as translucent quads, the box's edges, the four receding edges extended
// to the vanishing point, the horizon, the fitted box projected back (where the model
// disagrees with the photo), the eight labelled handles coloured by role; and the
// loupe's crosshair and the edges that meet at its corner. The loupe's pixels are an
// ImageView of the photo (nearest-neighbour) that the renderer draws under ImGui.
#pragma once

#include <array>
#include <optional>

#include <glm/glm.hpp>

#include "editor/edit/canvas.h"
#include "engine/gpu/view.h"
#include "metrology/measure.h"
#include "metrology/shot.h"
#include "metrology/vanishing.h"

struct ImDrawList;

namespace pw::edit {

// Corner roles: the far wall (P1..P4), the near floor (P5, P6), the near ceiling (P7, P8).
enum class CornerRole { kFarWall, kNearFloor, kNearCeiling };
CornerRole cornerRole(int corner);
// RGBA 0..255, for handles and their edges.
glm::u8vec4 roleColour(CornerRole role);

// The three corners joined to `corner` by the box's edges: along the width, along the
// height, along the corridor.
std::array<int, 3> cornerNeighbours(int corner);

// The corner whose handle is nearest `windowPx`, within `radiusPx`; -1 when none.
int handleAt(const Canvas& canvas, const metrology::Shot& shot, const glm::dvec2& windowPx, double radiusPx);

struct OverlayInput {
  const Canvas* canvas = nullptr;
  const metrology::Shot* shot = nullptr;
  int selected = -1;
  const metrology::CorridorVanishing* vanishing = nullptr;  // from the corners as given; null: none
  const metrology::Measurement* measurement = nullptr;     // null: the corners cannot be measured
  std::array<std::optional<double>, metrology::kCornerCount> confidence{};  // shown beside the label
};

// Draws everything but the loupe into `list` (within its current clip rectangle).
void drawOverlay(ImDrawList* list, const OverlayInput& input);

// A magnified, nearest-neighbour view of the photo around one corner, beside the cursor.
struct Loupe {
  static constexpr double kSizePx = 168;
  static constexpr double kMinScale = 8;  // screen pixels per photo pixel, whatever the photo's size
  static constexpr double kMaxScale = 64;
  int corner = -1;
  WindowRect rect;                    // in the window
  engine::ImageTransform transform;   // the photo in the window, within `rect`
  glm::dvec2 centre() const { return rect.centre(); }
};

// The loupe for `corner` beside `besidePx` (the cursor, or the handle when nudging),
// kept inside the canvas: the corner at its centre, at 4 times the canvas's scale
// rounded to whole screen pixels per photo pixel, within [kMinScale, kMaxScale].
Loupe placeLoupe(const Canvas& canvas, const glm::dvec2& cornerPx, int corner, const glm::dvec2& besidePx);

// The crosshair, the edges from the loupe's corner to its three neighbours (drawn
// through the loupe at its scale) and its border.
void drawLoupe(ImDrawList* list, const Loupe& loupe, const metrology::Shot& shot);

}  // namespace pw::edit
