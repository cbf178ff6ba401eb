// Warnings that belong to handles: corners that coincide, lie on one line or cross
// their plane's quad, a vanishing point behind the camera, a principal point off the
// photo. Each names its handles, has a short label drawn beside them in a warning
// ring, and one line in words a person can act on ("P5 is almost on the line P3-P4
// (6.4 px from it): the length is uncertain to +-14%; ..."). Pure geometry on the
// shot and its live measurement: tested headless (tests/edit/handle_warnings_test.cpp).
#pragma once

#include <string>
#include <vector>

#include "metrology/measure.h"
#include "metrology/shot.h"

struct ImDrawList;

namespace pw::edit {

class Canvas;

// The principal point's handle, beside the corners P1..P8 (0..7).
inline constexpr int kPrincipalPointHandle = metrology::kCornerCount;

// Below kCollinearDeg a plane's three corners are on one line (as metrology's
// checkShot says: it cannot be measured); below kAlmostCollinearDeg they are almost,
// which is said when the measurement's dimension that plane fixes is uncertain beyond
// warnings.h's kUncertainFraction (or there is no measurement).
inline constexpr double kCollinearDeg = 0.5;
inline constexpr double kAlmostCollinearDeg = 3.0;
inline constexpr double kCoincidentPx = 0.5;

struct HandleWarning {
  std::vector<int> handles;  // corners 0..7, or kPrincipalPointHandle: ringed and labelled
  std::string label;         // beside the handle: "on P3-P4", "crossed", "P3 = P5", "VP behind"
  std::string text;          // one line in words, what is wrong and what to do
  bool blocking = false;     // the corners cannot be measured so (not only uncertain)
  std::string dimension;     // "length", "width", "height" when it says one is uncertain
  std::vector<int> related;  // corners it concerns without being the one to move (the line's): a thin ring
};

// Never throws; every number in the text finite. `measurement` is the shot's, or null
// when it cannot be measured. `moved` (P1..P8, or -1): the corner the person moved
// last; a warning about corners that include it names it as the one to move (a line
// it landed on, a quad it crossed), not a corner that stayed where it was.
std::vector<HandleWarning> handleWarnings(const metrology::Shot& shot, const metrology::Measurement* measurement,
                                          int moved = -1);

// Draws a ring in the warning colour (red when blocking, amber otherwise) around each
// warned handle, with its label (a handle's first warning only).
void drawHandleWarnings(ImDrawList* list, const Canvas& canvas, const metrology::Shot& shot,
                        const std::vector<HandleWarning>& warnings);

}  // namespace pw::edit
