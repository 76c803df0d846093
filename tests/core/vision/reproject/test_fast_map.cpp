// SPDX-License-Identifier: GPL-3.0-or-later
#include <QTest>
#include <cmath>

#include "vision/reproject/fast_map.h"

using namespace bs::vision;

namespace {

// Distance of a source point from the edge of the valid area (image circle and source image bounds).
double border_distance(const Lens& lens, cv::Point2d s) {
  constexpr double kPi = 3.14159265358979323846;
  double theta_max = lens.fov_deg * kPi / 360;
  if (lens.type == LensType::Orthographic) theta_max = std::min(theta_max, kPi / 2);
  const double rmax = *lens.radius(theta_max);
  const cv::Point2d c = lens.centre();
  return std::min({std::abs(rmax - std::hypot(s.x - c.x, s.y - c.y)), std::abs(s.x), std::abs(s.y),
                   std::abs(lens.width - 1 - s.x), std::abs(lens.height - 1 - s.y)});
}

struct Comparison {
  double max_error = 0;
  int valid = 0, mismatched = 0, mismatched_off_border = 0;
};

Comparison compare(const Lens& lens, const View& view, int step) {
  const cv::Mat exact = build_reprojection_map(lens, view);
  const cv::Mat fast = build_reprojection_map_coarse(lens, view, step);
  Comparison c;
  for (int y = 0; y < exact.rows; ++y)
    for (int x = 0; x < exact.cols; ++x) {
      const cv::Vec2f e = exact.at<cv::Vec2f>(y, x), f = fast.at<cv::Vec2f>(y, x);
      const bool ev = e[0] >= 0, fv = f[0] >= 0;
      if (ev && fv) {
        ++c.valid;
        c.max_error = std::max(c.max_error, static_cast<double>(std::hypot(e[0] - f[0], e[1] - f[1])));
      } else if (ev != fv) {
        // Only pixels whose source lies within 0.1 px of the border may land on the other side of it.
        ++c.mismatched;
        const cv::Vec2f s = ev ? e : f;
        if (border_distance(lens, {s[0], s[1]}) > 0.1) ++c.mismatched_off_border;
      }
    }
  return c;
}

}  // namespace

class TestFastMap : public QObject {
  Q_OBJECT
 private slots:
  void paper_lens_step_8_is_within_a_tenth_of_a_pixel() {
    const Comparison c = compare(Lens::paper(), View{}, 8);
    qInfo("paper lens, 150 deg view, step 8: max error %.5f px over %d valid pixels, %d border mismatches", c.max_error,
          c.valid, c.mismatched);
    QVERIFY(c.valid > 1000000);
    QVERIFY2(c.max_error < 0.1, qPrintable(QString::number(c.max_error)));
    QCOMPARE(c.mismatched_off_border, 0);
  }
  void rotated_views_and_every_model_cross_the_circle_correctly() {
    struct Case {
      LensType type;
      double fov;
      View view;
    };
    const std::vector<Case> cases = {
        {LensType::Equidistant, 195, View{640, 480, 170, 70, -30, 15}},  // looks past the circle's edge
        {LensType::Equisolid, 180, View{640, 480, 120, -40, 50, 0}},
        {LensType::Stereographic, 200, View{640, 480, 100, 0, 85, -20}},
        {LensType::Orthographic, 180, View{640, 480, 150, 60, 0, 0}},  // model ends at 90 deg: exact cells
        {LensType::Rectilinear, 120, View{640, 480, 140, 30, 20, 10}},
        {LensType::KannalaBrandt, 190, View{640, 480, 160, 100, 0, 45}},
        {LensType::Equidistant, 360, View{640, 480, 170, 180, 0, 0}},  // looking backwards
    };
    for (const auto& k : cases) {
      Lens lens = Lens::paper();
      lens.type = k.type;
      lens.fov_deg = k.fov;
      lens.k = {0.02, -0.01, 0.001, 0};
      if (k.type == LensType::Rectilinear) lens.r_pp = 1.0 / 400;
      if (k.fov == 360) lens.r_pp = 3.14159265358979 / 512;  // the whole sphere within the image
      const Comparison c = compare(lens, k.view, 8);
      qInfo("%s fov %.0f: max error %.5f px, %d valid, %d border mismatches", std::string(to_string(k.type)).c_str(),
            k.fov, c.max_error, c.valid, c.mismatched);
      QVERIFY(c.valid > 1000);
      QVERIFY2(c.max_error < 0.1, qPrintable(QString("%1: %2").arg(to_string(k.type).data()).arg(c.max_error)));
      QCOMPARE(c.mismatched_off_border, 0);
    }
  }
  void step_one_is_the_exact_map_and_odd_sizes_are_covered() {
    const Lens lens = Lens::paper();
    const View view{333, 257, 120, 5, 5, 5};
    QCOMPARE(cv::norm(build_reprojection_map_coarse(lens, view, 1), build_reprojection_map(lens, view), cv::NORM_INF),
             0.0);
    const Comparison c = compare(lens, view, 16);  // 333 = 20 * 16 + 13: the last partial cell
    QVERIFY(c.max_error < 0.1);
    QCOMPARE(c.mismatched_off_border, 0);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, build_reprojection_map_coarse(lens, view, 0));
  }
};

QTEST_GUILESS_MAIN(TestFastMap)
#include "test_fast_map.moc"
