// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Synthetic checkerboard captures with ground truth, for checkerboard calibration tests: a board at a known pose,
// seen through a known lens, ray-traced per output pixel with supersampling so that its corners land with
// sub-pixel accuracy.
#include <filesystem>
#include <optional>
#include <string_view>
#include <vector>

#include <opencv2/core.hpp>

#include "vision/lens/checkerboard.h"
#include "vision/lens/lens.h"

namespace bs::vision {

// The board's pose in BenchScope's camera frame (x forward along the optical axis, y right, z up), millimetres
// and degrees. At zero rotation the board faces the camera, its columns run right (+y) and its rows down (-z),
// and (tx, ty, tz) is the board's centre. The rotation R = Rz(rz) Ry(ry) Rx(rx) turns the board about its
// centre: rx about the optical axis, ry tilts it up/down, rz swings it left/right.
struct BoardPose {
  double rx_deg = 0, ry_deg = 0, rz_deg = 0;
  double tx_mm = 300, ty_mm = 0, tz_mm = 0;
  cv::Matx33d rotation() const;
};

// "rx,ry,rz,tx,ty,tz"; throws std::invalid_argument with the reason.
BoardPose parse_pose(std::string_view text);
// One pose per line, '#' starts a comment; throws std::runtime_error naming the file and line.
std::vector<BoardPose> load_poses(const std::filesystem::path& path);

struct CheckerboardRender {
  Checkerboard board;
  int bits = 8;              // 8 (CV_8UC1) or 10, 12, 16 (CV_16UC1, values in the low bits)
  int supersample = 4;       // N x N samples per pixel
  double blur_sigma_px = 0;  // Gaussian blur after sampling (lens softness)
  double noise_sigma = 0;    // Gaussian noise, in grey levels of the output bit depth
  unsigned seed = 1;         // for the noise
};

// Grey image of the lens's size: dark squares (the corner square is dark) on a white board with a one-square
// white margin, a mid-grey background, black outside the lens's field of view.
cv::Mat render_checkerboard(const Lens& lens, const BoardPose& pose, const CheckerboardRender& how);

// Ground truth: where each inner corner (in Checkerboard::object_points order, with the board's centre at the
// pose's translation) lands in the image; nullopt when the lens cannot image it (beyond its field of view).
std::vector<std::optional<cv::Point2d>> board_corner_truth(const Lens& lens, const BoardPose& pose,
                                                           const Checkerboard& board);

}  // namespace bs::vision
