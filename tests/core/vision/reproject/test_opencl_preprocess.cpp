// SPDX-License-Identifier: GPL-3.0-or-later
// The OpenCL preprocessing (demosaic + reprojection kernels) against the CPU path (bilinear demosaic, then the
// fixed-point LUT remap) on a synthetic capture: every pixel within one grey level. Skipped without an OpenCL
// device (PoCL provides one on CPU-only machines).
#include <QTest>

#include "vision/frames/synthetic.h"
#include "vision/reproject/opencl_preprocess.h"
#include "vision/reproject/preprocess.h"

using namespace bs::vision;

class TestOpenClPreprocess : public QObject {
  Q_OBJECT
 private slots:
  void matches_cpu_within_one_grey_level() {
    for (const BayerPattern pattern : {BayerPattern::BGGR, BayerPattern::GRBG}) {
      Lens lens = Lens::paper();
      lens.r_pp *= 4;  // quarter size, same field of view
      lens.width = 320;
      lens.height = 256;
      const View view{.width = 400, .height = 300, .yaw_deg = 10};
      const cv::Mat raw = mosaic(render_fisheye(lens, 8), pattern);
      Preprocessor gpu;
      OpenClPreprocessorInfo info;
      try {
        gpu = make_opencl_preprocessor(lens, view, pattern, &info);
      } catch (const std::runtime_error& e) {
        QSKIP(e.what());
      }
      QVERIFY(!info.device.empty());
      const Preprocessor cpu =
          make_preprocessor(lens, view, pattern, DemosaicMethod::Bilinear, PreprocessPath::Separate);
      const cv::Mat a = gpu(raw), b = cpu(raw);
      QCOMPARE(a.size(), cv::Size(400, 300));
      QCOMPARE(a.type(), b.type());
      cv::Mat diff;
      cv::absdiff(a, b, diff);
      double worst = 0;
      cv::minMaxLoc(diff.reshape(1), nullptr, &worst);
      QVERIFY2(worst <= 1, qPrintable(QString("largest difference %1 grey levels").arg(worst)));
      QVERIFY(cv::countNonZero(a.reshape(1)) > static_cast<int>(a.total()));  // not a black image
      // A second frame through the same buffers gives the same result.
      QCOMPARE(cv::norm(gpu(raw), a, cv::NORM_INF), 0.0);
    }
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, make_opencl_preprocessor(Lens{}, View{}, BayerPattern::BGGR));
  }
};

QTEST_GUILESS_MAIN(TestOpenClPreprocess)
#include "test_opencl_preprocess.moc"
