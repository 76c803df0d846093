// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/lens/checkerboard_calibration.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <sstream>
#include <stdexcept>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include "image_files/image_files.h"
#include "util/text.h"
#include "vision/lens/circle_detect.h"
#include "vision/lens/fisheye_opencv.h"
#include "vision/lens/stretch_8bit.h"

namespace bs::vision {
namespace {

constexpr double kPi = 3.14159265358979323846;
// A rim found along fewer rays is too little of the circle to judge the fit by (a board filling the view hides it).
constexpr int kMinRimPoints = 180;

// 8-bit grey for the corner finder: 16-bit images are stretched by their maximum (any bit depth in the low bits).
cv::Mat grey8(const cv::Mat& image) {
  cv::Mat grey = image;
  if (image.channels() == 3)
    cv::cvtColor(image, grey, cv::COLOR_BGR2GRAY);
  else if (image.channels() == 4)
    cv::cvtColor(image, grey, cv::COLOR_BGRA2GRAY);
  return stretch_to_8bit(grey);
}

// The view cv::fisheye's CALIB_CHECK_COND names ("... Ill-conditioned matrix for input array N"), or -1.
int ill_conditioned_view(const cv::Exception& e) {
  static const std::string marker = "Ill-conditioned matrix for input array ";
  const std::string text = e.err.empty() ? e.what() : e.err;
  const auto at = text.find(marker);
  if (at == std::string::npos) return -1;
  int index = -1;
  std::istringstream(text.substr(at + marker.size())) >> index;
  return index;
}

std::string short_error(const cv::Exception& e) { return e.err.empty() ? std::string(e.what()) : e.err; }

struct Fit {
  cv::Matx33d K;
  cv::Vec4d D;
  std::vector<cv::Vec3d> rvecs, tvecs;
  double rms = 0;
};

// Per-view RMS reprojection error of a cv::fisheye fit (its own K, D and poses), pixels.
std::vector<double> view_errors(const Fit& fit, const std::vector<int>& views, const Checkerboard& board,
                                const std::vector<CalibrationImageResult>& results) {
  const auto object = board.object_points();
  const std::vector<cv::Point3d> obj(object.begin(), object.end());
  std::vector<double> errors;
  for (std::size_t i = 0; i < views.size(); ++i) {
    std::vector<cv::Point2d> projected;
    cv::fisheye::projectPoints(obj, projected, fit.rvecs[i], fit.tvecs[i], fit.K, fit.D);
    const auto& corners = results[static_cast<std::size_t>(views[i])].corners;
    double s = 0;
    for (std::size_t k = 0; k < projected.size(); ++k)
      s += std::pow(projected[k].x - corners[k].x, 2) + std::pow(projected[k].y - corners[k].y, 2);
    errors.push_back(std::sqrt(s / static_cast<double>(projected.size())));
  }
  return errors;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

// A view reprojects far worse than the others: above both 1 px and 4x the median view's error.
bool outlier(double error, double median_error) { return error > std::max(1.0, 4 * median_error); }

class Calibrator {
 public:
  Calibrator(std::vector<CalibrationImageResult>& results, const Checkerboard& board, cv::Size size,
             const CancelToken* cancel)
      : results_(results), board_(board), object_(board.object_points()), size_(size), cancel_(cancel) {}

  // cv::fisheye::calibrate over `views`, dropping (and marking rejected) the views that make it fail.
  Fit fit(std::vector<int>& views, int flags, const cv::Matx33d& K0, const cv::Vec4d& D0) {
    while (true) {
      if (cancel_) cancel_->throw_if_cancelled();
      require_views(views);
      try {
        return run(views, flags, K0, D0);
      } catch (const cv::Exception& e) {
        const int idx = ill_conditioned_view(e);
        if (idx >= 0 && idx < static_cast<int>(views.size())) {
          // CALIB_CHECK_COND judges a view's pose under the intrinsics of that iteration, and flags good views too
          // (exact synthetic corners of a frontal board, for one). The fit without the check decides: a view it
          // reprojects like the others is kept.
          if (auto unchecked = try_run(views, flags & ~cv::fisheye::CALIB_CHECK_COND, K0, D0)) {
            const auto errors = view_errors(*unchecked, views, board_, results_);
            const double err = errors[static_cast<std::size_t>(idx)], med = median(errors);
            if (!outlier(err, med)) {
              note(results_[static_cast<std::size_t>(views[static_cast<std::size_t>(idx)])].name +
                   ": CALIB_CHECK_COND flagged it, but without the check it reprojects at " +
                   format_number("%.3f", err) + " px (median view " + format_number("%.3f", med) + " px): kept");
              return *unchecked;
            }
          }
          reject(views[static_cast<std::size_t>(idx)],
                 "ill-conditioned in cv::fisheye (CALIB_CHECK_COND): the board is too small, too oblique or too "
                 "far off the axis in this view");
          views.erase(views.begin() + idx);
          continue;
        }
        // A failure that names no view (e.g. InitExtrinsics' assertion): find the view without which it succeeds.
        const int culprit = leave_one_out(views, flags, K0, D0);
        if (culprit < 0)
          throw std::runtime_error("cv::fisheye::calibrate failed with every view left out in turn: " + short_error(e));
        reject(views[static_cast<std::size_t>(culprit)],
               "cv::fisheye::calibrate fails with this view and succeeds without it (" + short_error(e) + ")");
        views.erase(views.begin() + culprit);
      }
    }
  }

  void reject(int view, const std::string& reason) {
    auto& r = results_[static_cast<std::size_t>(view)];
    r.used = false;
    r.rejected = reason;
  }

  std::optional<Fit> try_run(const std::vector<int>& views, int flags, const cv::Matx33d& K0,
                             const cv::Vec4d& D0) const {
    try {
      return run(views, flags, K0, D0);
    } catch (const cv::Exception&) {
      return std::nullopt;
    }
  }

  std::vector<std::string> notes_;  // checks that were overruled, for the result's warnings
  void note(const std::string& text) {
    if (std::find(notes_.begin(), notes_.end(), text) == notes_.end()) notes_.push_back(text);
  }

  void require_views(const std::vector<int>& views) const {
    if (views.size() >= 3) return;
    std::string msg =
        "checkerboard calibration needs at least 3 usable views, " + std::to_string(views.size()) + " left:";
    for (const auto& r : results_) msg += "\n  " + r.name + ": " + (r.rejected.empty() ? "used" : r.rejected);
    throw std::runtime_error(msg);
  }

 private:
  Fit run(const std::vector<int>& views, int flags, const cv::Matx33d& K0, const cv::Vec4d& D0) const {
    std::vector<std::vector<cv::Point3f>> obj(views.size(), object_);
    std::vector<std::vector<cv::Point2f>> img;
    for (int v : views) img.push_back(results_[static_cast<std::size_t>(v)].corners);
    Fit f;
    f.K = K0;
    f.D = D0;
    f.rms = cv::fisheye::calibrate(obj, img, size_, f.K, f.D, f.rvecs, f.tvecs, flags,
                                   cv::TermCriteria(cv::TermCriteria::COUNT + cv::TermCriteria::EPS, 200, 1e-12));
    return f;
  }

  int leave_one_out(const std::vector<int>& views, int flags, const cv::Matx33d& K0, const cv::Vec4d& D0) const {
    if (views.size() <= 3) return -1;
    for (std::size_t i = 0; i < views.size(); ++i) {
      if (cancel_) cancel_->throw_if_cancelled();
      std::vector<int> rest = views;
      rest.erase(rest.begin() + static_cast<long>(i));
      try {
        run(rest, flags, K0, D0);
        return static_cast<int>(i);
      } catch (const cv::Exception&) {
      }
    }
    return -1;
  }

  std::vector<CalibrationImageResult>& results_;
  Checkerboard board_;
  std::vector<cv::Point3f> object_;
  cv::Size size_;
  const CancelToken* cancel_;
};

// Per-view reprojection errors under BenchScope's own lens model (the lens file), with the fit's poses.
void measure(const Lens& lens, const Fit& fit, const std::vector<int>& views, const Checkerboard& board,
             std::vector<CalibrationImageResult>& results, double* total_rms, double* max_theta_deg) {
  Lens unclipped = lens;
  unclipped.fov_deg = 360;  // errors are measured wherever corners were seen
  const auto object = board.object_points();
  double sum = 0;
  std::size_t count = 0;
  *max_theta_deg = 0;
  for (std::size_t i = 0; i < views.size(); ++i) {
    auto& r = results[static_cast<std::size_t>(views[i])];
    cv::Matx33d R;
    cv::Rodrigues(fit.rvecs[i], R);
    double view_sum = 0;
    std::size_t n = 0;
    r.max_theta_deg = 0;
    for (std::size_t k = 0; k < object.size(); ++k) {
      const cv::Vec3d p = R * cv::Vec3d(object[k].x, object[k].y, object[k].z) + fit.tvecs[i];
      r.max_theta_deg = std::max(r.max_theta_deg, std::acos(std::clamp(p[2] / cv::norm(p), -1.0, 1.0)) * 180 / kPi);
      const auto px = project_camera_point(unclipped, p);
      const double e2 = px ? std::pow(px->x - r.corners[k].x, 2) + std::pow(px->y - r.corners[k].y, 2) : 1e6;
      view_sum += e2;
      ++n;
    }
    r.rms_px = std::sqrt(view_sum / static_cast<double>(n));
    sum += view_sum;
    count += n;
    *max_theta_deg = std::max(*max_theta_deg, r.max_theta_deg);
  }
  *total_rms = count ? std::sqrt(sum / static_cast<double>(count)) : 0;
}

}  // namespace

std::string_view to_string(CalibrationModel m) {
  return m == CalibrationModel::Equidistant ? "equidistant" : "kannala-brandt";
}

CalibrationModel calibration_model_from_string(std::string_view s) {
  if (s == "kannala-brandt") return CalibrationModel::KannalaBrandt;
  if (s == "equidistant") return CalibrationModel::Equidistant;
  throw std::invalid_argument("unknown calibration model '" + std::string(s) +
                              "' (expected kannala-brandt or equidistant)");
}

int CheckerboardResult::used() const {
  return static_cast<int>(std::count_if(images.begin(), images.end(), [](const auto& r) { return r.used; }));
}

int CheckerboardResult::rejected() const { return static_cast<int>(images.size()) - used(); }

std::optional<std::vector<cv::Point2f>> find_board_corners(const cv::Mat& image, const Checkerboard& board,
                                                           std::string* reason) {
  board.validate();
  if (image.empty()) {
    if (reason) *reason = "empty image";
    return std::nullopt;
  }
  const cv::Mat grey = grey8(image);
  std::vector<cv::Point2f> corners;
  const cv::Size inner = board.inner_corners();
  // The sector-based detector is sub-pixel accurate by itself (CALIB_CB_ACCURACY) and copes with the strong
  // distortion of fisheye views better than the classic detector followed by cornerSubPix. Histogram
  // normalisation flattens the anti-aliased edges (corner RMS 0.10 px instead of 0.06 px on synthetic views), so it
  // and the exhaustive search are only the second try, for dim or low-contrast views.
  bool found = cv::findChessboardCornersSB(grey, inner, corners, cv::CALIB_CB_ACCURACY);
  if (!found)
    found = cv::findChessboardCornersSB(grey, inner, corners,
                                        cv::CALIB_CB_NORMALIZE_IMAGE | cv::CALIB_CB_EXHAUSTIVE | cv::CALIB_CB_ACCURACY);
  if (!found || static_cast<int>(corners.size()) != inner.area()) {
    if (reason)
      *reason = "no checkerboard of " + std::to_string(board.cols) + "x" + std::to_string(board.rows) + " squares (" +
                std::to_string(inner.width) + "x" + std::to_string(inner.height) + " inner corners) found";
    return std::nullopt;
  }
  return corners;
}

CheckerboardResult calibrate_checkerboard(const std::vector<CalibrationImage>& images, const Checkerboard& board,
                                          CalibrationModel model, const Lens& base, const CancelToken* cancel,
                                          const ProgressFn& progress) {
  board.validate();
  CheckerboardResult result;
  result.images.resize(images.size());
  std::vector<cv::Size> sizes(images.size());
  std::vector<std::optional<ImageCircle>> rims(images.size());  // each image's lit disc, where it shows one
  std::atomic<int> done{0};
  std::atomic<bool> cancelled{false};
  std::mutex progress_mutex;
  const int n = static_cast<int>(images.size());

  // 1. Corners, one view per thread (the corner finder is the slow part: about a second per megapixel view).
#pragma omp parallel for schedule(dynamic, 1)
  for (int i = 0; i < n; ++i) {
    if (cancelled || (cancel && cancel->cancelled())) {
      cancelled = true;
      continue;
    }
    const auto& in = images[static_cast<std::size_t>(i)];
    auto& r = result.images[static_cast<std::size_t>(i)];
    r.name = in.name.empty() ? in.path : in.name;
    std::error_code ec;
    const bool missing = in.image.empty() && !std::filesystem::is_regular_file(in.path, ec);
    const cv::Mat image = in.image.empty() && !missing
                              ? bs::image_files::read(in.path, cv::IMREAD_ANYDEPTH | cv::IMREAD_GRAYSCALE)
                              : in.image;
    if (image.empty()) {
      r.rejected = missing ? "no such file" : "cannot read the image";
    } else {
      sizes[static_cast<std::size_t>(i)] = image.size();
      rims[static_cast<std::size_t>(i)] = detect_image_circle(image);
      std::string reason;
      if (auto corners = find_board_corners(image, board, &reason)) {
        r.corners = std::move(*corners);
        r.used = true;
      } else {
        r.rejected = reason;
      }
    }
    const int finished = ++done;
    if (progress) {
      std::lock_guard lock(progress_mutex);
      progress(0.85 * finished / std::max(1, n), "corners: " + r.name);
    }
  }
  if (cancelled) throw Cancelled();

  // 2. One image size: the first readable image's.
  cv::Size size;
  for (int i = 0; i < n; ++i) {
    auto& r = result.images[static_cast<std::size_t>(i)];
    const cv::Size s = sizes[static_cast<std::size_t>(i)];
    if (s.empty()) continue;
    if (size.empty())
      size = s;
    else if (s != size && r.used) {
      r.used = false;
      r.rejected = std::to_string(s.width) + "x" + std::to_string(s.height) + " px, but the first image is " +
                   std::to_string(size.width) + "x" + std::to_string(size.height) + " px";
    }
  }
  CheckerboardResult out = calibrate_from_corners(std::move(result.images), size, board, model, base, cancel, progress);
  // The images' own rim (the median one, among images of the calibration's size that show enough of it) against the
  // fitted field-of-view circle.
  std::vector<ImageCircle> seen;
  for (int i = 0; i < n; ++i)
    if (const auto& rim = rims[static_cast<std::size_t>(i)];
        rim && sizes[static_cast<std::size_t>(i)] == size && rim->edge_points >= kMinRimPoints)
      seen.push_back(*rim);
  if (!seen.empty()) {
    std::sort(seen.begin(), seen.end(), [](const ImageCircle& a, const ImageCircle& b) { return a.radius < b.radius; });
    out.rim = compare_with_rim(out.lens, seen[seen.size() / 2]);
    if (out.rim && out.rim->disagrees) out.warnings.push_back(out.rim->text);
  }
  return out;
}

CheckerboardResult calibrate_from_corners(std::vector<CalibrationImageResult> images, cv::Size size,
                                          const Checkerboard& board, CalibrationModel model, const Lens& base,
                                          const CancelToken* cancel, const ProgressFn& progress) {
  board.validate();
  CheckerboardResult result;
  result.images = std::move(images);
  std::vector<int> views;
  for (std::size_t i = 0; i < result.images.size(); ++i) {
    auto& r = result.images[i];
    if (r.used && static_cast<int>(r.corners.size()) != board.inner_corners().area())
      throw std::invalid_argument(r.name + ": " + std::to_string(r.corners.size()) + " corners, the board has " +
                                  std::to_string(board.inner_corners().area()));
    if (r.used) views.push_back(static_cast<int>(i));
  }

  Calibrator calibrator(result.images, board, size, cancel);
  calibrator.require_views(views);
  if (progress) progress(0.88, "cv::fisheye::calibrate");
  int flags = cv::fisheye::CALIB_RECOMPUTE_EXTRINSIC | cv::fisheye::CALIB_FIX_SKEW | cv::fisheye::CALIB_CHECK_COND;
  if (model == CalibrationModel::Equidistant)
    flags |=
        cv::fisheye::CALIB_FIX_K1 | cv::fisheye::CALIB_FIX_K2 | cv::fisheye::CALIB_FIX_K3 | cv::fisheye::CALIB_FIX_K4;
  const cv::Matx33d K0 = cv::Matx33d::eye();  // cv::fisheye starts from f = max(w, h) / pi at the image centre
  const cv::Vec4d D0(0, 0, 0, 0);

  // 3. The free fit; then views whose corners reproject far worse than the others' are dropped and it reruns.
  Fit free = calibrator.fit(views, flags, K0, D0);
  for (std::size_t round = 0; round < result.images.size() / 3 + 1; ++round) {
    const std::vector<double> errors = view_errors(free, views, board, result.images);
    const double med = median(errors);
    const auto worst = static_cast<std::size_t>(std::max_element(errors.begin(), errors.end()) - errors.begin());
    if (views.size() <= 3) break;
    if (outlier(errors[worst], med)) {
      calibrator.reject(views[worst], "reprojection error " + format_number("%.2f", errors[worst]) +
                                          " px, more than 4x the "
                                          "median view's " +
                                          format_number("%.2f", med) + " px (corners mis-detected?)");
      views.erase(views.begin() + static_cast<long>(worst));
      calibrator.notes_.clear();  // notes on the fit this view spoiled no longer hold
      free = calibrator.fit(views, flags, K0, D0);
      continue;
    }
    if (med <= 1.0) break;
    // Every view fits badly: one inconsistent view can drag the whole fit away, so that no view stands out.
    // The view without which the fit improves most, and by more than half, is the one.
    std::optional<std::size_t> culprit;
    double best = free.rms;
    for (std::size_t i = 0; i < views.size(); ++i) {
      if (cancel) cancel->throw_if_cancelled();
      std::vector<int> rest = views;
      rest.erase(rest.begin() + static_cast<long>(i));
      if (const auto f = calibrator.try_run(rest, flags & ~cv::fisheye::CALIB_CHECK_COND, K0, D0); f && f->rms < best) {
        best = f->rms;
        culprit = i;
      }
    }
    if (!culprit || best > free.rms / 2) break;
    calibrator.reject(views[*culprit], "without this view the fit's RMS drops from " + format_number("%.2f", free.rms) +
                                           " px to " + format_number("%.2f", best) +
                                           " px (corners no board pose explains)");
    views.erase(views.begin() + static_cast<long>(*culprit));
    calibrator.notes_.clear();  // notes on the fit this view spoiled no longer hold
    free = calibrator.fit(views, flags, K0, D0);
  }
  result.fx = free.K(0, 0);
  result.fy = free.K(1, 1);
  result.free_rms_px = free.rms;
  if (progress) progress(0.94, "refit with fx = fy");

  // 4. BenchScope's lens has one focal length: refit with fx = fy = sqrt(fx fy) held, so centre, k and poses
  //    adapt to it instead of the average being imposed afterwards.
  const double f = std::sqrt(result.fx * result.fy);
  const cv::Matx33d Kiso(f, 0, free.K(0, 2), 0, f, free.K(1, 2), 0, 0, 1);
  const Fit iso = calibrator.fit(
      views, flags | cv::fisheye::CALIB_USE_INTRINSIC_GUESS | cv::fisheye::CALIB_FIX_FOCAL_LENGTH, Kiso, free.D);
  Lens lens = base;
  lens.width = size.width;
  lens.height = size.height;
  lens = lens_from_opencv_fisheye(OpenCvFisheye::from(iso.K, iso.D), lens);
  if (model == CalibrationModel::KannalaBrandt) lens.type = LensType::KannalaBrandt;
  measure(lens, iso, views, board, result.images, &result.rms_px, &result.max_theta_deg);

  // 5. What the numbers do not say by themselves.
  result.warnings = calibrator.notes_;
  const double aspect = result.fy / result.fx;
  if (std::abs(aspect - 1) > kAspectWarning)
    result.warnings.push_back("the free fit's fy/fx is " + format_number("%.4f", aspect) + " (fx " +
                              format_number("%.2f", result.fx) + " px, fy " + format_number("%.2f", result.fy) +
                              " px): BenchScope's lens has one focal length, "
                              "refitted at " +
                              format_number("%.2f", f) +
                              " px; non-square pixels or views that do not pin "
                              "the focal length down");
  for (double deg = 0.5; deg <= lens.fov_deg / 2; deg += 0.5) {
    const auto r0 = lens.radius((deg - 0.5) * kPi / 180), r1 = lens.radius(deg * kPi / 180);
    if (r0 && r1 && *r1 <= *r0) {
      result.warnings.push_back("the fitted polynomial folds back at " + format_number("%.1f", deg) +
                                " degrees off the axis, "
                                "inside the lens's " +
                                format_number("%.0f", lens.fov_deg) + " degree field of view");
      break;
    }
  }
  if (result.max_theta_deg < lens.fov_deg / 2 - 5)
    result.warnings.push_back("corners were seen up to " + format_number("%.0f", result.max_theta_deg) +
                              " degrees off the "
                              "axis; beyond that, up to the lens's " +
                              format_number("%.1f", lens.fov_deg / 2) + " degrees, the model is extrapolated");

  // The uncertainty of the field of view's circle: its radius over leave-one-image-out refits (jackknife standard
  // error). A rim detected farther away than a few of these contradicts the fit (lens_limits.h).
  if (views.size() >= 4) {
    std::vector<double> radii;
    for (std::size_t i = 0; i < views.size(); ++i) {
      if (cancel) cancel->throw_if_cancelled();
      std::vector<int> rest = views;
      rest.erase(rest.begin() + static_cast<long>(i));
      const auto fit = calibrator.try_run(
          rest, (flags & ~cv::fisheye::CALIB_CHECK_COND) | cv::fisheye::CALIB_USE_INTRINSIC_GUESS, free.K, free.D);
      if (!fit) continue;
      const double fi = std::sqrt(fit->K(0, 0) * fit->K(1, 1));
      const Lens li = lens_from_opencv_fisheye(
          OpenCvFisheye::from(cv::Matx33d(fi, 0, fit->K(0, 2), 0, fi, fit->K(1, 2), 0, 0, 1), fit->D), lens);
      if (const auto r = li.radius(lens.fov_deg / 2 * kPi / 180)) radii.push_back(*r);
    }
    if (radii.size() >= 3) {
      double mean = 0, ss = 0;
      for (double r : radii) mean += r / static_cast<double>(radii.size());
      for (double r : radii) ss += (r - mean) * (r - mean);
      const double n = static_cast<double>(radii.size());
      lens.calibration.rim_radius_se_px = std::sqrt((n - 1) / n * ss);
    }
  }
  lens.calibration.covered_deg = result.max_theta_deg;
  lens.calibration.method = LensCalibration::Method::Checkerboard;
  lens.calibration.rms_px = result.rms_px;
  lens.calibration.images_used = result.used();
  lens.calibration.images_rejected = result.rejected();
  lens.calibration.detail = std::to_string(board.cols) + "x" + std::to_string(board.rows) + " squares of " +
                            format_number("%g", board.square_mm) + " mm, " + std::string(to_string(model)) +
                            " model; free fit fx " + format_number("%.2f", result.fx) + " px, fy " +
                            format_number("%.2f", result.fy) + " px, refitted with f = " + format_number("%.2f", f) +
                            " px; corners up to " + format_number("%.0f", result.max_theta_deg) + " deg off axis";
  result.lens = lens;
  if (progress) progress(1.0, "done");
  return result;
}

}  // namespace bs::vision
