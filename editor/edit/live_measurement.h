// What the editor shows of a shot as it is, measured again at each change (a drag
// step): the measurement, or why there is none, the vanishing geometry of the corners
// as given (drawn even when the box cannot be measured), and the warnings.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "editor/edit/handle_warnings.h"
#include "metrology/input_sigma.h"
#include "metrology/measure.h"
#include "metrology/shot.h"
#include "metrology/vanishing.h"

namespace pw::edit {

struct LiveMeasurement {
  std::optional<metrology::Measurement> measurement;
  std::string error;  // why there is no measurement (one line), when there is none
  std::optional<metrology::CorridorVanishing> vanishing;
  std::vector<std::string> warnings;  // warnings.h
  std::vector<HandleWarning> handleWarnings;  // handle_warnings.h: on the handles and in words
};

// Never throws, whatever the corners: a failure is `error`.
// The measurement's ± carries the inputs by `origins` (metrology/input_sigma.h).
// `moved`: the corner the person moved last (P1..P8, or -1), which the warnings name as
// the one to move back.
LiveMeasurement measureLive(const metrology::Shot& shot, const metrology::InputOrigins& origins = {}, int moved = -1);

}  // namespace pw::edit
