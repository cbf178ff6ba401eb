// Warnings a person can act on, from a measurement that succeeded: a box larger than
// any interior (its scale's units: metrology::implausibleSize), which number is
// uncertain and what to do about it, which corner disagrees with the fitted box.
#pragma once

#include <string>
#include <vector>

#include "metrology/measure.h"
#include "metrology/shot.h"

namespace pw::edit {

// Thresholds: a dimension uncertain beyond kUncertainFraction (one standard deviation
// at the measurement's corner sigma), a corner farther than kCornerOffPx from where the
// fitted box puts it, receding edges that miss their vanishing point by more than
// kVanishingResidualPx (RMS), a reference length off by more than kReferencePercent.
inline constexpr double kUncertainFraction = 0.10;
inline constexpr double kCornerOffPx = 3.0;
inline constexpr double kVanishingResidualPx = 2.0;
inline constexpr double kReferencePercent = 5.0;

// One line each; empty when all is well. `measurement` is `shot` measured with
// `options`; a box that misses the corners is refitted (up to eight times) to find the
// corner to check (`*culpritCorner`, when given: that corner, -1 when none is named).
std::vector<std::string> measurementWarnings(const metrology::Shot& shot, const metrology::Measurement& measurement,
                                             const metrology::MeasureOptions& options = {}, int* culpritCorner = nullptr);

}  // namespace pw::edit
