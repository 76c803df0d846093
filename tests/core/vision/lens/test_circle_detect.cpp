// SPDX-License-Identifier: GPL-3.0-or-later
#include <QTest>
#include <cmath>

#include <opencv2/imgproc.hpp>

#include "vision/frames/synthetic.h"
#include "vision/frames/synthetic_room.h"
#include "vision/lens/circle_detect.h"
#include "vision/lens/straight_line.h"

using namespace bs::vision;

namespace {

constexpr double kPi = 3.14159265358979323846;

// Darkness-weighted centre of the chart line near column `guess` in each row: the line is dark (0.05) in a light
// quiet zone (0.9, 14 px wide each side here), so the weight is zero outside the line.
std::vector<cv::Point2d> trace_vertical_line(const cv::Mat& bgr, double guess, int y0, int y1) {
  cv::Mat gray;
  cv::cvtColor(bgr, gray, cv::COLOR_BGR2GRAY);
  std::vector<cv::Point2d> pts;
  for (int y = y0; y <= y1; y += 4) {
    // The darkest pixel within 40 px of the guess is on the line (checkerboard squares are 0.3, the line 0.05).
    int best = static_cast<int>(guess);
    for (int x = static_cast<int>(guess) - 40; x <= static_cast<int>(guess) + 40; ++x)
      if (gray.at<std::uint8_t>(y, x) < gray.at<std::uint8_t>(y, best)) best = x;
    double sw = 0, sx = 0;
    for (int x = best - 6; x <= best + 6; ++x) {
      const double w = std::max(0.0, 200.0 - gray.at<std::uint8_t>(y, x));
      sw += w;
      sx += w * x;
    }
    if (sw > 0) pts.emplace_back(sx / sw, y);
  }
  return pts;
}

}  // namespace

