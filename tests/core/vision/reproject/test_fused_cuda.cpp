// SPDX-License-Identifier: GPL-3.0-or-later
// The CUDA preprocessing path: its per-pixel code (fused_pixel.h, which the kernel runs unchanged) must equal the
// CPU's FusedTable bit for bit on every machine; the kernel itself is compared when a GPU is present, and without
// one the path must refuse with a reason instead of failing later.
#include <QTest>

#include "../../../support/refusal.h"
#include "../small_paper_lens.h"
#include "vision/lens/lens.h"
#include "vision/reproject/cuda_preprocess.h"
#include "vision/reproject/fused.h"
#include "vision/reproject/fused_reference.h"

using namespace bs::vision;

namespace {

// What these tests look at: 200x160 pixels of a 320x256 sensor, turned `yaw_deg` to the side.
Lens small_lens() { return bs::test::small_paper_lens(320, 256); }
View side_view(double yaw_deg = 60) { return View{.width = 200, .height = 160, .yaw_deg = yaw_deg}; }

// A mosaic with structure at every scale (not a smooth ramp, where errors cancel).
cv::Mat noisy_mosaic(cv::Size size, unsigned seed) {
  cv::Mat m(size, CV_8UC1);
  cv::RNG rng(seed);
  rng.fill(m, cv::RNG::UNIFORM, 0, 256);
  return m;
}

int differing_pixels(const cv::Mat& a, const cv::Mat& b) {
  cv::Mat d;
  cv::absdiff(a, b, d);
  return cv::countNonZero(d.reshape(1));
}

const BayerPattern kPatterns[] = {BayerPattern::BGGR, BayerPattern::RGGB, BayerPattern::GRBG, BayerPattern::GBRG};

}  // namespace

class TestFusedCuda : public QObject {
  Q_OBJECT
 private slots:
  void per_pixel_code_equals_fused_table() {
    const Lens lens = small_lens();
    for (BayerPattern p : kPatterns)
      for (double yaw : {0.0, 80.0}) {  // 80 degrees: the view reaches the mosaic's edge (reflected borders)
        const cv::Mat map = build_reprojection_map(lens, side_view(yaw));
        const cv::Mat raw = noisy_mosaic({320, 256}, 7);
        for (auto kernel : {FusedTable::Kernel::Scalar, FusedTable::Kernel::Auto}) {
          cv::Mat table;
          FusedTable(map, raw.size(), p, kernel).run(raw, table);
          const int diff = differing_pixels(table, fused_reference(map, raw, p));
          QVERIFY2(diff == 0, qPrintable(QString("%1 yaw %2: %3 channel values differ")
                                             .arg(QString::fromUtf8(to_string(p).data()))
                                             .arg(yaw)
                                             .arg(diff)));
        }
      }
  }

  void corners_edges_and_fill() {
    // Positions on the mosaic's first and last rows/columns (reflected taps), exact grid points, half-way points
    // (round half to even), and "no source" (negative) which takes the fill colour.
    const cv::Mat raw = noisy_mosaic({16, 12}, 3);
    cv::Mat map(1, 10, CV_32FC2);
    const cv::Vec2f at[10] = {
        {0, 0},   {15, 11}, {14.99f, 0.01f}, {0, 10.5f}, {7.5f, 5.5f}, {3 + 1.0f / 64, 4 + 3.0f / 64},
        {-1, -1}, {5, -1},  {-0.5f, 2},      {15, 5}};
    for (int i = 0; i < 10; ++i) map.at<cv::Vec2f>(0, i) = at[i];
    for (BayerPattern p : kPatterns) {
      cv::Mat table;
      FusedTable(map, raw.size(), p, FusedTable::Kernel::Scalar).run(raw, table, {9, 8, 7});
      const cv::Mat reference = fused_reference(map, raw, p, {9, 8, 7});
      QCOMPARE(differing_pixels(table, reference), 0);
      QCOMPARE(reference.at<cv::Vec3b>(0, 6), cv::Vec3b(9, 8, 7));
    }
    // At an exact grid point the sample is the demosaiced pixel itself: a blue site of BGGR keeps its value.
    const cv::Mat one = fused_reference(map.colRange(0, 1), raw, BayerPattern::BGGR);
    QCOMPARE(int(one.at<cv::Vec3b>(0, 0)[0]), int(raw.at<uchar>(0, 0)));
  }

  void rejects_bad_input() {
    const cv::Mat map(2, 2, CV_32FC2, cv::Scalar(0, 0));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, fused_reference(map, cv::Mat(4, 4, CV_16UC1), BayerPattern::BGGR));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             fused_reference(cv::Mat(2, 2, CV_32FC1), cv::Mat(4, 4, CV_8UC1), BayerPattern::BGGR));
  }

  void gpu_kernel_equals_cpu_or_refuses_with_reason() {
    const Lens lens = small_lens();
    const View view = side_view();
    const std::string why = cuda_preprocessing_unavailable();
    if (!why.empty()) {
      // No GPU (or no nvcc): building the preprocessor must fail at once, saying why, not at the first frame.
      const QString refusal = bs::test::refusal([&] { make_cuda_preprocessor(lens, view, BayerPattern::BGGR); });
      QVERIFY2(refusal.contains(QString::fromStdString(why)), qPrintable(refusal));
      QSKIP(qPrintable(QString("kernel not run here: %1").arg(QString::fromStdString(why))));
    }
    CudaPreprocessorInfo info;
    const Preprocessor gpu = make_cuda_preprocessor(lens, view, BayerPattern::BGGR, &info);
    QVERIFY(!info.device.empty());
    const cv::Mat raw = noisy_mosaic({320, 256}, 11);
    cv::Mat cpu;
    FusedTable(build_reprojection_map(lens, view), raw.size(), BayerPattern::BGGR).run(raw, cpu);
    QCOMPARE(differing_pixels(gpu(raw), cpu), 0);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, gpu(cv::Mat(10, 10, CV_8UC1)));
  }

  // The steps `bench vision` times apart (upload, kernel alone, download) give the same image as the CPU, and the
  // kernel's device time is positive; without a GPU they refuse at construction with the same reason.
  void gpu_steps_equal_cpu_or_refuse_with_reason() {
    const Lens lens = small_lens();
    const View view = side_view();
    const std::string why = cuda_preprocessing_unavailable();
    if (!why.empty()) {
      const QString refusal = bs::test::refusal([&] { CudaFusedSteps steps(lens, view, BayerPattern::RGGB); });
      QVERIFY2(refusal.contains(QString::fromStdString(why)), qPrintable(refusal));
      QSKIP(qPrintable(QString("kernel not run here: %1").arg(QString::fromStdString(why))));
    }
    CudaFusedSteps steps(lens, view, BayerPattern::RGGB);
    QVERIFY(!steps.device().empty());
    const cv::Mat raw = noisy_mosaic({320, 256}, 13);
    steps.upload(raw);
    steps.compute();
    cv::Mat gpu;
    steps.download(gpu);
    cv::Mat cpu;
    FusedTable(build_reprojection_map(lens, view), raw.size(), BayerPattern::RGGB).run(raw, cpu);
    QCOMPARE(differing_pixels(gpu, cpu), 0);
    QVERIFY(steps.kernel_seconds(3) > 0);
    QCOMPARE(steps.kernel_bytes(), 200.0 * 160 * 11 + 320.0 * 256);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, steps.upload(cv::Mat(10, 10, CV_8UC1)));
  }
};

QTEST_APPLESS_MAIN(TestFusedCuda)
#include "test_fused_cuda.moc"
