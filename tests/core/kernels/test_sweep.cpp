// SPDX-License-Identifier: GPL-3.0-or-later
#include <QTest>
#include <chrono>
#include <cmath>
#include <thread>

#include "analysis/peaks/flops.h"
#include "kernels/sweep.h"
#include "kernels/worker_spec.h"

using namespace bs::kernels;

class TestSweep : public QObject {
  Q_OBJECT
 private slots:
  void worker_specs() {
    QCOMPARE(parse_worker_spec("1,2,4,8"), (std::vector<std::int64_t>{1, 2, 4, 8}));
    QCOMPARE(parse_worker_spec("256:1024:256"), (std::vector<std::int64_t>{256, 512, 768, 1024}));
    QCOMPARE(parse_worker_spec("1:100:32"), (std::vector<std::int64_t>{1, 33, 65, 97}));  // the paper's CPU sweep
    QCOMPARE(parse_worker_spec("8,1,2,4:8:2"), (std::vector<std::int64_t>{1, 2, 4, 6, 8}));
    QCOMPARE(parse_worker_spec("256:1024000:256").size(), std::size_t{4000});
    QCOMPARE(parse_dims_list("4,1,2"), (std::vector<int>{1, 2, 4}));
  }
  void bad_specs_name_the_problem_data() {
    QTest::addColumn<QString>("spec");
    QTest::addColumn<QString>("message");
    QTest::newRow("empty") << ""
                           << "empty";
    QTest::newRow("zero") << "0,4"
                          << "at least 1";
    QTest::newRow("negative step") << "1:10:-1"
                                   << "at least 1";
    QTest::newRow("zero step") << "1:10:0"
                               << "at least 1";
    QTest::newRow("reversed") << "10:1:1"
                              << "start is greater than stop";
    QTest::newRow("junk") << "4x"
                          << "expected a whole number";
    QTest::newRow("two colons") << "1:2"
                                << "START:STOP:STEP";
    QTest::newRow("too many") << "1:2000000:1"
                              << "more than";
    QTest::newRow("overflow") << "99999999999999999999"
                              << "too large";
    QTest::newRow("range near INT64_MAX") << "9223372036854775000:9223372036854775807:1000"
                                          << "workers";
    QTest::newRow("count beyond memory") << "1,300000000"
                                         << "workers";
    QTest::newRow("empty part") << "1,,4"
                                << "expected a whole number";
    QTest::newRow("four fields") << "1:2:3:4"
                                 << "START:STOP:STEP";
  }
  void bad_specs_name_the_problem() {
    QFETCH(QString, spec);
    QFETCH(QString, message);
    try {
      parse_worker_spec(spec.toStdString());
      QFAIL("accepted");
    } catch (const std::invalid_argument& e) {
      QVERIFY2(QString(e.what()).contains(message), e.what());
    }
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, parse_dims_list("65"));
  }
  void sweep_produces_verified_runs() {
    const CpuInfo cpu = detect_cpu(/*calibrate=*/false);
    const Backend simd = cpu_backends(cpu).front();
    SweepSpec spec;
    spec.workers = {1, 8, 64};
    spec.dims = {1, 4};
    spec.iterations = 2000;
    spec.repeats = 2;
    int points = 0;
    const auto result = run_sweep(simd, cpu, spec, bs::CancelToken{}, {}, [&](const bs::FlopsRun&) { ++points; });
    QVERIFY(!result.cancelled);
    QCOMPARE(points, 6);
    QCOMPARE(result.runs.size(), std::size_t{2});
    for (const auto& run : result.runs) {
      QCOMPARE(run.samples.size(), std::size_t{3});
      QCOMPARE(run.samples[0].seconds.size(), std::size_t{2});
      QCOMPARE(run.provenance.origin, bs::DataOrigin::Measured);
      QVERIFY(!run.provenance.host.empty() && !run.provenance.cpu_model.empty());
      QCOMPARE(run.variant, std::string("throughput"));
      QVERIFY(run.provenance.gpu_model.empty());
      QVERIFY(run.provenance.tool.starts_with("benchscope "));
      QCOMPARE(run.provenance.date.size(), std::size_t{20});  // 2026-11-22T13:00:00Z
      QVERIFY(run.provenance.date.ends_with('Z'));
      QVERIFY(run.provenance.note.find(cpu.simd.name) != std::string::npos);
      QVERIFY(run.theoretical_peak_flops.has_value() == (simd.theoretical_peak_flops > 0));
      QVERIFY(bs::find_peak(run)->flops > 0);
      // FLOPS arithmetic: every point's mean is the mean over repetitions of 6 D N W / t.
      const auto curve = bs::flops_curve(run);
      QCOMPARE(curve.size(), run.samples.size());
      for (std::size_t i = 0; i < curve.size(); ++i) {
        const auto& sample = run.samples[i];
        double sum = 0;
        for (double t : sample.seconds)
          sum += 6.0 * run.dims * run.iterations * static_cast<double>(sample.workers) / t;
        QCOMPARE(curve[i].workers, sample.workers);
        QVERIFY(std::abs(curve[i].flops.mean - sum / static_cast<double>(sample.seconds.size())) <=
                1e-9 * curve[i].flops.mean);
      }
    }
  }
  void sweep_sorts_workers_and_refuses_what_a_backend_cannot_run() {
    const CpuInfo cpu = detect_cpu(false);
    Backend simd = cpu_backends(cpu).front();
    SweepSpec spec;
    spec.workers = {8, 1, 8, 2};
    spec.iterations = 100;
    spec.warmup = false;
    const auto result = run_sweep(simd, cpu, spec, bs::CancelToken{});
    QCOMPARE(result.runs.at(0).samples.size(), std::size_t{3});
    QCOMPARE(result.runs[0].samples[0].workers, std::int64_t{1});
    QCOMPARE(result.runs[0].samples[2].workers, std::int64_t{8});
    // A backend whose paper kernel has vector types for D = 1, 2, 4 only refuses D = 3 before running anything.
    simd.paper_dims = {1, 2, 4};
    spec.variant = Variant::Paper;
    spec.dims = {1, 3};
    int points = 0;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             run_sweep(simd, cpu, spec, bs::CancelToken{}, {}, [&](const bs::FlopsRun&) { ++points; }));
    QCOMPARE(points, 0);
    spec.dims = {4};
    spec.workers = {kMaxStatePoints};
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, run_sweep(simd, cpu, spec, bs::CancelToken{}));
  }
  void scalar_backend_matches_the_closed_form() {
    const CpuInfo cpu = detect_cpu(false);
    const Backend scalar = find_backend(cpu_backends(cpu), "cpu-scalar");
    for (int d : {1, 2, 4}) {
      std::vector<float> out;
      const RotationParams p{d, 1000};
      QVERIFY(scalar.run_point(p, 5, Variant::Paper, out, bs::CancelToken{}) > 0);
      QCOMPARE(out.size(), std::size_t{5});
      QCOMPARE(first_wrong_output(out, p), std::int64_t{-1});
    }
  }
  void cancel_from_progress_keeps_the_completed_points_data() {
    QTest::addColumn<int>("k");
    for (int k : {0, 1, 3, 5}) QTest::newRow(qPrintable(QString("after %1").arg(k))) << k;
  }
  void cancel_from_progress_keeps_the_completed_points() {
    QFETCH(int, k);
    const CpuInfo cpu = detect_cpu(false);
    const Backend simd = cpu_backends(cpu).front();
    SweepSpec spec;
    spec.workers = {1, 2, 3, 4, 5, 6, 7, 8};
    spec.iterations = 1000;
    spec.repeats = 2;
    bs::CancelToken cancel;
    int calls = 0;
    std::vector<std::string> steps;
    const auto result = run_sweep(simd, cpu, spec, cancel, [&](double f, std::string_view step) {
      QVERIFY(f >= 0 && f <= 1);
      steps.emplace_back(step);
      if (calls++ == k) cancel.cancel();  // progress is reported before each point: k points are complete
    });
    QVERIFY(result.cancelled);
    const std::size_t kept = result.runs.empty() ? 0 : result.runs[0].samples.size();
    QVERIFY(kept == static_cast<std::size_t>(k) || kept == static_cast<std::size_t>(k) + 1);
    for (const auto& run : result.runs)
      for (const auto& s : run.samples) {
        QCOMPARE(s.seconds.size(), std::size_t{2});
        QVERIFY(s.seconds[0] > 0 && s.seconds[1] > 0);
      }
    QCOMPARE(steps.front(), std::string("W=1, D=4"));
    QCOMPARE(steps.back(), std::string("cancelled"));
  }
  void cancel_during_a_long_point_stops_it() {
    // 4096 workers x 4 points x 1e9 steps would run for many minutes; a cancel from another thread after the
    // first chunks must end it with Cancelled (chunks are ~40 ms). Checks the outcome, not the time taken.
    const CpuInfo cpu = detect_cpu(false);
    for (const Backend& b : cpu_backends(cpu)) {
      bs::CancelToken cancel;
      std::thread canceller([&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
        cancel.cancel();
      });
      std::vector<float> out;
      const std::int64_t workers = b.id == "cpu-scalar" ? 4 : 4096;
      QVERIFY_THROWS_EXCEPTION(bs::Cancelled,
                               b.run_point({4, 1'000'000'000}, workers, b.variants.front(), out, cancel));
      canceller.join();
    }
  }
  void cancel_keeps_a_valid_partial_run() {
    const CpuInfo cpu = detect_cpu(false);
    const Backend simd = cpu_backends(cpu).front();
    SweepSpec spec;
    spec.workers = {1, 2, 3, 4, 5, 6, 7, 8};
    spec.iterations = 1000;
    bs::CancelToken cancel;
    int completed = 0;
    const auto result = run_sweep(simd, cpu, spec, cancel, {}, [&](const bs::FlopsRun&) {
      if (++completed == 3) cancel.cancel();
    });
    QVERIFY(result.cancelled);
    QCOMPARE(result.runs.size(), std::size_t{1});
    QCOMPARE(result.runs[0].samples.size(), std::size_t{3});
    for (const auto& s : result.runs[0].samples) QVERIFY(s.seconds.size() == 1 && s.seconds[0] > 0);
  }
  void cancel_interrupts_a_long_point_between_chunks() {
    // One point of 4096 workers x 4 points x 2e6 steps would take tens of seconds; a pre-set cancel must stop it
    // at the first chunk boundary instead. Counted in chunks of work, not in wall-clock time.
    const CpuInfo cpu = detect_cpu(false);
    const Backend simd = cpu_backends(cpu).front();
    bs::CancelToken cancel;
    cancel.cancel();
    std::vector<float> out;
    QVERIFY_THROWS_EXCEPTION(bs::Cancelled, simd.run_point({4, 2'000'000}, 4096, Variant::Throughput, out, cancel));
  }
};

QTEST_APPLESS_MAIN(TestSweep)
#include "test_sweep.moc"
