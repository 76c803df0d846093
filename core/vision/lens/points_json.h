// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Polylines in the lens tools' JSON files: a picked straight line (line_fit) and a mask polygon (tuner_state) are
// both arrays of [x, y] pairs, read and checked here so that a bad point is named the same way in both.
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>  // declarations only: the full header costs each includer ~2 s to compile
#include <opencv2/core.hpp>

namespace bs::vision {

// The points of `j`, an array of [x, y] number pairs (T: float or double). Throws std::invalid_argument naming the
// JSON pointer `at` ("/lines/3"), or the point ("/lines/3/7"), when it is not one; with `finite`, also when a
// coordinate is infinite or NaN.
template <class T>
std::vector<cv::Point_<T>> points_from_json(const nlohmann::json& j, const std::string& at, bool finite);

}  // namespace bs::vision
