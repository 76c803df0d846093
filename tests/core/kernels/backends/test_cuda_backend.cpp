// SPDX-License-Identifier: GPL-3.0-or-later
#include <QTest>

#include "kernels/cuda/ceilings_cuda.h"
#include "kernels/cuda/rotation_cuda.h"
#include "kernels/rotation/rotation.h"

using namespace bs::kernels;

class TestCudaBackend : public QObject {
  Q_OBJECT
 private slots:
  void matches_the_closed_form_on_every_gpu() {
    std::string why;
    const auto gpus = cuda::devices(&why);
    if (gpus.empty()) QSKIP(qPrintable("CUDA backend compiled; not run: " + QString::fromStdString(why)));
    for (const auto& g : gpus)
      for (bool paper : {true, false})
        for (int d : {1, 2, 4})
          for (std::int64_t w : {1, 100, 5000}) {
            const RotationParams p{d, 1000};
            std::vector<float> out;
            QVERIFY(cuda::run_point(g.index, d, p.iterations, w, paper, out, bs::CancelToken{}) > 0);
            QCOMPARE(first_wrong_output(out, p), std::int64_t{-1});
          }
  }
  // The GPU's ceiling micro-kernels check their own results (exact FMA sums, rotation angles, the copy) and throw
  // on a wrong one; here they must run and give positive rates.
  void ceiling_kernels_run_and_check_their_work() {
    std::string why;
    const auto gpus = cuda::devices(&why);
    if (gpus.empty()) QSKIP(qPrintable("CUDA ceilings compiled; not run: " + QString::fromStdString(why)));
    cuda::CeilingKernels k(gpus.front().index, 0.01, 16);
    for (const cuda::CeilingRun& r : {k.fma(), k.rotation_mix(), k.copy()}) QVERIFY(r.work > 0 && r.seconds > 0);
    QVERIFY(k.last_mix_points() == 4 || k.last_mix_points() == 8 || k.last_mix_points() == 16);
    QVERIFY(k.copy_how().find("16 MiB") != std::string::npos);
  }
};

QTEST_APPLESS_MAIN(TestCudaBackend)
#include "test_cuda_backend.moc"
