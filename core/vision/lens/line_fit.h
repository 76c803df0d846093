// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Straight-line ("plumb-line") refinement of a fisheye lens: points the user picked along lines that are straight
// in the world must, through the right lens, become rays on one plane through the camera centre each (a great
// circle on the sphere of rays), which is what makes them straight in every rectilinear view. A Levenberg-Marquardt
// fit of the Kannala-Brandt model (r_pp, principal point, k1..k4) minimises their distance from those planes.
//
// What lines cannot tell: any linear map of the rays that keeps the optical axis, v -> (v_x, s v_y, s v_z), maps
// every plane through the centre to another one, so straightness is blind to a change of scale s of tan(theta)
// (a focal-length change in every rectilinear view). The fit therefore keeps the rim of the image circle fixed:
// the ray fov/2 off the axis stays on the circle the circle fit measured (the start lens's, unless given), which
// pins s, but only where lines reach the rim: with clicks a few tenths of a pixel off, r(theta) can still follow
// that family by a few pixels half way out while every line is straight to the click noise (the tests measure it).
// Where the focal length is known (a datasheet), hold r_pp fixed (LineFitOptions::fixed) and the family is gone.
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>  // declarations only: the full header costs each includer ~2 s to compile
#include <opencv2/core.hpp>

#include "vision/lens/lens.h"

namespace bs::vision {

using PickedLine = std::vector<cv::Point2d>;  // source (fisheye) pixels along one line that is straight in the world

// Unit ray (x forward, y right, z up) of a fisheye source pixel; nullopt where the model has no inverse (a
// Kannala-Brandt polynomial that turns back before that radius). Not limited to the FOV.
std::optional<cv::Vec3d> pixel_to_ray(const Lens& lens, const cv::Point2d& source_px);

// Output pixel of the rectilinear view where a source pixel appears, for overlays of picked points; unlike
// view_geometry.h's output_of() not limited to the lens's FOV or the output image; nullopt behind the view.
std::optional<cv::Point2d> view_pixel_of(const Lens& lens, const View& view, const cv::Point2d& source_px);

// The Kannala-Brandt lens closest to `lens` (least squares of r(theta) over [0, fov/2]; exact for equidistant and
// for Kannala-Brandt itself). Centre, size, FOV and calibration record are kept.
Lens to_kannala_brandt(const Lens& lens);

struct LineStraightness {
  double rms_px = 0;  // RMS distance in source pixels of the points from the image of their line's best 3D line
  double max_px = 0;
  int lines = 0, points = 0;
};
// Each line's rays get their best plane through the camera centre (least squares); a point's distance is how far,
// in source pixels, it lies from that plane's image curve (to first order). Lines with fewer than 3 points are
// skipped. Throws std::invalid_argument when a point has no ray or no line has 3 points.
LineStraightness line_straightness(const Lens& lens, const std::vector<PickedLine>& lines);

struct LineFitOptions {
  double circle_radius_px = 0;  // radius(fov/2) held fixed; <= 0: the start lens's
  int max_iterations = 200;
  // Parameters held at the start's value, in the order r_pp, cx, cy, k1, k2, k3, k4.
  std::array<bool, 7> fixed{};
  // > 0: lines that are no lines of the world (two lines meeting at a slight angle, an edge that bends) are left
  // out: after a fit, every line whose straightness RMS under the fitted lens exceeds max(reject_lines x the
  // median line's, 0.1 px) is dropped and the fit repeated from the start over the others, until the set settles
  // (4 rounds at most). For proposed lines (edge_proposals.h), where a few such edges always get in; 3 suits.
  double reject_lines = 0;
};
// "r_pp", "cx", "cy", "centre" (both), "k1".."k4", comma-separated -> LineFitOptions::fixed; throws
// std::invalid_argument naming the unknown name.
std::array<bool, 7> fixed_parameters_from_string(const std::string& names);
struct LineFitResult {
  Lens lens;  // Kannala-Brandt, calibration = line-fit with RMS after and the residual before/after in detail
  LineStraightness before, after;  // source pixels, over the lines used (all but rejected_lines)
  int iterations = 0;
  std::vector<int> rejected_lines;  // indices into the lines given, left out by LineFitOptions::reject_lines
};
// Needs at least 3 lines of 3+ points. Throws std::invalid_argument naming the line and point without a ray.
LineFitResult fit_lens_to_lines(const Lens& start, const std::vector<PickedLine>& lines,
                                const LineFitOptions& options = {});

// The points file of `benchscope-cli lens refine-lines` and the Lens tab's "Save lines":
// {"format": "benchscope-lines", "version": 1, "width": W, "height": H, "lines": [[[x, y], [x, y], ...], ...]}
// with source-pixel coordinates (x right, y down, origin at the top-left pixel's centre); width/height optional.
nlohmann::json lines_to_json(const std::vector<PickedLine>& lines, int width, int height);
std::vector<PickedLine> lines_from_json(const nlohmann::json& j);  // throws std::invalid_argument naming the field
void save_lines_json(const std::vector<PickedLine>& lines, int width, int height, const std::filesystem::path& path);
std::vector<PickedLine> load_lines_json(const std::filesystem::path& path);  // throws std::runtime_error naming file

}  // namespace bs::vision
