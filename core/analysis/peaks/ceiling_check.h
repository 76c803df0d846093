// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A FLOPS figure against the two peaks BenchScope has for a device: the computed peak (a model: threads x clock x
// flops per cycle, cpu_info.h) and the empirical ceiling (the rotation kernel's instruction mix measured by a
// micro-kernel, kernels/ceilings.h). A figure above the computed peak is always flagged, with the reason, never
// shown silently above 100 %: within the empirical ceiling the model understates the core (more pipes or a higher
// clock than it assumes); above both, the figure itself is suspect. A figure above the empirical ceiling is
// flagged too: the ceiling was then measured under more load, or is not the fastest form of the mix.
#include <optional>
#include <string>
#include <vector>

#include "analysis/peaks/plausibility.h"

namespace bs {

namespace flag_code {
inline constexpr const char* kAboveComputedPeak = "above_computed_peak";
inline constexpr const char* kAboveEmpiricalCeiling = "above_empirical_ceiling";
}  // namespace flag_code

struct CeilingComparison {
  std::optional<double> fraction_of_peak;     // measured / computed peak
  std::optional<double> fraction_of_ceiling;  // measured / empirical ceiling
  std::vector<PlausibilityFlag> flags;
};

// `what` names the figure in the reasons ("throughput variant", "rotation-mix ceiling"); `ceiling_how` says how
// the ceiling was obtained (measured when, which micro-kernel). Peaks <= 0 count as unknown.
CeilingComparison compare_to_ceilings(double measured_flops, std::optional<double> computed_peak_flops,
                                      std::optional<double> empirical_ceiling_flops, const std::string& what,
                                      const std::string& ceiling_how = {});

// "98.3 %" or "n/a"; with a flag marker "⚠ 104.0 %" (text outputs and tables).
std::string fraction_text(std::optional<double> fraction, bool flagged = false);

}  // namespace bs
