// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A printed calibration checkerboard: COLS x ROWS squares of one size. OpenCV counts inner corners, which are
// (COLS - 1) x (ROWS - 1): a board of 10x7 squares has 9x6 inner corners.
#include <string_view>
#include <vector>

#include <opencv2/core.hpp>

namespace bs::vision {

struct Checkerboard {
  int cols = 10, rows = 7;  // squares
  double square_mm = 30;    // side of one square
  cv::Size inner_corners() const { return {cols - 1, rows - 1}; }
  // The inner corners in the board's plane (z = 0), millimetres, row by row from the first inner corner, in the
  // order findChessboardCornersSB reports them.
  std::vector<cv::Point3f> object_points() const;
  void validate() const;  // throws std::invalid_argument: at least 3x3 squares, at most 100 per side, size > 0
};

// "COLSxROWS" (squares), e.g. "10x7"; throws std::invalid_argument with the reason.
Checkerboard parse_board(std::string_view text, double square_mm);

}  // namespace bs::vision
