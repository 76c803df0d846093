// SPDX-License-Identifier: GPL-3.0-or-later
#include <QTest>
#include <cmath>

#include "../../../support/refusal.h"
#include "../small_paper_lens.h"
#include "vision/lens/lens.h"

using namespace bs::vision;

namespace {

constexpr double kPi = 3.14159265358979323846;

// The paper's equation 2, written out independently of lens.cpp: output pixel -> fisheye pixel.
cv::Point2d paper_equation(double x, double y) {
  const double W = 1280, H = 1024, fov = 150 * kPi / 180, r_pp = 195 * kPi / 180 / 1280;
  const double f = std::sqrt((W - 1) * (W - 1) + (H - 1) * (H - 1)) / (2 * std::tan(fov / 2));
  const double sx = x - (W - 1) / 2, sy = (H - 1) / 2 - y;
  const double n = std::sqrt(f * f + sx * sx + sy * sy);
  const double vx = f / n, vy = sx / n, vz = sy / n;
  const double theta = std::acos(vx);
  double ox = 0, oy = 0;
  if (theta != 0) {
    const double alpha = theta / (r_pp * std::sin(theta));
    ox = alpha * vy;
    oy = alpha * vz;
  }
  return {(W - 1) / 2 + ox, (H - 1) / 2 - oy};
}

}  // namespace

