// SPDX-License-Identifier: GPL-3.0-or-later
// The OpenCL backend on whatever devices the ICD loader lists (PoCL's CPU device here and in CI).
#include <QTest>
#include <chrono>
#include <thread>

#include "kernels/backends/backend_opencl.h"
#include "kernels/sweep.h"

using namespace bs::kernels;

class TestOpenClBackend : public QObject {
  Q_OBJECT
 private slots:
  void every_device_and_variant_matches_the_closed_form() {
    const CpuInfo cpu = detect_cpu(false);
    const auto backends = opencl_backends(cpu);
    if (backends.empty()) QSKIP("no OpenCL platform installed (install pocl-opencl-icd)");
    for (const Backend& b : backends) {
      QVERIFY(!b.device_name.empty());
      for (Variant v : {Variant::Paper, Variant::Throughput})
        for (int d : {1, 2, 4})
          for (std::int64_t w : {1, 7, 100}) {
            const RotationParams p{d, 1000};
            std::vector<float> out;
            const double seconds = b.run_point(p, w, v, out, bs::CancelToken{});
            QVERIFY(seconds > 0);
            QCOMPARE(out.size(), static_cast<std::size_t>(w));
            QVERIFY2(first_wrong_output(out, p) == -1,
                     qPrintable(QString("%1 %2 D=%3 W=%4")
                                    .arg(QString::fromStdString(b.device_name), QString::fromStdString(variant_name(v)))
                                    .arg(d)
                                    .arg(w)));
          }
      std::vector<float> out;
      QVERIFY_THROWS_EXCEPTION(std::invalid_argument, b.run_point({3, 10}, 4, Variant::Paper, out, bs::CancelToken{}));
      bs::CancelToken cancel;
      cancel.cancel();
      QVERIFY_THROWS_EXCEPTION(bs::Cancelled, b.run_point({4, 2'000'000}, 4096, Variant::Throughput, out, cancel));
      QCOMPARE(b.variant_label(Variant::Throughput), std::string("float16x4"));
      QCOMPARE(b.variant_label(Variant::Paper), std::string("paper"));
    }
  }
  void cancel_during_a_long_launch_sequence_stops_it() {
    // Minutes of work in launches of ~40 ms: a cancel from another thread ends it with Cancelled.
    const CpuInfo cpu = detect_cpu(false);
    const auto backends = opencl_backends(cpu);
    if (backends.empty()) QSKIP("no OpenCL platform installed (install pocl-opencl-icd)");
    for (Variant v : {Variant::Paper, Variant::Throughput}) {
      bs::CancelToken cancel;
      std::thread canceller([&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(150));
        cancel.cancel();
      });
      std::vector<float> out;
      QVERIFY_THROWS_EXCEPTION(bs::Cancelled, backends.front().run_point({4, 1'000'000'000}, 1024, v, out, cancel));
      canceller.join();
    }
  }
  void sweep_records_the_device_and_variant() {
    const CpuInfo cpu = detect_cpu(false);
    const auto backends = opencl_backends(cpu);
    if (backends.empty()) QSKIP("no OpenCL platform installed (install pocl-opencl-icd)");
    SweepSpec spec;
    spec.workers = {1, 64};
    spec.dims = {2};
    spec.iterations = 500;
    spec.variant = Variant::Throughput;
    const auto result = run_sweep(backends.front(), cpu, spec, bs::CancelToken{});
    QCOMPARE(result.runs.size(), std::size_t{1});
    const bs::FlopsRun& run = result.runs[0];
    QCOMPARE(run.variant, std::string("float16x4"));
    QCOMPARE(run.backend, std::string("OpenCL"));
    QCOMPARE(run.provenance.gpu_model, backends.front().device_name);
    QVERIFY(run.provenance.note.find("driver") != std::string::npos);
    spec.variant = Variant::Paper;
    spec.dims = {3};
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, run_sweep(backends.front(), cpu, spec, bs::CancelToken{}));
  }
};

QTEST_APPLESS_MAIN(TestOpenClBackend)
#include "test_opencl_backend.moc"
