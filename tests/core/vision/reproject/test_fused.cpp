// SPDX-License-Identifier: GPL-3.0-or-later
#include <QTest>
#include <cmath>

#include "../small_paper_lens.h"
#include "vision/lens/lens.h"
#include "vision/reproject/fused.h"

using namespace bs::vision;

namespace {

cv::Mat textured(int w, int h) {
  cv::Mat img(h, w, CV_8UC3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int v = ((x / 7 + y / 5) % 2) * 90;
      img.at<cv::Vec3b>(y, x) = cv::Vec3b(static_cast<uchar>(40 + v + x % 50), static_cast<uchar>(60 + (y * 3) % 100),
                                          static_cast<uchar>(30 + v + (x + y) % 80));
    }
  return img;
}

int max_difference(const cv::Mat& a, const cv::Mat& b) {
  cv::Mat d;
  cv::absdiff(a, b, d);
  double mx = 0;
  cv::minMaxLoc(d.reshape(1), nullptr, &mx);
  return static_cast<int>(mx);
}

}  // namespace

class TestFused : public QObject {
  Q_OBJECT
 private slots:
  void equals_demosaic_then_reproject_within_one_level() {
    const Lens lens = bs::test::small_paper_lens(320, 256);
    for (BayerPattern p : {BayerPattern::BGGR, BayerPattern::RGGB, BayerPattern::GRBG, BayerPattern::GBRG})
      for (double yaw : {0.0, 80.0}) {  // 80 degrees: the view reaches the mosaic's edge (reflected border path)
        const cv::Mat map = build_reprojection_map(lens, View{.width = 200, .height = 160, .yaw_deg = yaw});
        const cv::Mat raw = mosaic(textured(320, 256), p);
        // The same maths at 16-bit precision, rounded once at the end: an 8-bit reference would round twice
        // (after demosaicing and inside remap) and differ by 2 at a few pixels for that reason alone.
        cv::Mat raw16, reference;
        raw.convertTo(raw16, CV_16U, 256);
        reproject(demosaic(raw16, p, DemosaicMethod::Bilinear), map).convertTo(reference, CV_8U, 1.0 / 256);
        cv::Mat fused;
        FusedTable(map, raw.size(), p).run(raw, fused);
        const int diff = max_difference(reference, fused);
        QVERIFY2(diff <= 1, qPrintable(QString("%1 yaw %2: max difference %3 grey levels")
                                           .arg(QString::fromUtf8(to_string(p).data()))
                                           .arg(yaw)
                                           .arg(diff)));
      }
  }
  void vector_kernel_equals_scalar_kernel_bit_for_bit() {
    // Both kernels compute the same integers; the vector one (when this CPU has it) must not differ anywhere,
    // including row tails (width 203 is not a multiple of 16), pixels with no source and reflected borders.
    const Lens lens = bs::test::small_paper_lens(322, 250);
    std::size_t tiled = 0, gathered = 0;
    for (BayerPattern p : {BayerPattern::BGGR, BayerPattern::RGGB, BayerPattern::GRBG, BayerPattern::GBRG})
      for (double yaw : {0.0, 60.0, 100.0}) {
        View view{.width = 203, .height = 77};
        // 170 degrees over 203 pixels steps several mosaic pixels per output pixel: blocks too wide for a tile.
        view.fov_deg = yaw == 0.0 ? 170 : 120;
        view.yaw_deg = yaw;
        view.pitch_deg = yaw / 4;
        const cv::Mat map = build_reprojection_map(lens, view);
        const cv::Mat raw = mosaic(textured(lens.width, lens.height), p);
        const FusedTable automatic(map, raw.size(), p);
        const FusedTable scalar(map, raw.size(), p, FusedTable::Kernel::Scalar);
        QVERIFY(!scalar.vectorised());
        cv::Mat a, b;
        automatic.run(raw, a, {7, 8, 9});
        scalar.run(raw, b, {7, 8, 9});
        QCOMPARE(max_difference(a, b), 0);
        tiled += automatic.tiled_blocks();
        gathered += automatic.gather_blocks();
        if (yaw == 100.0)
          QVERIFY(cv::countNonZero(map.reshape(1, static_cast<int>(map.total())).col(0) < 0) >
                  0);  // some pixels have no source
      }
    // Both ways of reading the mosaic were compared (when this CPU has the vector kernel at all).
    if (FusedTable(cv::Mat(2, 2, CV_32FC2, cv::Scalar(5, 5)), {16, 16}, BayerPattern::BGGR).vectorised()) {
      QVERIFY(tiled > 0);
      QVERIFY(gathered > 0);
    }
  }
  void rejects_mismatched_input() {
    const cv::Mat map(10, 10, CV_32FC2, cv::Scalar(2, 2));
    FusedTable table(map, {16, 16}, BayerPattern::BGGR);
    cv::Mat out;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, table.run(cv::Mat(8, 8, CV_8UC1), out));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             FusedTable(cv::Mat(10, 10, CV_32FC1), {16, 16}, BayerPattern::BGGR));
  }
};

QTEST_APPLESS_MAIN(TestFused)
#include "test_fused.moc"