class TestLens : public QObject {
  Q_OBJECT
 private slots:
  void equals_the_paper_equations() {
    const Lens lens = Lens::paper();
    const View view;
    for (const auto& [x, y] : std::vector<std::pair<double, double>>{
             {0, 0}, {1279, 1023}, {100, 900}, {640, 10}, {1000, 512}, {639.5, 511.5}, {333, 777}}) {
      const auto got = source_of(lens, view, x, y);
      QVERIFY(got.has_value());
      const cv::Point2d want = paper_equation(x, y);
      QVERIFY2(std::abs(got->x - want.x) < 1e-9 && std::abs(got->y - want.y) < 1e-9,
               qPrintable(QString("(%1, %2): got (%3, %4), paper (%5, %6)")
                              .arg(x)
                              .arg(y)
                              .arg(got->x)
                              .arg(got->y)
                              .arg(want.x)
                              .arg(want.y)));
    }
  }
  void centre_is_theta_zero_and_corners_are_half_the_fov() {
    const Lens lens = Lens::paper();
    const View view;
    const auto c = source_of(lens, view, 639.5, 511.5);
    QVERIFY(c && std::abs(c->x - 639.5) < 1e-12 && std::abs(c->y - 511.5) < 1e-12);
    // The output diagonal spans the FOV, so a corner ray is 75 degrees off axis: r = theta / r_pp.
    const auto corner = source_of(lens, view, 1279, 0);
    QVERIFY(corner.has_value());
    const double r = std::hypot(corner->x - 639.5, corner->y - 511.5);
    QVERIFY(std::abs(r - (75 * kPi / 180) / lens.r_pp) < 1e-6);
    QVERIFY(corner->x > 639.5 && corner->y < 511.5);  // up-right in the output is up-right in the fisheye
  }
  void models_agree_near_the_axis_and_differ_away() {
    Lens l = Lens::paper();
    const double small = 0.01, big = 1.2;
    for (LensType t : {LensType::Equisolid, LensType::Stereographic, LensType::Orthographic, LensType::Rectilinear}) {
      l.type = t;
      l.fov_deg = 170;
      QVERIFY(std::abs(*l.radius(small) - small / l.r_pp) < 0.02);
      QVERIFY(std::abs(*l.radius(big) - big / l.r_pp) > 1);
    }
    l.type = LensType::KannalaBrandt;
    l.k = {0, 0, 0, 0};
    QCOMPARE(*l.radius(big), big / l.r_pp);  // zero coefficients = equidistant
    l.fov_deg = 100;
    QVERIFY(!l.radius(1.0).has_value());  // 57 degrees > 50: outside the image circle
  }
  void map_and_mask() {
    const Lens lens = bs::test::small_paper_lens(320, 256);
    const View view{.width = 160, .height = 128};
    const cv::Mat map = build_reprojection_map(lens, view);
    QCOMPARE(map.type(), CV_32FC2);
    const auto s = source_of(lens, view, 37, 91);
    QVERIFY(std::abs(map.at<cv::Vec2f>(91, 37)[0] - s->x) < 1e-3);
    cv::Mat src(256, 320, CV_8UC3, cv::Scalar(10, 20, 30));
    cv::Mat mask = cv::Mat::zeros(256, 320, CV_8UC1);
    mask.rowRange(200, 256).setTo(255);  // the robot's nose at the bottom of the fisheye image
    const cv::Mat out = reproject(src, map, mask, cv::Scalar(255, 0, 255));
    QCOMPARE(out.at<cv::Vec3b>(64, 80), cv::Vec3b(10, 20, 30));    // centre: plain source colour
    QCOMPARE(out.at<cv::Vec3b>(127, 80), cv::Vec3b(255, 0, 255));  // bottom centre samples the masked rows
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, reproject(src, map, cv::Mat::zeros(10, 10, CV_8UC1)));
    // The fixed-point table samples on OpenCV's 1/32 grid: within one level of the float map, same mask rule.
    const ReprojectionLut lut(lens, view);
    cv::Mat smooth(256, 320, CV_8UC3);
    for (int y = 0; y < 256; ++y)
      for (int x = 0; x < 320; ++x)
        smooth.at<cv::Vec3b>(y, x) = cv::Vec3b(uchar(x * 255 / 319), uchar(y), uchar((x + y) / 3));
    cv::Mat diff;
    cv::absdiff(lut.apply(smooth, mask, cv::Scalar(255, 0, 255)), reproject(smooth, map, mask, cv::Scalar(255, 0, 255)),
                diff);
    double worst = 0;
    cv::minMaxLoc(diff.reshape(1), nullptr, &worst);
    QVERIFY2(worst <= 1, qPrintable(QString("fixed-point vs float map: %1 levels").arg(worst)));
    QCOMPARE(lut.apply(src, mask, cv::Scalar(255, 0, 255)).at<cv::Vec3b>(127, 80), cv::Vec3b(255, 0, 255));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, lut.apply(cv::Mat(100, 100, CV_8UC3)));
  }
  void bad_parameters_are_rejected() {
    Lens lens = Lens::paper();
    View view;
    view.fov_deg = 180;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, build_reprojection_map(lens, view));
    view.fov_deg = 150;
    view.width = 0;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, build_reprojection_map(lens, view));
    view.width = 100;
    lens.r_pp = 0;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, build_reprojection_map(lens, view));
    lens.r_pp = -1;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, build_reprojection_map(lens, view));
  }
  void json_round_trip() {
    Lens lens = Lens::paper();
    lens.type = LensType::KannalaBrandt;
    lens.k = {0.01, -0.002, 0.0003, 0};
    lens.cx = 641.25;
    View view;
    view.yaw_deg = 12.5;
    view.roll_deg = -3;
    const auto [l2, v2] = lens_from_json(nlohmann::json::parse(lens_to_json(lens, view).dump()));
    QCOMPARE(l2.type, lens.type);
    QCOMPARE(l2.k, lens.k);
    QCOMPARE(l2.cx, 641.25);
    QCOMPARE(l2.r_pp, lens.r_pp);
    QCOMPARE(v2.yaw_deg, 12.5);
    QCOMPARE(v2.roll_deg, -3.0);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, lens_from_json(nlohmann::json{{"format", "other"}}));
    auto j = lens_to_json(lens, view);
    j["lens"]["r_pp"] = "fast";
    QVERIFY(bs::test::refusal<std::invalid_argument>([&] { lens_from_json(j); }).contains("/lens/r_pp"));
  }
  void calibration_record_round_trips_and_is_optional() {
    Lens lens = Lens::paper();
    QCOMPARE(lens.calibration.method, LensCalibration::Method::Manual);
    lens.calibration.method = LensCalibration::Method::Checkerboard;
    lens.calibration.rms_px = 0.31;
    lens.calibration.images_used = 12;
    lens.calibration.images_rejected = 2;
    lens.calibration.detail = "board 9x6, 25 mm";
    const auto [l2, v2] = lens_from_json(nlohmann::json::parse(lens_to_json(lens, View{}).dump()));
    QCOMPARE(l2.calibration.method, LensCalibration::Method::Checkerboard);
    QCOMPARE(*l2.calibration.rms_px, 0.31);
    QCOMPARE(l2.calibration.images_used, 12);
    QCOMPARE(l2.calibration.images_rejected, 2);
    QCOMPARE(QString::fromStdString(describe(l2.calibration)),
             QString("checkerboard, 12 images (2 rejected), RMS 0.31 px; board 9x6, 25 mm"));
    // Files written before the record existed still load, as hand-made ("manual").
    auto j = lens_to_json(Lens::paper(), View{});
    j["lens"].erase("calibration");
    QCOMPARE(lens_from_json(j).first.calibration.method, LensCalibration::Method::Manual);
    j["lens"]["calibration"] = {{"method", "guess"}};
    QVERIFY(bs::test::refusal<std::invalid_argument>([&] { lens_from_json(j); }).contains("/lens/calibration/method"));
  }
};

QTEST_APPLESS_MAIN(TestLens)
#include "test_lens.moc"
