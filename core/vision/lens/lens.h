// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Fisheye lens models and the paper's reprojection to a rectilinear view (Biddulph et al. 2018, eq. 2).
//
// Conventions, as in the paper: screen-centred coordinates, (0, 0) in the middle of the image, +x right, +y up.
// The camera looks along +x of the ray space; a ray v = normalise(f, s_x, s_y) makes the angle theta = acos(v_x)
// with the optical axis, and lands in the fisheye image at radius r(theta) in the direction of (v_y, v_z).
#include <array>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json_fwd.hpp>  // declarations only: the full header costs each includer ~2 s to compile
#include <opencv2/core.hpp>

namespace bs::vision {

enum class LensType { Equidistant, Equisolid, Stereographic, Orthographic, Rectilinear, KannalaBrandt };
std::string_view to_string(LensType t);
LensType lens_type_from_string(std::string_view s);  // throws std::invalid_argument

// How a lens's parameters were obtained, so that every view can say how far to trust them.
struct LensCalibration {
  enum class Method { Manual, CircleFit, Checkerboard, LineFit };
  Method method = Method::Manual;
  std::optional<double> rms_px;  // reprojection error (checkerboard) or residual (line fit), pixels
  int images_used = 0;           // checkerboard: images whose corners were found and used
  int images_rejected = 0;
  std::string detail;  // free text: board, model, line count, fit residual before/after...
  // Checkerboard (issue #43.8): the widest angle off the axis at which corners were seen, in degrees; beyond it the
  // model is extrapolated, and a view reaching further says so (lens/lens_limits.h).
  std::optional<double> covered_deg;
  // Checkerboard: the standard error of the field of view's circle radius (pixels, leave-one-image-out refits): how
  // far a detected image rim may lie from the fitted circle before the two disagree.
  std::optional<double> rim_radius_se_px;
};
std::string_view to_string(LensCalibration::Method m);
LensCalibration::Method calibration_method_from_string(std::string_view s);  // throws std::invalid_argument
// One line for the user: "checkerboard, 12 images, RMS 0.31 px" / "manual".
std::string describe(const LensCalibration& c);

struct Lens {
  LensType type = LensType::Equidistant;
  double r_pp = 0;            // radians per pixel (the paper's r_pp); the focal length in pixels is 1 / r_pp
  std::array<double, 4> k{};  // Kannala-Brandt: theta_d = theta (1 + k1 theta^2 + k2 theta^4 + k3 theta^6 + k4 theta^8)
  double cx = -1, cy = -1;    // principal point in source pixels; < 0 means the image centre
  double fov_deg = 195;       // field of view of the lens: rays beyond fov/2 from the axis are outside the circle
  int width = 1280, height = 1024;  // source image size
  LensCalibration calibration;      // how the values above were obtained (lens files: "calibration", optional)

  // Radius in pixels at which a ray `theta` radians off the axis lands; nullopt when the model cannot image it.
  std::optional<double> radius(double theta) const;
  cv::Point2d centre() const;
  void validate() const;  // throws std::invalid_argument naming the bad field

  // The paper's camera: 1280x1024, 195 degree equidistant, r_pp = 195 degrees / 1280 px.
  static Lens paper();
};

// The rectilinear view to produce.
struct View {
  int width = 1280, height = 1024;
  double fov_deg = 150;  // diagonal-based, as the paper: f = |(W-1, H-1)| / (2 tan(FOV/2))
  double yaw_deg = 0, pitch_deg = 0, roll_deg = 0;
  double focal_px() const;
  void validate() const;
};

// Rotation taking a ray of the output camera (x forward, y right, z up) into the lens's ray space: yaw about z,
// then pitch about y, then roll about the optical x axis (R = yaw * pitch * roll).
cv::Matx33d view_rotation(const View& view);

nlohmann::json lens_to_json(const Lens& lens, const View& view);
std::pair<Lens, View> lens_from_json(const nlohmann::json& j);  // throws std::invalid_argument naming the field

// For output pixel (x, y): where in the fisheye image it comes from (source pixel coordinates), or nullopt when
// the ray is outside the lens's field of view or the source image. Exactly the paper's equations for equidistant.
std::optional<cv::Point2d> source_of(const Lens& lens, const View& view, double x, double y);

// Lookup table built once per parameter set: CV_32FC2 with the source (x, y) of every output pixel, (-1, -1) where
// there is none. Float keeps sub-pixel precision for bilinear sampling; OpenCV's convertMaps can turn it into the
// fixed-point CV_16SC2 + CV_16UC1 pair.
cv::Mat build_reprojection_map(const Lens& lens, const View& view);

// Samples `src` (8/16-bit, 1 or 3 channels) through the map with bilinear interpolation; pixels without a source,
// or whose source lies under a non-zero `mask` pixel (same size as src, CV_8UC1, may be empty), get `fill`.
cv::Mat reproject(const cv::Mat& src, const cv::Mat& map, const cv::Mat& mask = {},
                  const cv::Scalar& fill = cv::Scalar::all(0));

// The lookup table of one lens + view, built once and applied to every frame. It keeps both forms:
//  - map():   CV_32FC2, float (x, y) source position per output pixel, (-1, -1) where there is none;
//  - applied: OpenCV's fixed-point pair from convertMaps, CV_16SC2 integer (x, y) + CV_16UC1 index of the 5-bit
//             x and y fractions (1/32 pixel), which remap() reads with less memory traffic and no float work.
// The fixed-point grid is the one the fused path (fused.h) uses, so both give the same sampling positions.
class ReprojectionLut {
 public:
  ReprojectionLut(const Lens& lens, const View& view);
  const cv::Mat& map() const { return map_; }
  cv::Size source_size() const { return source_; }
  // As reproject(): bilinear, `fill` outside the image circle, the source, or under a non-zero `mask` pixel.
  cv::Mat apply(const cv::Mat& src, const cv::Mat& mask = {}, const cv::Scalar& fill = cv::Scalar::all(0)) const;

 private:
  cv::Mat map_, fixed_xy_, fixed_fraction_;
  cv::Size source_;
};

}  // namespace bs::vision
