// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/lens/checkerboard.h"

#include <cstdio>
#include <stdexcept>
#include <string>

namespace bs::vision {

std::vector<cv::Point3f> Checkerboard::object_points() const {
  std::vector<cv::Point3f> pts;
  const cv::Size inner = inner_corners();
  pts.reserve(static_cast<std::size_t>(inner.area()));
  for (int j = 0; j < inner.height; ++j)
    for (int i = 0; i < inner.width; ++i)
      pts.emplace_back(static_cast<float>(i * square_mm), static_cast<float>(j * square_mm), 0.f);
  return pts;
}

void Checkerboard::validate() const {
  if (cols < 3 || rows < 3 || cols > 100 || rows > 100)
    throw std::invalid_argument("a checkerboard needs 3 to 100 squares per side, got " + std::to_string(cols) + "x" +
                                std::to_string(rows));
  if (!(square_mm > 0) || square_mm > 10000) throw std::invalid_argument("the square size must be in (0, 10000] mm");
}

Checkerboard parse_board(std::string_view text, double square_mm) {
  Checkerboard b;
  char extra = 0;
  const std::string s(text);
  if (std::sscanf(s.c_str(), "%dx%d%c", &b.cols, &b.rows, &extra) != 2)
    throw std::invalid_argument("board '" + s + "': expected COLSxROWS squares, e.g. 10x7");
  b.square_mm = square_mm;
  b.validate();
  return b;
}

}  // namespace bs::vision
