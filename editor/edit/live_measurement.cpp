#include "editor/edit/live_measurement.h"

#include <exception>

#include "editor/edit/warnings.h"

namespace pw::edit {

LiveMeasurement measureLive(const metrology::Shot& shot) {
  LiveMeasurement live;
  try {
    if (auto vanishing = metrology::corridorVanishing(shot.cornersPx)) live.vanishing = *vanishing;
    auto measured = metrology::measureCorridor(shot);
    if (measured) {
      live.measurement = std::move(*measured);
      live.warnings = measurementWarnings(shot, *live.measurement);
    } else {
      live.error = measured.message();
    }
  } catch (const std::exception& e) {  // nothing a person does may end the editor
    live.measurement.reset();
    live.error = std::string("the measurement failed: ") + e.what();
  }
  return live;
}

}  // namespace pw::edit
