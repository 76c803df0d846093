// SPDX-License-Identifier: GPL-3.0-or-later
// Checkerboard calibration against ground truth: views of a board at known poses rendered through a known
// Kannala-Brandt lens (vision/synthetic_checkerboard.h) must give that lens back; the conversion between
// BenchScope's lens and OpenCV's fisheye camera must agree with cv::fisheye's own projection both ways.
#include <QString>
#include <QTemporaryDir>
#include <QTest>
#include <cmath>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgcodecs.hpp>

#include "../../../support/checkerboard_lens.h"
#include "vision/frames/synthetic_checkerboard.h"
#include "vision/lens/checkerboard_calibration.h"
#include "vision/lens/fisheye_opencv.h"

using namespace bs::vision;

namespace {

constexpr double kPi = 3.14159265358979323846;

// The lens on a 1280x1024 sensor, its principal point off the centre.
Lens truth_lens() { return bs::test::checkerboard_truth_lens(1280, 1024, 645.3, 508.7); }

// Thirteen views: straight ahead, tilted, rolled, and swung out to 45-70 degrees off the axis in every direction.
std::vector<BoardPose> truth_poses() {
  std::vector<BoardPose> poses;
  for (const char* p :
       {"0,0,0,300,0,0", "15,20,0,350,0,0", "-10,-25,15,320,50,30", "0,0,45,300,300,0", "0,0,-45,300,-300,0",
        "0,-45,0,300,0,300", "0,45,0,300,0,-300", "0,0,70,150,412,0", "0,0,-70,150,-412,0", "20,-30,35,300,200,170",
        "-20,30,-35,300,-200,-170", "30,0,0,400,0,0", "0,30,30,250,0,0"})
    poses.push_back(parse_pose(p));
  return poses;
}

Checkerboard board() { return parse_board("10x7", 30); }

// 2x2 samples per pixel: the corners come out as accurately as with 4x4 or 8x8 (detected vs true RMS 0.06 px for
// all three) at a quarter of the rendering time.
CheckerboardRender render_settings() {
  CheckerboardRender how;
  how.board = board();
  how.supersample = 2;
  return how;
}

// Seven views of the board through `lens`: straight ahead, and swung out 45 degrees each way and diagonally.
std::vector<CalibrationImage> seven_views(const Lens& lens) {
  const CheckerboardRender how = render_settings();
  std::vector<CalibrationImage> images;
  int n = 0;
  for (const char* p : {"0,0,0,300,0,0", "0,0,45,300,300,0", "0,0,-45,300,-300,0", "0,-45,0,300,0,300",
                        "0,45,0,300,0,-300", "20,-30,35,300,200,170", "-20,30,-35,300,-200,-170"})
    images.push_back({"view " + std::to_string(++n), "", render_checkerboard(lens, parse_pose(p), how)});
  return images;
}

}  // namespace

