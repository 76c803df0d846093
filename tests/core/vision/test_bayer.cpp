// SPDX-License-Identifier: GPL-3.0-or-later
#include <QTest>
#include <cmath>
#include <filesystem>

#include <opencv2/imgcodecs.hpp>

#include "vision/bayer.h"

using namespace bs::vision;

namespace {

// A smooth, colourful scene with luminance edges (the same step in every channel, as in natural images, which is
// what gradient-corrected demosaicing assumes): ground truth for demosaicing.
cv::Mat scene(int w, int h, int depth) {
  cv::Mat img(h, w, CV_64FC3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double u = x / static_cast<double>(w), v = y / static_cast<double>(h);
      const double edge = (x / 16 + y / 16) % 2 ? 0.15 : 0.0;  // checker edges every 16 px
      img.at<cv::Vec3d>(y, x) = cv::Vec3d(0.5 + 0.3 * std::sin(6 * u + 1) - edge, 0.5 + 0.3 * std::cos(5 * v) - edge,
                                          0.5 + 0.3 * std::sin(4 * (u + v)) - edge);
    }
  cv::Mat out;
  img.convertTo(out, depth == CV_8U ? CV_8UC3 : CV_16UC3, depth == CV_8U ? 255 : 65535);
  return out;
}

}  // namespace

class TestBayer : public QObject {
  Q_OBJECT
 private slots:
  void pattern_cells() {
    QCOMPARE(bayer_channel(BayerPattern::BGGR, 0, 0), 0);
    QCOMPARE(bayer_channel(BayerPattern::BGGR, 1, 1), 2);
    QCOMPARE(bayer_channel(BayerPattern::BGGR, 0, 1), 1);
    QCOMPARE(bayer_channel(BayerPattern::RGGB, 0, 0), 2);
    QCOMPARE(bayer_channel(BayerPattern::GRBG, 0, 1), 2);
    QCOMPARE(bayer_channel(BayerPattern::GBRG, 1, 0), 2);
    QCOMPARE(bayer_pattern_from_string("GBRG"), BayerPattern::GBRG);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, bayer_pattern_from_string("BRGG"));
  }

  void every_pattern_and_method_recovers_the_scene() {
    const cv::Mat truth = scene(160, 120, CV_8U);
    for (BayerPattern p : {BayerPattern::BGGR, BayerPattern::RGGB, BayerPattern::GRBG, BayerPattern::GBRG}) {
      const cv::Mat raw = mosaic(truth, p);
      const double bil = psnr(demosaic(raw, p, DemosaicMethod::Bilinear), truth);
      const double mhc = psnr(demosaic(raw, p, DemosaicMethod::MalvarHeCutler), truth);
      const double ocv = psnr(demosaic(raw, p, DemosaicMethod::OpenCvBilinear), truth);
      const QByteArray what = QString("%1: bilinear %2 dB, MHC %3 dB, OpenCV %4 dB")
                                  .arg(QString::fromUtf8(to_string(p).data())).arg(bil).arg(mhc).arg(ocv).toUtf8();
      QVERIFY2(bil > 28, what.constData());
      QVERIFY2(mhc > bil, what.constData());  // gradient correction helps
      QVERIFY2(ocv > 28, what.constData());   // proves the OpenCV code mapping per pattern
    }
  }

  void sixteen_bit_paths() {
    const cv::Mat truth = scene(96, 64, CV_16U);
    const cv::Mat raw = mosaic(truth, BayerPattern::BGGR);
    QCOMPARE(raw.type(), CV_16UC1);
    const cv::Mat out = demosaic(raw, BayerPattern::BGGR, DemosaicMethod::MalvarHeCutler);
    QCOMPARE(out.type(), CV_16UC3);
    QVERIFY(psnr(out, truth) > 30);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, demosaic(raw, BayerPattern::BGGR, DemosaicMethod::OpenCvVng));
  }

  void bad_input() {
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, demosaic(cv::Mat(8, 8, CV_32FC1), BayerPattern::BGGR, DemosaicMethod::Bilinear));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, demosaic(cv::Mat(2, 2, CV_8UC1), BayerPattern::BGGR, DemosaicMethod::Bilinear));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, mosaic(cv::Mat(8, 8, CV_8UC1), BayerPattern::BGGR));
    QVERIFY(std::isinf(psnr(scene(16, 16, CV_8U), scene(16, 16, CV_8U))));
  }

  void kodak_images_when_present() {
    const std::filesystem::path dir = BENCHSCOPE_SOURCE_DIR "/../shared/datasets/kodak";
    if (!std::filesystem::exists(dir / "kodim01.png")) QSKIP("Kodak images not present (../shared/datasets/kodak)");
    double sum_bil = 0, sum_mhc = 0;
    int n = 0;
    for (int i = 1; i <= 24; ++i) {
      char name[32];
      std::snprintf(name, sizeof name, "kodim%02d.png", i);
      const cv::Mat truth = cv::imread((dir / name).string(), cv::IMREAD_COLOR);
      if (truth.empty()) continue;
      const cv::Mat raw = mosaic(truth, BayerPattern::BGGR);
      sum_bil += psnr(demosaic(raw, BayerPattern::BGGR, DemosaicMethod::Bilinear), truth);
      sum_mhc += psnr(demosaic(raw, BayerPattern::BGGR, DemosaicMethod::MalvarHeCutler), truth);
      ++n;
    }
    QVERIFY(n > 0);
    qInfo("Kodak (%d images), mean PSNR: bilinear %.2f dB, Malvar-He-Cutler %.2f dB", n, sum_bil / n, sum_mhc / n);
    QVERIFY(sum_mhc / n > sum_bil / n + 1.0);  // Malvar et al. report ~5 dB over bilinear on Kodak
  }
};

QTEST_APPLESS_MAIN(TestBayer)
#include "test_bayer.moc"
