// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// `devices`' ARM CPU section: the board, each cluster's core type with its NEON lanes, FMA units, clock and FP32
// peak (with the core table's source), the sum, and the device table's entry for the board.
#include <ostream>

#include <nlohmann/json.hpp>

#include "kernels/cpu/arm_cores.h"

namespace bs::cli {

void print_arm_cpu(const kernels::ArmCpu& cpu, std::ostream& out);
nlohmann::json arm_cpu_json(const kernels::ArmCpu& cpu);

}  // namespace bs::cli
