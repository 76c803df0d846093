// SPDX-License-Identifier: GPL-3.0-or-later
// Straight lines of the synthetic chart must come out straight after fisheye capture, demosaicing and the
// reprojection to a rectilinear view: the end-to-end check of the lens model and the LUT.
#include <QTest>
#include <cmath>

#include "vision/frames/synthetic.h"
#include "vision/reproject/fused.h"

using namespace bs::vision;

namespace {

// Row of the dark line's centre in column x (darkness-weighted centroid within [y0, y1]); nan if none.
double line_centre(const cv::Mat& bgr, int x, int y0, int y1) {
  double sum = 0, weight = 0;
  for (int y = y0; y <= y1; ++y) {
    const cv::Vec3b p = bgr.at<cv::Vec3b>(y, x);
    const double dark = std::max(0.0, 150.0 - (p[0] + p[1] + p[2]) / 3.0);
    sum += dark * y;
    weight += dark;
  }
  return weight > 200 ? sum / weight : std::nan("");
}

// Renders the chart through the paper's lens (scaled to 640x512), demosaics + reprojects with the lens scaled by
// `rpp_error`, and fits a straight line to the chart's line z = +0.4. Returns (RMS, worst) residual in pixels.
std::pair<double, double> line_residuals(double rpp_error) {
  constexpr double kPi = 3.14159265358979323846;
  Lens lens = Lens::paper();
  lens.width = 640;
  lens.height = 512;
  lens.r_pp = 195 * kPi / 180 / 640;
  View view;
  view.width = 640;
  view.height = 512;
  view.fov_deg = 120;
  const cv::Mat raw = mosaic(render_fisheye(lens), BayerPattern::BGGR);
  Lens assumed = lens;
  assumed.r_pp *= rpp_error;
  cv::Mat rect;
  FusedTable(build_reprojection_map(assumed, view), raw.size(), BayerPattern::BGGR).run(raw, rect);
  // With the true lens, z = +0.4 lies at row (H-1)/2 - 0.4 f of the rectilinear view: straight and horizontal.
  const int expected = static_cast<int>(std::lround((view.height - 1) / 2.0 - 0.4 * view.focal_px()));
  std::vector<double> xs, ys;
  for (int x = 40; x < view.width - 40; x += 4) {
    const double y = line_centre(rect, x, expected - 12, expected + 12);
    if (std::isnan(y)) continue;
    xs.push_back(x);
    ys.push_back(y);
  }
  if (xs.size() < 100) return {1e9, 1e9};
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < xs.size(); ++i) mx += xs[i], my += ys[i];
  mx /= static_cast<double>(xs.size());
  my /= static_cast<double>(ys.size());
  double sxy = 0, sxx = 0;
  for (std::size_t i = 0; i < xs.size(); ++i) sxy += (xs[i] - mx) * (ys[i] - my), sxx += (xs[i] - mx) * (xs[i] - mx);
  const double slope = sxy / sxx;
  double worst = 0, ss = 0;
  for (std::size_t i = 0; i < xs.size(); ++i) {
    const double r = ys[i] - (my + slope * (xs[i] - mx));
    worst = std::max(worst, std::abs(r));
    ss += r * r;
  }
  return {std::sqrt(ss / static_cast<double>(xs.size())), worst};
}

}  // namespace

class TestSynthetic : public QObject {
  Q_OBJECT
 private slots:
  void inverse_lens_matches_forward() {
    Lens lens = Lens::paper();
    for (LensType t : {LensType::Equidistant, LensType::Equisolid, LensType::Stereographic}) {
      lens.type = t;
      for (double theta : {0.0, 0.3, 1.0, 1.6})
        QVERIFY(std::abs(*lens_theta(lens, *lens.radius(theta)) - theta) < 1e-9);
    }
    QVERIFY(!lens_theta(Lens::paper(), 5000).has_value());
  }

  void straight_lines_stay_straight() {
    const auto right = line_residuals(1.0);
    qInfo("line z = 0.4 through the true lens: RMS residual %.3f px, worst %.3f px", right.first, right.second);
    QVERIFY2(right.first < 0.25, qPrintable(QString("RMS residual %1 px").arg(right.first)));
    QVERIFY2(right.second < 0.6, qPrintable(QString("worst residual %1 px").arg(right.second)));  // single-column noise
    // Negative control: reprojecting with r_pp 5 % off bends the line, so the check can fail.
    const auto wrong = line_residuals(1.05);
    qInfo("line z = 0.4 through a lens 5 %% off: RMS residual %.3f px", wrong.first);
    QVERIFY(wrong.first > 4 * right.first);
  }

  void sixteen_bit_render() {
    Lens lens = Lens::paper();
    lens.width = 64;
    lens.height = 48;
    lens.r_pp = 195 * 3.14159265358979323846 / 180 / 64;
    const cv::Mat img = render_fisheye(lens, 12);
    QCOMPARE(img.type(), CV_16UC3);
    double mx = 0;
    cv::minMaxLoc(img.reshape(1), nullptr, &mx);
    QVERIFY(mx <= 4095 && mx > 2000);  // 12-bit values in 16-bit words
  }
};

QTEST_APPLESS_MAIN(TestSynthetic)
#include "test_synthetic.moc"