class TestCircleDetect : public QObject {
  Q_OBJECT
 private slots:
  void finds_offset_circles_of_different_radii() {
    struct Case {
      LensType type;
      double fov, radius, cx, cy;
    };
    // 640x512 frames; FOV under 174 degrees so the chart (which ends ~87 degrees off axis) fills the circle.
    const std::vector<Case> cases = {{LensType::Equidistant, 160, 220, 330.0, 250.0},
                                     {LensType::Equidistant, 170, 180, 290.5, 270.25},
                                     {LensType::Equisolid, 150, 240, 322.0, 241.0},
                                     {LensType::Equidistant, 160, 290, 318.0, 260.0}};  // cut by the top and bottom
    for (const auto& k : cases) {
      Lens lens;
      lens.type = k.type;
      lens.width = 640;
      lens.height = 512;
      lens.fov_deg = k.fov;
      lens.cx = k.cx;
      lens.cy = k.cy;
      lens.r_pp = 1;
      lens.r_pp = *lens.radius(k.fov * kPi / 360) / k.radius;  // puts fov/2 on the wanted radius
      const cv::Mat frame = render_fisheye(lens);
      const auto c = detect_image_circle(frame);
      QVERIFY(c.has_value());
      qInfo("true centre (%.2f, %.2f) r %.2f -> found (%.2f, %.2f) r %.2f, rms %.3f px over %d points", k.cx, k.cy,
            k.radius, c->centre.x, c->centre.y, c->radius, c->rms_px, c->edge_points);
      QVERIFY(std::hypot(c->centre.x - k.cx, c->centre.y - k.cy) < 2);
      QVERIFY(std::abs(c->radius - k.radius) < 2);
      Lens guess = lens;
      guess.cx = guess.cy = -1;
      guess.r_pp = lens.r_pp * 1.3;
      const Lens proposed = propose_lens(guess, *c);
      // r_pp within the 2 px radius tolerance, and the proposed lens puts fov/2 on the detected circle.
      QVERIFY(std::abs(proposed.r_pp - lens.r_pp) / lens.r_pp < 2.0 / k.radius);
      QVERIFY(std::abs(*proposed.radius(k.fov * kPi / 360) - c->radius) < 1e-6);
      QCOMPARE(proposed.cx, c->centre.x);
      // A disc that ends before the lens's FOV: r_pp from the angle it does end at.
      const Lens inner = propose_lens(guess, *c, k.fov - 20);
      QVERIFY(std::abs(*inner.radius((k.fov - 20) * kPi / 360) - c->radius) < 1e-6);
    }
    QVERIFY(!detect_image_circle(cv::Mat::zeros(100, 100, CV_8UC3)).has_value());
  }
  // Issue #20 part 1: the room scene lights the whole circle, dark lines and dark objects reach the rim, the sensor
  // cuts the circle at top and bottom (and for the paper's lens touches it left and right); vignetting, noise,
  // black level and 8 to 16 bits. The fit must land within 0.5 px (centre) and 0.3 % (radius) of the truth. The
  // threshold-and-contour fit this replaced was 105 px off in the centre on the first case.
  void robust_fit_meets_the_tolerances_on_room_captures() {
    struct Case {
      const char* name;
      LensType type;
      double fov, radius, cx, cy;
      RoomOptions room;
    };
    const std::vector<Case> cases = {
        {"paper lens, clean, 8-bit, seed 1", LensType::Equidistant, 195, 640, 639.5, 511.5, {8, 0, 0, 0, 1}},
        {"paper lens, clean, 8-bit, seed 2", LensType::Equidistant, 195, 640, 639.5, 511.5, {8, 0, 0, 0, 2}},
        {"offset, vignetting 0.5, noise 1 %, 8-bit",
         LensType::Equidistant,
         195,
         600,
         652.3,
         498.7,
         {8, 0.5, 0.01, 0, 4}},
        {"offset, vignetting 0.6, noise 2 %, 16-bit",
         LensType::Equidistant,
         195,
         600,
         652.3,
         498.7,
         {16, 0.6, 0.02, 0, 5}},
        {"offset, vignetting 0.3, noise 0.5 %, black 3 %, 12-bit",
         LensType::Equidistant,
         195,
         605,
         631.8,
         520.25,
         {12, 0.3, 0.005, 0.03, 6}},
        {"equisolid 190 deg, vignetting 0.8, noise 3 %, 8-bit",
         LensType::Equisolid,
         190,
         590,
         645.0,
         505.0,
         {8, 0.8, 0.03, 0, 7}},
        {"kannala-brandt 200 deg, vignetting 0.4, noise 1 %, 10-bit",
         LensType::KannalaBrandt,
         200,
         580,
         636.6,
         515.1,
         {10, 0.4, 0.01, 0.01, 8}},
    };
    for (const auto& k : cases) {
      Lens lens;
      lens.type = k.type;
      lens.fov_deg = k.fov;
      lens.cx = k.cx;
      lens.cy = k.cy;
      if (k.type == LensType::KannalaBrandt) lens.k = {-0.02, 0.004, 0, 0};
      lens.r_pp = 1;
      lens.r_pp = *lens.radius(k.fov * kPi / 360) / k.radius;
      const cv::Mat frame = render_room_fisheye(lens, k.room);
      QCOMPARE(frame.depth(), k.room.bits > 8 ? CV_16U : CV_8U);
      const auto c = detect_image_circle(frame);
      QVERIFY2(c.has_value(), k.name);
      const double centre_err = std::hypot(c->centre.x - k.cx, c->centre.y - k.cy);
      const double radius_err = std::abs(c->radius - k.radius) / k.radius;
      qInfo("%s: centre error %.3f px, radius error %.4f %% (rms %.3f px, %d of %d rim points)", k.name, centre_err,
            100 * radius_err, c->rms_px, c->edge_points, c->rays);
      QVERIFY2(centre_err < 0.5, k.name);
      QVERIFY2(radius_err < 0.003, k.name);
      // A gray copy gives the same circle (1-channel input).
      cv::Mat gray;
      cv::cvtColor(frame, gray, cv::COLOR_BGR2GRAY);
      const auto g = detect_image_circle(gray);
      QVERIFY(g && std::hypot(g->centre.x - k.cx, g->centre.y - k.cy) < 0.5);
    }
  }
  void proposed_lens_records_the_circle_fit() {
    ImageCircle c;
    c.centre = {640.2, 511.8};
    c.radius = 600;
    c.rms_px = 0.08;
    c.edge_points = 300;
    const Lens l = propose_lens(Lens::paper(), c);
    QCOMPARE(l.calibration.method, LensCalibration::Method::CircleFit);
    QVERIFY(l.calibration.rms_px && std::abs(*l.calibration.rms_px - 0.08) < 1e-12);
    QVERIFY(describe(l.calibration).find("circle-fit") == 0);
    QVERIFY(l.calibration.detail.find("300 rim points") != std::string::npos);
  }
  void line_residual_of_exact_points() {
    const auto r = line_residual({{0, 1}, {1, 3}, {2, 5}, {3, 7}});
    QVERIFY(r.rms_px < 1e-12 && r.max_px < 1e-12);
    // A point 1 px off a horizontal line of 4 others: TLS line moves up by 1/5.
    const auto off = line_residual({{0, 0}, {1, 0}, {2, 1}, {3, 0}, {4, 0}});
    QVERIFY(std::abs(off.max_px - 0.8) < 1e-9);
    QVERIFY(std::abs(off.rms_px - std::sqrt((4 * 0.04 + 0.64) / 5)) < 1e-9);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, line_residual({{0, 0}, {1, 1}}));
  }
  void chart_lines_stay_straight_only_with_the_right_lens() {
    Lens lens = Lens::paper();  // the paper's lens at half size
    lens.width = 640;
    lens.height = 512;
    lens.r_pp *= 2;
    const cv::Mat fisheye = render_fisheye(lens);
    const View view{640, 512, 120, 0, 0, 0};
    // The chart line y = 0.5 on the plane x = 1 is the output column centre + f * 0.5.
    const double col = (view.width - 1) / 2.0 + view.focal_px() * 0.5;
    const auto residual_with = [&](const Lens& assumed) {
      const cv::Mat out = reproject(fisheye, build_reprojection_map(assumed, view));
      return line_residual(trace_vertical_line(out, col, 180, 330));
    };
    const LineResidual right = residual_with(lens);
    Lens wrong = lens;
    wrong.r_pp *= 1.3;
    const LineResidual bent = residual_with(wrong);
    qInfo("right lens: rms %.3f px, max %.3f px (n = %d); r_pp 30%% off: rms %.3f px, max %.3f px", right.rms_px,
          right.max_px, right.points, bent.rms_px, bent.max_px);
    QVERIFY(right.points >= 35);
    QVERIFY(right.rms_px < 0.25 && right.max_px < 0.5);
    QVERIFY(bent.rms_px > 0.5 && bent.rms_px > 3 * right.rms_px);
  }
};

QTEST_GUILESS_MAIN(TestCircleDetect)
#include "test_circle_detect.moc"
