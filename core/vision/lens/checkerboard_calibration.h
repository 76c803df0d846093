// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Lens calibration from checkerboard photos: corners with OpenCV's findChessboardCornersSB (sub-pixel), the
// Kannala-Brandt fit with cv::fisheye::calibrate, the result as BenchScope's lens (fisheye_opencv.h).
//
// How images are rejected, each with its reason: unreadable; a different size from the first image; no board
// found; ill-conditioned in cv::fisheye (CALIB_CHECK_COND names the view, which is dropped only when the fit
// without the check does not keep it either; a failure that names none is traced by leaving one view out at a
// time); a reprojection error far above the others' (mis-detected corners); when every view fits badly, the view
// without which the RMS drops by more than half (one inconsistent view can drag all the others off).
//
// fx and fy: cv::fisheye fits both, BenchScope's lens has one focal length. The free fit's fx and fy are
// reported; the lens is then refitted with fx = fy = sqrt(fx fy) held fixed (centre, k and the poses adapt), and
// every RMS reported is that of the lens file's own model. A free-fit aspect fy/fx off 1 by more than
// kAspectWarning is a warning: the sensor's pixels are not square, or the views do not constrain the focal length.
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "util/cancel.h"
#include "vision/lens/checkerboard.h"
#include "vision/lens/lens.h"
#include "vision/lens/lens_limits.h"

namespace bs::vision {

enum class CalibrationModel { KannalaBrandt, Equidistant };  // equidistant: k1..k4 held at zero
std::string_view to_string(CalibrationModel m);
CalibrationModel calibration_model_from_string(std::string_view s);  // throws std::invalid_argument

inline constexpr double kAspectWarning = 0.002;  // |fy/fx - 1|

struct CalibrationImage {
  std::string name;  // shown in tables and reasons (a file name)
  std::string path;  // read when `image` is empty
  cv::Mat image;     // 8/16-bit, grey or BGR
};

struct CalibrationImageResult {
  std::string name;
  bool used = false;
  std::string rejected;              // the reason, empty when used
  std::vector<cv::Point2f> corners;  // found corners (also for images rejected after detection)
  std::optional<double> rms_px;      // reprojection RMS of this view under the calibrated lens
  double max_theta_deg = 0;          // the largest angle off the axis at which this view's corners were seen
};

struct CheckerboardResult {
  Lens lens;                                   // with lens.calibration filled
  std::vector<CalibrationImageResult> images;  // in the input order
  double rms_px = 0;                           // all used corners, the lens file's model
  double free_rms_px = 0;                      // cv::fisheye's own RMS of the free (fx, fy) fit
  double fx = 0, fy = 0;                       // the free fit's focal lengths, pixels
  double max_theta_deg = 0;                    // the widest angle covered by used corners
  // The field of view's circle (the lens's FOV/2 ray) against the rim detected in the images (issue #43.8): nullopt
  // when no image shows a rim. A disagreement beyond the uncertainties is also among the warnings, with both numbers.
  std::optional<RimComparison> rim;
  std::vector<std::string> warnings;
  int used() const;
  int rejected() const;
};

// Finds the board's inner corners (sub-pixel) or says why not in `reason`.
std::optional<std::vector<cv::Point2f>> find_board_corners(const cv::Mat& image, const Checkerboard& board,
                                                           std::string* reason = nullptr);

// `base` gives what a checkerboard does not measure (field of view) and is the starting point. Throws
// std::runtime_error when fewer than 3 views remain (the message lists every image with its reason),
// bs::Cancelled when `cancel` fires. `progress` may be called from several threads at once.
CheckerboardResult calibrate_checkerboard(const std::vector<CalibrationImage>& images, const Checkerboard& board,
                                          CalibrationModel model, const Lens& base, const CancelToken* cancel = nullptr,
                                          const ProgressFn& progress = {});

// The fit alone, for corners found elsewhere: `images` with `used` set and their corners (inner_corners().area()
// each, in Checkerboard::object_points order), all from images of `size`. Throws as calibrate_checkerboard, and
// std::invalid_argument for a used view with the wrong number of corners.
CheckerboardResult calibrate_from_corners(std::vector<CalibrationImageResult> images, cv::Size size,
                                          const Checkerboard& board, CalibrationModel model, const Lens& base,
                                          const CancelToken* cancel = nullptr, const ProgressFn& progress = {});

}  // namespace bs::vision
