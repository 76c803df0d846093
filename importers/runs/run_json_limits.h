// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Limits of the run JSON format itself (docs/run-json-v1.md), shared by its reader (run_json.cpp) and its writer
// (run_json_write.cpp).
#include <cstdint>

namespace bs::run_json_limits {

constexpr std::int64_t kMaxIterations = std::int64_t{1} << 40;
constexpr std::int64_t kMaxWorkers = std::int64_t{1} << 40;
constexpr int kMaxDims = 64;

}  // namespace bs::run_json_limits