class TestCheckerboardCalibration : public QObject {
  Q_OBJECT
 private slots:
  void conversion_round_trip() {
    const Lens lens = truth_lens();
    const OpenCvFisheye cam = to_opencv_fisheye(lens);
    QCOMPARE(cam.fx, 360.0);
    QCOMPARE(cam.fy, 360.0);
    QCOMPARE(cam.cx, 645.3);
    QCOMPARE(cam.cy, 508.7);
    const Lens back = lens_from_opencv_fisheye(cam, lens);
    QCOMPARE(back.type, LensType::KannalaBrandt);
    QVERIFY(std::abs(back.r_pp - lens.r_pp) < 1e-15);
    QVERIFY(back.k == lens.k);
    // An equidistant lens with its centre left at "image centre" (cx < 0) gets OpenCV's explicit centre.
    Lens eq = Lens::paper();
    const OpenCvFisheye c2 = to_opencv_fisheye(eq);
    QCOMPARE(c2.cx, 639.5);
    QCOMPARE(c2.cy, 511.5);
    QCOMPARE(lens_from_opencv_fisheye(c2, eq).type, LensType::Equidistant);
    eq.type = LensType::Stereographic;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, to_opencv_fisheye(eq));
  }

  void unequal_focal_lengths_use_the_geometric_mean() {
    OpenCvFisheye cam;
    cam.fx = 400;
    cam.fy = 404;
    cam.cx = 600;
    cam.cy = 500;
    const Lens l = lens_from_opencv_fisheye(cam, truth_lens());
    QVERIFY(std::abs(1 / l.r_pp - std::sqrt(400.0 * 404.0)) < 1e-9);
  }

  void projection_agrees_with_cv_fisheye() {
    const Lens lens = truth_lens();
    const OpenCvFisheye cam = to_opencv_fisheye(lens);
    cv::RNG rng(7);
    std::vector<cv::Point3d> points;
    for (int i = 0; i < 200; ++i) {
      // Directions up to 85 degrees off the axis (cv::fisheye divides by z, so it cannot go past 90).
      const double theta = rng.uniform(0.0, 85.0) * kPi / 180, phi = rng.uniform(0.0, 2 * kPi);
      const double dist = rng.uniform(100.0, 2000.0);
      points.emplace_back(dist * std::sin(theta) * std::cos(phi), dist * std::sin(theta) * std::sin(phi),
                          dist * std::cos(theta));
    }
    std::vector<cv::Point2d> theirs;
    cv::fisheye::projectPoints(points, theirs, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), cam.camera_matrix(),
                               cam.distortion());
    for (std::size_t i = 0; i < points.size(); ++i) {
      const auto ours = project_camera_point(lens, cv::Vec3d(points[i].x, points[i].y, points[i].z));
      QVERIFY(ours);
      QVERIFY2(cv::norm(*ours - theirs[i]) < 1e-6,
               qPrintable(QString("point %1: %2 px apart").arg(i).arg(cv::norm(*ours - theirs[i]))));
      // And back: the pixel's ray is the point's direction.
      const auto ray = camera_ray(lens, *ours);
      QVERIFY(ray);
      const cv::Vec3d dir = cv::Vec3d(points[i].x, points[i].y, points[i].z) / cv::norm(points[i]);
      QVERIFY(cv::norm(*ray - dir) < 1e-9);
    }
  }

  void rendered_corners_are_where_the_lens_puts_them() {
    const Lens lens = truth_lens();
    const BoardPose pose = parse_pose("10,-20,30,300,120,-60");
    CheckerboardRender how = render_settings();
    const cv::Mat image = render_checkerboard(lens, pose, how);
    QCOMPARE(image.type(), CV_8UC1);
    QCOMPARE(image.cols, 1280);
    std::string reason;
    const auto found = find_board_corners(image, how.board, &reason);
    QVERIFY2(found, reason.c_str());
    const auto truth = board_corner_truth(lens, pose, how.board);
    QCOMPARE(found->size(), truth.size());
    double worst = 0, sum = 0;
    for (const auto& c : *found) {
      double best = 1e9;
      for (const auto& t : truth) best = std::min(best, cv::norm(cv::Point2d(c) - *t));
      worst = std::max(worst, best);
      sum += best * best;
    }
    const double rms = std::sqrt(sum / static_cast<double>(found->size()));
    qInfo("detected vs true corners: RMS %.3f px, worst %.3f px", rms, worst);
    QVERIFY(rms < 0.1);
    QVERIFY(worst < 0.3);
    // 16-bit with noise and blur: values in the low bits, and the corners are still found.
    how.bits = 12;
    how.noise_sigma = 20;
    how.blur_sigma_px = 0.8;
    const cv::Mat wide = render_checkerboard(lens, pose, how);
    QCOMPARE(wide.type(), CV_16UC1);
    double max = 0;
    cv::minMaxLoc(wide, nullptr, &max);
    QVERIFY(max <= 4095 && max > 3000);
    QVERIFY(find_board_corners(wide, how.board));
  }

  void recovers_a_known_kannala_brandt_lens() {
    const Lens lens = truth_lens();
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    CheckerboardRender how = render_settings();
    how.noise_sigma = 1.0;
    std::vector<CalibrationImage> images;
    int n = 0;
    for (const auto& pose : truth_poses()) {
      const std::string path = dir.filePath(QString("view-%1.png").arg(++n)).toStdString();
      how.seed = static_cast<unsigned>(n);
      QVERIFY(cv::imwrite(path, render_checkerboard(lens, pose, how)));
      images.push_back({"", path, {}});
    }
    // Two views that must be rejected: a blank frame, and one whose board is behind the camera.
    const std::string blank = dir.filePath("blank.png").toStdString();
    QVERIFY(cv::imwrite(blank, cv::Mat(1024, 1280, CV_8UC1, cv::Scalar(128))));
    images.push_back({"", blank, {}});
    const std::string behind = dir.filePath("behind.png").toStdString();
    QVERIFY(cv::imwrite(behind, render_checkerboard(lens, parse_pose("0,0,0,-300,0,0"), how)));
    images.push_back({"", behind, {}});
    images.push_back({"", dir.filePath("missing.png").toStdString(), {}});

    Lens base = Lens::paper();
    base.fov_deg = 190;
    std::vector<double> fractions;
    const auto result = calibrate_checkerboard(images, board(), CalibrationModel::KannalaBrandt, base, nullptr,
                                               [&](double f, std::string_view) { fractions.push_back(f); });
    QVERIFY(!fractions.empty());
    QCOMPARE(fractions.back(), 1.0);
    for (const auto& r : result.images)
      qInfo("%s: %s", r.name.c_str(),
            r.used ? QString("RMS %1 px, up to %2 deg")
                         .arg(*r.rms_px, 0, 'f', 3)
                         .arg(r.max_theta_deg, 0, 'f', 0)
                         .toUtf8()
                         .constData()
                   : r.rejected.c_str());
    const Lens& got = result.lens;
    qInfo(
        "r_pp %.8g (truth %.8g, %.3f %%), centre (%.3f, %.3f) (truth (%.1f, %.1f)), k %.5f %.5f %.5f %.5f, RMS %.3f "
        "px, "
        "free fx %.3f fy %.3f",
        got.r_pp, lens.r_pp, 100 * (got.r_pp / lens.r_pp - 1), got.cx, got.cy, lens.cx, lens.cy, got.k[0], got.k[1],
        got.k[2], got.k[3], result.rms_px, result.fx, result.fy);
    for (const auto& w : result.warnings) qInfo("warning: %s", w.c_str());
    QCOMPARE(result.used(), 13);
    QCOMPARE(result.rejected(), 3);
    QCOMPARE(result.images[13].name, blank);
    QVERIFY(!result.images[13].used);
    QVERIFY(result.images[13].rejected.find("no checkerboard of 10x7 squares") != std::string::npos);
    QVERIFY(result.images[14].rejected.find("no checkerboard") != std::string::npos);
    QCOMPARE(result.images[15].rejected, std::string("no such file"));
    QCOMPARE(got.type, LensType::KannalaBrandt);
    QVERIFY(std::abs(got.r_pp / lens.r_pp - 1) < 0.005);
    QVERIFY(std::hypot(got.cx - lens.cx, got.cy - lens.cy) < 1.0);
    QVERIFY(result.rms_px < 0.3);
    QCOMPARE(got.width, 1280);
    QCOMPARE(got.fov_deg, 190.0);
    // The lens reproduces the true radius over the angles the views covered.
    for (double deg = 5; deg <= 75; deg += 5) {
      const double t = deg * kPi / 180;
      QVERIFY2(std::abs(*got.radius(t) - *lens.radius(t)) < 1.0, qPrintable(QString("at %1 deg").arg(deg)));
    }
    QCOMPARE(got.calibration.method, LensCalibration::Method::Checkerboard);
    QCOMPARE(got.calibration.images_used, 13);
    QCOMPARE(got.calibration.images_rejected, 3);
    QCOMPARE(*got.calibration.rms_px, result.rms_px);
    QVERIFY(got.calibration.detail.find("10x7 squares of 30 mm") != std::string::npos);
  }

  void a_degenerate_view_is_rejected_and_the_fit_goes_on() {
    // Corners straight from the ground truth (no rendering), plus one view whose "corners" are scattered at random
    // over the image (mis-detections no board pose explains): it must be named and dropped, not sink the fit.
    const Lens lens = truth_lens();
    std::vector<CalibrationImageResult> views;
    int n = 0;
    for (const auto& pose : truth_poses()) {
      CalibrationImageResult r;
      r.name = "view " + std::to_string(++n);
      for (const auto& c : board_corner_truth(lens, pose, board())) r.corners.emplace_back(cv::Point2f(*c));
      r.used = true;
      views.push_back(r);
    }
    CalibrationImageResult bad;
    bad.name = "degenerate";
    bad.used = true;
    cv::RNG rng(3);
    for (int k = 0; k < board().inner_corners().area(); ++k)
      bad.corners.emplace_back(static_cast<float>(rng.uniform(100.0, 1180.0)),
                               static_cast<float>(rng.uniform(100.0, 900.0)));
    views.insert(views.begin() + 4, bad);
    Lens base = lens;
    base.fov_deg = 190;
    const auto result =
        calibrate_from_corners(views, cv::Size(1280, 1024), board(), CalibrationModel::KannalaBrandt, base);
    for (const auto& r : result.images)
      qInfo("%s: %s %.3f", r.name.c_str(), r.used ? "used" : r.rejected.c_str(), r.rms_px.value_or(-1));
    for (const auto& w : result.warnings) qInfo("warning: %s", w.c_str());
    QVERIFY(!result.images[4].used);
    QVERIFY(!result.images[4].rejected.empty());
    // The views 85 degrees off the axis sit at cv::fisheye's conditioning threshold: with clang -O1 (the sanitizer
    // build) one of them is judged ill-conditioned, with GCC -O2 none. Dropping such a view is the right outcome
    // too; anything else dropped, or more than one such view, is a failure.
    int ill_conditioned = 0;
    for (std::size_t i = 0; i < result.images.size(); ++i) {
      if (i == 4 || result.images[i].used) continue;
      QVERIFY2(result.images[i].rejected.find("ill-conditioned") != std::string::npos, result.images[i].name.c_str());
      ++ill_conditioned;
    }
    QVERIFY(ill_conditioned <= 1);
    QCOMPARE(result.used(), 13 - ill_conditioned);
    // Exact corners: the lens comes back almost exactly.
    QVERIFY(std::abs(result.lens.r_pp / lens.r_pp - 1) < 1e-4);
    QVERIFY(std::hypot(result.lens.cx - lens.cx, result.lens.cy - lens.cy) < 0.05);
    QVERIFY(result.rms_px < 0.01);
    // A used view with the wrong number of corners is a caller's error.
    views[0].corners.pop_back();
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, calibrate_from_corners(views, cv::Size(1280, 1024), board(),
                                                                           CalibrationModel::KannalaBrandt, base));
  }

  void equidistant_model_keeps_k_at_zero() {
    Lens lens = Lens::paper();  // 195 degree equidistant
    lens.cx = 641.2;
    lens.cy = 510.4;
    const std::vector<CalibrationImage> images = seven_views(lens);
    const auto result = calibrate_checkerboard(images, board(), CalibrationModel::Equidistant, lens);
    qInfo("equidistant: r_pp %.8g (truth %.8g), centre (%.3f, %.3f), RMS %.3f px", result.lens.r_pp, lens.r_pp,
          result.lens.cx, result.lens.cy, result.rms_px);
    QCOMPARE(result.lens.type, LensType::Equidistant);
    QVERIFY(result.lens.k == (std::array<double, 4>{}));
    QVERIFY(std::abs(result.lens.r_pp / lens.r_pp - 1) < 0.005);
    QVERIFY(std::hypot(result.lens.cx - lens.cx, result.lens.cy - lens.cy) < 1.0);
    QVERIFY(result.rms_px < 0.3);
    // Issue #43.8: the images' rim lies where the fitted 195-degree circle does (no warning about it), and the lens
    // records how far off the axis its corners went and how sure its circle is.
    QVERIFY(result.rim);
    QVERIFY2(!result.rim->disagrees, result.rim->text.c_str());
    QVERIFY(result.lens.calibration.covered_deg);
    QCOMPARE(*result.lens.calibration.covered_deg, result.max_theta_deg);
    QVERIFY(result.lens.calibration.rim_radius_se_px && *result.lens.calibration.rim_radius_se_px < 5);
  }

  void a_fit_that_contradicts_the_images_rim_says_so_with_both_numbers() {
    // Issue #43.8: the lit disc ends at 174 degrees while the lens is taken to see 195 (the file says so): the fit's
    // 195-degree circle lies far outside the rim the images show, and the result says so with both radii.
    Lens optics = Lens::paper();
    optics.fov_deg = 174;
    const std::vector<CalibrationImage> images = seven_views(optics);
    const auto result = calibrate_checkerboard(images, board(), CalibrationModel::Equidistant, Lens::paper());
    QVERIFY(result.rim);
    QVERIFY(result.rim->disagrees);
    const double rim_truth = 87 * kPi / 180 / optics.r_pp, fit_truth = 97.5 * kPi / 180 / optics.r_pp;
    QVERIFY2(std::abs(result.rim->rim_radius_px - rim_truth) < 2, std::to_string(result.rim->rim_radius_px).c_str());
    QVERIFY(std::abs(result.rim->fitted_radius_px - fit_truth) < 5);
    bool said = false;
    for (const std::string& w : result.warnings)
      said = said || (w.find("disagrees with the image's detected rim") != std::string::npos &&
                      w.find(QString::number(result.rim->rim_radius_px, 'f', 1).toStdString()) != std::string::npos &&
                      w.find(QString::number(result.rim->fitted_radius_px, 'f', 1).toStdString()) != std::string::npos);
    QVERIFY(said);
  }

  void a_view_beyond_the_corners_says_so() {
    Lens lens = Lens::paper();
    lens.calibration.method = LensCalibration::Method::Checkerboard;
    lens.calibration.covered_deg = 57;
    View view;  // the paper's 150-degree output: its corners look 75 degrees off the axis
    QVERIFY(std::abs(view_reach_deg(lens, view) - 75) < 0.5);
    const std::string note = extrapolation_note(lens, view);
    QVERIFY2(
        note.find("reaches 75 degrees") != std::string::npos && note.find("covered 57 degrees") != std::string::npos,
        note.c_str());
    view.fov_deg = 90;  // within the corners
    QVERIFY(extrapolation_note(lens, view).empty());
    view.yaw_deg = 40;  // turned towards the edge: beyond them again
    QVERIFY(!extrapolation_note(lens, view).empty());
    lens.calibration.covered_deg.reset();  // not a checkerboard lens: nothing known, nothing said
    QVERIFY(extrapolation_note(lens, view).empty());
    // The covered angle and the circle's uncertainty travel in the lens file.
    lens.calibration.covered_deg = 57;
    lens.calibration.rim_radius_se_px = 1.5;
    const auto back = lens_from_json(lens_to_json(lens, view)).first;
    QCOMPARE(*back.calibration.covered_deg, 57.0);
    QCOMPARE(*back.calibration.rim_radius_se_px, 1.5);
  }

  void too_few_views_name_every_image() {
    std::vector<CalibrationImage> images{{"a.png", "", cv::Mat(100, 100, CV_8UC1, cv::Scalar(0))},
                                         {"b.png", "", cv::Mat(100, 100, CV_8UC1, cv::Scalar(255))}};
    try {
      calibrate_checkerboard(images, board(), CalibrationModel::KannalaBrandt, Lens::paper());
      QFAIL("expected an error");
    } catch (const std::runtime_error& e) {
      const std::string msg = e.what();
      QVERIFY(msg.find("at least 3 usable views") != std::string::npos);
      QVERIFY(msg.find("a.png: no checkerboard") != std::string::npos);
      QVERIFY(msg.find("b.png: no checkerboard") != std::string::npos);
    }
  }

  void cancel_stops_the_run() {
    bs::CancelToken cancel;
    cancel.cancel();
    std::vector<CalibrationImage> images{{"a.png", "", cv::Mat(100, 100, CV_8UC1, cv::Scalar(0))}};
    QVERIFY_THROWS_EXCEPTION(bs::Cancelled, calibrate_checkerboard(images, board(), CalibrationModel::KannalaBrandt,
                                                                   Lens::paper(), &cancel));
  }

  void parses_boards_and_poses() {
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, parse_board("10x", 30));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, parse_board("2x7", 30));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, parse_board("10x7", 0));
    QCOMPARE(parse_board("10x7", 25).inner_corners(), cv::Size(9, 6));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, parse_pose("1,2,3,4,5"));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, parse_pose("0,0,0,0,0,0"));
    const BoardPose p = parse_pose("0,0,90,300,0,0");
    // Swung 90 degrees about the vertical: the board's columns (+y at rest) now run along +x... toward the camera
    // axis, i.e. R * (0, 1, 0) = (-1, 0, 0).
    const cv::Vec3d col = p.rotation() * cv::Vec3d(0, 1, 0);
    QVERIFY(cv::norm(col - cv::Vec3d(-1, 0, 0)) < 1e-12);
    QCOMPARE(calibration_model_from_string("equidistant"), CalibrationModel::Equidistant);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, calibration_model_from_string("pinhole"));
  }
};

QTEST_GUILESS_MAIN(TestCheckerboardCalibration)
#include "test_checkerboard_calibration.moc"
