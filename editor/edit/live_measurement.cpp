#include "editor/edit/live_measurement.h"

#include <exception>
#include <string>

#include "editor/edit/warnings.h"

namespace pw::edit {

LiveMeasurement measureLive(const metrology::Shot& shot, const metrology::InputOrigins& origins, int moved) {
  LiveMeasurement live;
  try {
    if (auto vanishing = metrology::corridorVanishing(shot.cornersPx)) live.vanishing = *vanishing;
    auto measured = metrology::measureCorridor(shot, metrology::withInputSigmas({}, shot, origins));
    if (measured) {
      live.measurement = std::move(*measured);
      int culprit = -1;
      live.warnings = measurementWarnings(shot, *live.measurement, {}, &culprit);
      live.handleWarnings = handleWarnings(shot, &*live.measurement, moved);
      if (culprit >= 0) {  // the corner that breaks the box: said on its handle
        const std::string prefix = "the corners do not make one box";
        for (auto it = live.warnings.begin(); it != live.warnings.end(); ++it) {
          if (it->rfind(prefix, 0) != 0) continue;
          live.handleWarnings.push_back({{culprit}, "off the box", *it, false, "", {}});
          live.warnings.erase(it);
          break;
        }
      }
    } else {
      live.error = measured.message();
      live.handleWarnings = handleWarnings(shot, nullptr, moved);
    }
    // A dimension's uncertainty said on the handle to move is not said again in general.
    for (const HandleWarning& w : live.handleWarnings) {
      if (w.dimension.empty()) continue;
      const std::string general = "the " + w.dimension + " is uncertain";
      std::erase_if(live.warnings, [&](const std::string& line) { return line.rfind(general, 0) == 0; });
    }
  } catch (const std::exception& e) {  // nothing a person does may end the editor
    live.measurement.reset();
    live.error = std::string("the measurement failed: ") + e.what();
  }
  return live;
}

}  // namespace pw::edit
