// SPDX-License-Identifier: GPL-3.0-or-later
#include <QTest>
#include <cmath>
#include <filesystem>

#include <opencv2/imgcodecs.hpp>

#include "vision/demosaic/bayer.h"
#include "vision/demosaic/bayer_reference.h"
#include "vision/demosaic/bayer_simd.h"

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

constexpr BayerPattern kPatterns[] = {BayerPattern::BGGR, BayerPattern::RGGB, BayerPattern::GRBG, BayerPattern::GBRG};

// Mosaics that reach every corner of the arithmetic: uniform noise over the full range, only 0 and the maximum
// (the largest over- and undershoots of the MHC kernels, so the clamps and the widest intermediates), and a
// smooth ramp with a little noise (values near each other, where rounding decides).
cv::Mat random_mosaic(int w, int h, int depth, int kind, cv::RNG& rng) {
  const int type = depth == CV_8U ? CV_8UC1 : CV_16UC1;
  const double top = depth == CV_8U ? 255 : 65535;
  cv::Mat m(h, w, type);
  if (kind == 0) {
    rng.fill(m, cv::RNG::UNIFORM, 0, top + 1);
  } else if (kind == 1) {
    cv::Mat bits(h, w, CV_8UC1);
    rng.fill(bits, cv::RNG::UNIFORM, 0, 2);
    bits.convertTo(m, type, top);
  } else {
    cv::Mat f(h, w, CV_64FC1);
    rng.fill(f, cv::RNG::NORMAL, 0, top / 200);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) f.at<double>(y, x) += top * (0.2 + 0.6 * (x + 2 * y) / (w + 2.0 * h));
    f.convertTo(m, type);
  }
  return m;
}

