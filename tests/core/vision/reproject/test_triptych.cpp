// SPDX-License-Identifier: GPL-3.0-or-later
// Figure 3's images from a frame (triptych.h), frame <-> Mat, and the geometry the inspector and overlays use
// (view_geometry.h: output_of inverts source_of; the image circle; the view outline).
#include <QTest>

#include <cstring>

#include "vision/frames/frame_image.h"
#include "vision/frames/synthetic.h"
#include "vision/lens/view_geometry.h"
#include "vision/reproject/triptych.h"

namespace {

bs::Frame frame_from(const cv::Mat& raw, const char* pattern, int bits) {
  bs::Frame f;
  f.width = raw.cols;
  f.height = raw.rows;
  f.channels = raw.channels();
  f.bit_depth = bits;
  f.pattern = pattern;
  f.pixels.assign(raw.datastart, raw.dataend);
  return f;
}

}  // namespace

class TestTriptych : public QObject {
  Q_OBJECT
 private slots:
  void output_of_inverts_source_of() {
    using namespace bs::vision;
    Lens lens = Lens::paper();
    for (const double yaw : {0.0, 20.0}) {
      View view;
      view.yaw_deg = yaw;
      view.pitch_deg = yaw / 2;
      view.roll_deg = -yaw / 3;
      int checked = 0;
      for (int y = 0; y < view.height; y += 97)
        for (int x = 0; x < view.width; x += 89) {
          const auto src = source_of(lens, view, x, y);
          if (!src) continue;
          const auto back = output_of(lens, view, src->x, src->y);
          QVERIFY2(back, qPrintable(QString("no inverse for (%1, %2)").arg(x).arg(y)));
          QVERIFY2(std::abs(back->x - x) < 1e-6 && std::abs(back->y - y) < 1e-6,
                   qPrintable(QString("(%1, %2) -> (%3, %4)").arg(x).arg(y).arg(back->x).arg(back->y)));
          ++checked;
        }
      QVERIFY(checked > 100);
    }
    // The fisheye corner is outside the 195 degree circle: no output pixel.
    QVERIFY(!output_of(lens, View{}, 0, 0));
  }

  void image_circle_and_outline() {
    using namespace bs::vision;
    const Lens lens = Lens::paper();
    const auto circle = image_circle(lens);
    QVERIFY(circle);
    // Equidistant: r = theta / r_pp = (195/2 degrees) / (195 degrees / 1280 px) = 640 px.
    QVERIFY(std::abs(circle->radius - 640.0) < 1e-9);
    QVERIFY(std::abs(circle->centre.x - 639.5) < 1e-9 && std::abs(circle->centre.y - 511.5) < 1e-9);
    const View view;
    const auto outline = view_outline(lens, view, 16);
    QCOMPARE(outline.size(), std::size_t{64});  // a 150 degree view lies inside the 195 degree circle
    for (const auto& p : outline) {
      const double r = std::hypot(p.x - circle->centre.x, p.y - circle->centre.y);
      QVERIFY(r < circle->radius);
      // Every outline point maps back onto the output border.
      const auto o = output_of(lens, view, p.x, p.y);
      QVERIFY(o);
      const bool on_border = std::abs(o->x) < 1e-6 || std::abs(o->y) < 1e-6 ||
                             std::abs(o->x - (view.width - 1)) < 1e-6 || std::abs(o->y - (view.height - 1)) < 1e-6;
      QVERIFY(on_border);
    }
  }

  void triptych_matches_the_stages() {
    using namespace bs::vision;
    Lens lens = Lens::paper();
    lens.r_pp *= 4;
    lens.width = 320;
    lens.height = 256;
    View view;
    view.width = 200;
    view.height = 160;
    for (const int bits : {8, 12}) {
      const cv::Mat raw = mosaic(render_fisheye(lens, bits), BayerPattern::GRBG);
      const bs::Frame frame = frame_from(raw, "GRBG", bits);
      const cv::Mat back = frame_to_mat(frame);
      QCOMPARE(cv::norm(back, raw, cv::NORM_INF), 0.0);
      const TriptychImages t = render_triptych(frame, DemosaicMethod::MalvarHeCutler, lens, view);
      QCOMPARE(cv::norm(t.mosaic, raw, cv::NORM_INF), 0.0);
      const cv::Mat bgr = demosaic(raw, BayerPattern::GRBG, DemosaicMethod::MalvarHeCutler);
      QCOMPARE(cv::norm(t.demosaiced, bgr, cv::NORM_INF), 0.0);
      QCOMPARE(t.reprojected.size(), cv::Size(200, 160));
      QCOMPARE(cv::norm(t.reprojected, ReprojectionLut(lens, view).apply(bgr), cv::NORM_INF), 0.0);
    }
    // A frame of another size than the lens is refused.
    const bs::Frame wrong = frame_from(cv::Mat(10, 10, CV_8UC1, cv::Scalar(1)), "BGGR", 8);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, render_triptych(wrong, DemosaicMethod::Bilinear, lens, view));
    // Damaged pixel buffers are refused too.
    bs::Frame short_frame = wrong;
    short_frame.pixels.resize(5);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, frame_to_mat(short_frame));
  }

  void window_level_and_default_lens() {
    using namespace bs::vision;
    cv::Mat m(1, 4, CV_16UC1);
    m.at<std::uint16_t>(0) = 100;
    m.at<std::uint16_t>(1) = 200;
    m.at<std::uint16_t>(2) = 300;
    m.at<std::uint16_t>(3) = 4095;
    const cv::Mat w = window_to_8bit(m, 100, 610);  // 510 counts over 255 grey levels: 2 counts per level
    QCOMPARE(int(w.at<std::uint8_t>(0)), 0);
    QCOMPARE(int(w.at<std::uint8_t>(1)), 50);
    QCOMPARE(int(w.at<std::uint8_t>(2)), 100);
    QCOMPARE(int(w.at<std::uint8_t>(3)), 255);  // clamped
    bs::Frame f;
    f.width = 640;
    f.height = 512;
    const FrameLens fl = lens_for_frame(f);
    QVERIFY(!fl.from_frame);
    QCOMPARE(fl.lens.width, 640);
    QVERIFY(std::abs(fl.lens.r_pp - Lens::paper().r_pp * 2) < 1e-15);  // still 195 degrees across the width
    QCOMPARE(fl.view.width, 640);
    f.lens_json = lens_to_json(fl.lens, View{}).dump();
    QVERIFY(lens_for_frame(f).from_frame);
  }
};

QTEST_APPLESS_MAIN(TestTriptych)
#include "test_triptych.moc"
