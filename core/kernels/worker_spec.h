// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <cstdint>
#include <string_view>
#include <vector>

namespace bs::kernels {

// Parses worker lists: "256:1024000:256" (start:stop:step, stop included when hit), "1,2,4,8", or mixes
// "1,2,4:64:4". Result is sorted and unique. Throws std::invalid_argument with a message naming the bad part:
// zero/negative numbers or step, start > stop, junk, more than `max_points` points, a count above kMaxStatePoints
// (rotation.h), overflow.
std::vector<std::int64_t> parse_worker_spec(std::string_view spec, std::size_t max_points = 1'000'000);

// "1,2,4" -> {1, 2, 4} for D; each in 1..64.
std::vector<int> parse_dims_list(std::string_view spec);

}  // namespace bs::kernels
