// SPDX-License-Identifier: GPL-3.0-or-later
#include <QTest>
#include <cmath>

#include <opencv2/imgproc.hpp>

#include "../../../support/core_ray_projection.h"
#include "vision/frames/synthetic_room.h"

using namespace bs::vision;

namespace {

constexpr double kPi = 3.14159265358979323846;

}  // namespace

class TestSyntheticRoom : public QObject {
  Q_OBJECT
 private slots:
  void whole_circle_is_lit_and_outside_is_black() {
    const Lens lens = Lens::paper();  // circle radius 640 px about (639.5, 511.5)
    const cv::Mat img = render_room_fisheye(lens);
    QCOMPARE(img.type(), CV_8UC3);
    cv::Mat gray;
    cv::cvtColor(img, gray, cv::COLOR_BGR2GRAY);
    int dark_inside = 0, lit_outside = 0, inside = 0;
    for (int y = 0; y < gray.rows; y += 3)
      for (int x = 0; x < gray.cols; x += 3) {
        const double r = std::hypot(x - 639.5, y - 511.5);
        if (r < 638) ++inside, dark_inside += gray.at<std::uint8_t>(y, x) == 0;
        if (r > 642) lit_outside += gray.at<std::uint8_t>(y, x) != 0;
      }
    // The darkest surface reflects 3 %: 7 or 8 of 255, never 0 inside; nothing outside.
    QCOMPARE(dark_inside, 0);
    QCOMPARE(lit_outside, 0);
    QVERIFY(inside > 100000);
  }
  void bits_noise_and_vignetting_are_as_asked() {
    Lens lens = Lens::paper();
    lens.r_pp *= 640.0 / 560;  // circle radius 560 px: the corners are outside
    RoomOptions o;
    o.bits = 12;
    o.noise = 0.01;
    o.black_level = 0.05;  // no clipping at 0, so the corner's SD is the noise's
    o.seed = 3;
    const cv::Mat img = render_room_fisheye(lens, o);
    QCOMPARE(img.type(), CV_16UC3);
    double mx = 0;
    cv::minMaxLoc(img.reshape(1), nullptr, &mx);
    QVERIFY(mx <= 4095);
    cv::Scalar mean, sd;
    cv::meanStdDev(img(cv::Rect(0, 0, 120, 100)), mean, sd);
    qInfo("corner: mean %.2f, SD %.2f (expected %.2f, %.2f)", mean[0], sd[0], 0.05 * 4095, 0.01 * 4095);
    QVERIFY(std::abs(mean[0] - 0.05 * 4095) < 2);
    QVERIFY(std::abs(sd[0] - 0.01 * 4095) < 0.05 * 0.01 * 4095);
    // Vignetting 0.5: the same ray's colour at the rim is half as bright as without.
    RoomOptions v;
    v.vignetting = 0.5;
    v.seed = 3;
    RoomOptions plain;
    plain.seed = 3;
    const cv::Mat a = render_room_fisheye(lens, plain), b = render_room_fisheye(lens, v);
    const cv::Point2d c = lens.centre();
    const cv::Point p(static_cast<int>(c.x - 0.97 * 560), static_cast<int>(c.y));  // near the left of the rim
    // theta is proportional to the radius (equidistant); the 5x5 patch's sum keeps rounding out of the ratio.
    const double t = std::hypot(p.x - c.x, p.y - c.y) / 560, expect = 1 - 0.5 * t * t;
    const cv::Rect patch(p.x - 2, p.y - 2, 5, 5);
    const double ratio = cv::sum(b(patch))[1] / cv::sum(a(patch))[1];
    QVERIFY2(std::abs(ratio - expect) < 0.03, qPrintable(QString::number(ratio)));
  }
  void grid_lines_land_on_dark_pixels_through_the_lens() {
    Lens lens = Lens::paper();
    lens.cx = 650.25;
    lens.cy = 505.5;
    RoomOptions o;
    o.seed = 2;
    const cv::Mat img = render_room_fisheye(lens, o);
    cv::Mat gray;
    cv::cvtColor(img, gray, cv::COLOR_BGR2GRAY);
    int on_line = 0, total = 0;
    for (const auto& seg : room_grid_lines(room_yaw(o.seed)))
      for (int i = 1; i < 40; ++i) {
        const double t = i / 40.0;
        const auto p = bs::test::project_ray(lens, seg.a * (1 - t) + seg.b * t, 1);
        if (!p) continue;
        ++total;
        on_line += gray.at<std::uint8_t>(cvRound(p->y), cvRound(p->x)) < 40;  // lines reflect 6 %, walls 60 %+
      }
    qInfo("%d of %d projected grid points on dark pixels", on_line, total);
    QVERIFY(total > 800);
    // Room corners (where a grid line meets the next wall's light area edge-on) miss by a pixel now and then.
    QVERIFY(on_line > 0.97 * total);
    QVERIFY(std::abs(room_yaw(1) - room_yaw(2)) > 0.3);
    QVERIFY(std::abs(room_yaw(2)) <= kPi);
  }
};

QTEST_GUILESS_MAIN(TestSyntheticRoom)
#include "test_synthetic_room.moc"
