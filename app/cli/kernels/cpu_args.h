// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The CPU as this machine reports it, with the SIMD instruction set `--isa avx512|avx2|sse4|generic` asks for: how
// `bench kernels`, `run flops` and `devices` all start.
#include <optional>
#include <string>

#include "common/args.h"
#include "kernels/cpu/cpu_info.h"

namespace bs::cli {

// Throws UsageError for an instruction set this CPU does not have, or an unknown one.
kernels::CpuInfo cpu_from_args(const ParsedArgs& args);
// The same from --isa's value (absent: the best this CPU has).
kernels::CpuInfo cpu_from_isa(const std::optional<std::string>& isa);

}  // namespace bs::cli
