// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Empirical ceilings stored in a workspace (result sets of source "benchscope-ceilings", kernels/ceilings.h) and
// the peak table's "% of empirical ceiling": each row's peak against the rotation-mix ceiling of its platform and
// device, flagged (ceiling_check.h) above the computed peak or above the ceiling.
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "analysis/peaks/flops.h"
#include "model/flops_run.h"

namespace bs {

inline constexpr const char* kCeilingSource = "benchscope-ceilings";
inline constexpr const char* kRotationMixMetric = "rotation-mix ceiling";
inline constexpr const char* kFmaMetric = "fma ceiling";

struct EmpiricalCeiling {
  std::string platform, device, backend;  // backend: the CPU SIMD label it was measured with
  Summary flops;                          // the rotation-mix ceiling's repetitions, FLOP/s
  std::string how;                        // "rotation mix, <date>: <micro-kernel>"
};

// Every rotation-mix ceiling in the sets, in order.
std::vector<EmpiricalCeiling> empirical_ceilings(std::span<const ResultSet> sets);

// The ceiling for a platform and device: the latest measured with `backend` when there is one, else the highest
// of the device's; nullptr when the device has none.
const EmpiricalCeiling* ceiling_for(std::span<const EmpiricalCeiling> ceilings, const std::string& platform,
                                    const std::string& device, const std::string& backend);

// Fills each row's empirical ceiling and fraction of it, and adds the flags of compare_to_ceilings() (a peak
// above its computed peak is flagged even when the device has no ceiling).
void apply_empirical_ceilings(std::vector<PeakRow>& rows, std::span<const ResultSet> sets);

}  // namespace bs