// "" when equal, else where and how the first pixel differs.
QString first_difference(const cv::Mat& got, const cv::Mat& want) {
  if (got.size() != want.size() || got.type() != want.type()) return "size or type differs";
  for (int y = 0; y < got.rows; ++y)
    for (int x = 0; x < got.cols; ++x)
      for (int k = 0; k < 3; ++k) {
        const int a = got.depth() == CV_8U ? got.at<cv::Vec3b>(y, x)[k] : got.at<cv::Vec3w>(y, x)[k];
        const int b = want.depth() == CV_8U ? want.at<cv::Vec3b>(y, x)[k] : want.at<cv::Vec3w>(y, x)[k];
        if (a != b)
          return QString("pixel (x %1, y %2) channel %3: %4, reference %5").arg(x).arg(y).arg(k).arg(a).arg(b);
      }
  return {};
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
                                  .arg(QString::fromUtf8(to_string(p).data()))
                                  .arg(bil)
                                  .arg(mhc)
                                  .arg(ocv)
                                  .toUtf8();
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

  // The fast path (SIMD interior, scalar borders, row stripes on threads) against the scalar definition, every
  // output pixel, for every instruction set this binary has and this CPU runs, both depths, all four patterns,
  // both methods, odd and even sizes from the smallest allowed up to past several vector widths, and a full frame.
  void fast_path_equals_reference_bit_for_bit() {
    const std::vector<std::string> targets = demosaic_simd_targets();
    QVERIFY(!targets.empty());
    std::vector<cv::Size> sizes;
    for (int w = 4; w <= 40; ++w)
      for (int h : {4, 5, 7}) sizes.emplace_back(w, h);
    for (int w : {63, 64, 65, 66, 67, 97, 127, 128, 129, 130, 131}) sizes.emplace_back(w, 6);
    sizes.emplace_back(5, 37);
    sizes.emplace_back(203, 29);
    cv::RNG rng(20261123);
    long compared = 0;
    for (const std::string& target : targets) {
      demosaic_simd_pin_target(target);
      QCOMPARE(QString(demosaic_simd_target()), QString::fromStdString(target));
      for (int depth : {CV_8U, CV_16U})
        for (const cv::Size& size : sizes)
          for (int kind = 0; kind < 3; ++kind) {
            const cv::Mat raw = random_mosaic(size.width, size.height, depth, kind, rng);
            for (BayerPattern p : kPatterns)
              for (DemosaicMethod m : {DemosaicMethod::Bilinear, DemosaicMethod::MalvarHeCutler}) {
                const QString diff = first_difference(demosaic(raw, p, m), demosaic_reference(raw, p, m));
                const QByteArray what =
                    QString("%1, %2-bit %3x%4 kind %5, %6 %7: %8")
                        .arg(QString::fromStdString(target))
                        .arg(depth == CV_8U ? 8 : 16)
                        .arg(size.width)
                        .arg(size.height)
                        .arg(kind)
                        .arg(QString::fromUtf8(to_string(p).data()), QString::fromUtf8(to_string(m).data()), diff)
                        .toUtf8();
                QVERIFY2(diff.isEmpty(), what.constData());
                ++compared;
              }
          }
    }
    demosaic_simd_pin_target("");
    // A full frame of the paper's size on the best instruction set, several random images.
    for (int depth : {CV_8U, CV_16U})
      for (int kind = 0; kind < 3; ++kind) {
        const cv::Mat raw = random_mosaic(1280, 1024, depth, kind, rng);
        for (BayerPattern p : kPatterns)
          for (DemosaicMethod m : {DemosaicMethod::Bilinear, DemosaicMethod::MalvarHeCutler}) {
            const QByteArray what =
                QString("1280x1024 %1-bit kind %2, %3 %4")
                    .arg(depth == CV_8U ? 8 : 16)
                    .arg(kind)
                    .arg(QString::fromUtf8(to_string(p).data()), QString::fromUtf8(to_string(m).data()))
                    .toUtf8();
            QVERIFY2(first_difference(demosaic(raw, p, m), demosaic_reference(raw, p, m)).isEmpty(), what.constData());
            ++compared;
          }
      }
    qInfo("demosaic() equal to demosaic_reference() in %ld images; instruction sets: %s", compared,
          [&] {
            std::string s;
            for (const auto& t : targets) s += t + " ";
            return s;
          }()
              .c_str());
  }

  // The overload that writes into `out`: reuses a buffer of the right size and type (as cvtColor does), replaces
  // any other, and gives what the returning overload gives.
  void demosaic_into_a_kept_buffer() {
    cv::RNG rng(7);
    const cv::Mat raw = random_mosaic(70, 33, CV_16U, 0, rng);
    cv::Mat out(5, 5, CV_8UC1);
    demosaic(raw, BayerPattern::GRBG, DemosaicMethod::MalvarHeCutler, out);
    QCOMPARE(out.type(), CV_16UC3);
    QVERIFY(
        first_difference(out, demosaic_reference(raw, BayerPattern::GRBG, DemosaicMethod::MalvarHeCutler)).isEmpty());
    const uchar* kept = out.data;
    demosaic(raw, BayerPattern::GBRG, DemosaicMethod::Bilinear, out);
    QCOMPARE(out.data, kept);
    QVERIFY(first_difference(out, demosaic(raw, BayerPattern::GBRG, DemosaicMethod::Bilinear)).isEmpty());
    QVERIFY(first_difference(out, demosaic_reference(raw, BayerPattern::GBRG, DemosaicMethod::Bilinear)).isEmpty());
  }

  // The build's choice (Highway or the portable path) is the one CMake announced at configure time. Where the runner
  // names the instruction sets this CPU must offer (BENCHSCOPE_EXPECT_DEMOSAIC_TARGETS, comma-separated, best first:
  // the aarch64 cross test sets it for each CPU qemu emulates), the list is exactly that, so
  // fast_path_equals_reference_bit_for_bit has compared each of them with the reference and skipped none.
  void the_expected_instruction_sets_are_tested() {
    QCOMPARE(demosaic_simd_uses_highway(), BENCHSCOPE_EXPECT_HIGHWAY != 0);
    QStringList have;
    for (const std::string& t : demosaic_simd_targets()) have << QString::fromStdString(t);
    if (!demosaic_simd_uses_highway()) QCOMPARE(have, QStringList{"portable"});
    const QString expected = qEnvironmentVariable("BENCHSCOPE_EXPECT_DEMOSAIC_TARGETS");
    if (!expected.isEmpty()) QCOMPARE(have.join(','), expected);
  }

  void pinning_an_instruction_set() {
    const std::string best = demosaic_simd_target();
    QCOMPARE(demosaic_simd_targets().front(), best);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, demosaic_simd_pin_target("no such instruction set"));
    demosaic_simd_pin_target(demosaic_simd_targets().back());
    QCOMPARE(std::string(demosaic_simd_target()), demosaic_simd_targets().back());
    demosaic_simd_pin_target("");
    QCOMPARE(std::string(demosaic_simd_target()), best);
  }

  // Below 4x4 neither path is defined (the 5x5 MHC window cannot be reflected into 1 or 2 pixels): both refuse.
  void tiny_images_are_refused_by_both_paths() {
    for (const cv::Size size :
         {cv::Size(1, 1), cv::Size(2, 2), cv::Size(3, 5), cv::Size(5, 3), cv::Size(3, 3), cv::Size(4, 3)})
      for (int type : {CV_8UC1, CV_16UC1})
        for (DemosaicMethod m : {DemosaicMethod::Bilinear, DemosaicMethod::MalvarHeCutler}) {
          const cv::Mat raw(size, type, cv::Scalar(7));
          QVERIFY_THROWS_EXCEPTION(std::invalid_argument, demosaic(raw, BayerPattern::RGGB, m));
          QVERIFY_THROWS_EXCEPTION(std::invalid_argument, demosaic_reference(raw, BayerPattern::RGGB, m));
        }
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, demosaic_reference(cv::Mat(8, 8, CV_8UC1), BayerPattern::BGGR,
                                                                       DemosaicMethod::OpenCvBilinear));
  }

  void bad_input() {
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             demosaic(cv::Mat(8, 8, CV_32FC1), BayerPattern::BGGR, DemosaicMethod::Bilinear));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             demosaic(cv::Mat(2, 2, CV_8UC1), BayerPattern::BGGR, DemosaicMethod::Bilinear));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, mosaic(cv::Mat(8, 8, CV_8UC1), BayerPattern::BGGR));
    QVERIFY(std::isinf(psnr(scene(16, 16, CV_8U), scene(16, 16, CV_8U))));
  }

  void kodak_images_when_present() {
    const std::filesystem::path dir = BENCHSCOPE_SOURCE_DIR "/../shared/datasets/kodak";
    if (!std::filesystem::exists(dir / "kodim01.png")) QSKIP("Kodak images not present (../shared/datasets/kodak)");
    // Under qemu (the aarch64 cross test) the 24 photographs take longer than Qt Test's 5 minutes per function; they
    // check image quality, which is the same integer arithmetic compared bit for bit above on every target.
    if (qEnvironmentVariableIsSet("BENCHSCOPE_UNDER_EMULATOR")) QSKIP("Kodak images not run under an emulator");
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
