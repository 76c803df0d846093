// SPDX-License-Identifier: GPL-3.0-or-later
#include "kernels/cpu_args.h"

#include <stdexcept>

#include "kernels/rotation/rotation_simd.h"

namespace bs::cli {

kernels::CpuInfo cpu_from_args(const ParsedArgs& args) { return cpu_from_isa(args.value("--isa")); }

kernels::CpuInfo cpu_from_isa(const std::optional<std::string>& isa) {
  kernels::CpuInfo cpu = kernels::detect_cpu();
  if (isa) {
    try {
      kernels::use_simd_target(cpu, kernels::simd_target_by_id(*isa));
    } catch (const std::invalid_argument& e) {
      throw UsageError(e.what());
    }
  }
  return cpu;
}

}  // namespace bs::cli
