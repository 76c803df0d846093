// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/peaks/ceiling_check.h"

#include "analysis/stats/units.h"
#include "util/text.h"

namespace bs {
namespace {

std::string percent(double f) { return format_number("%.1f %%", 100.0 * f); }

}  // namespace

CeilingComparison compare_to_ceilings(double measured, std::optional<double> peak, std::optional<double> ceiling,
                                      const std::string& what, const std::string& ceiling_how) {
  CeilingComparison out;
  if (peak && *peak > 0) out.fraction_of_peak = measured / *peak;
  if (ceiling && *ceiling > 0) out.fraction_of_ceiling = measured / *ceiling;
  const std::string figure = what + " " + format_si(measured, "FLOPS");
  const std::string how = ceiling_how.empty() ? "" : " (" + ceiling_how + ")";
  if (out.fraction_of_peak && *out.fraction_of_peak > 1.0) {
    std::string reason = figure + " is " + percent(*out.fraction_of_peak) + " of the computed peak " +
                         format_si(*peak, "FLOPS") + " (threads x measured clock x the model's flops per cycle). ";
    if (out.fraction_of_ceiling && *out.fraction_of_ceiling <= 1.0)
      reason += "It is within the empirical ceiling " + format_si(*ceiling, "FLOPS") + how +
                ": the model understates this core (more pipes, or a higher clock under vector load, than it "
                "assumes); judge the figure by the empirical ceiling.";
    else if (out.fraction_of_ceiling)
      reason += "It is above the empirical ceiling " + format_si(*ceiling, "FLOPS") + how +
                " too: check the timing and that every counted flop ran.";
    else
      reason +=
          "No empirical ceiling was measured for this device: the model may understate the core, or the "
          "timing or the flop count is wrong; measure the ceilings (bench kernels, devices --measure).";
    out.flags.push_back({flag_code::kAboveComputedPeak, reason});
  }
  if (out.fraction_of_ceiling && *out.fraction_of_ceiling > 1.0)
    out.flags.push_back({flag_code::kAboveEmpiricalCeiling,
                         figure + " is " + percent(*out.fraction_of_ceiling) + " of the empirical ceiling " +
                             format_si(*ceiling, "FLOPS") + how +
                             ": the ceiling was measured under more load from other processes (compare per "
                             "CPU-second, or measure both in the same minutes), or its micro-kernel is not the "
                             "fastest form of this instruction mix."});
  return out;
}

std::string fraction_text(std::optional<double> fraction, bool flagged) {
  if (!fraction) return "n/a";
  return (flagged ? "\xE2\x9A\xA0 " : "") + percent(*fraction);
}

}  // namespace bs
