// SPDX-License-Identifier: GPL-3.0-or-later
// Roofline arithmetic: the roof, the ridge, placement of kernels, and ceilings gathered from runs and results.
#include <QTest>

#include "../../../support/run_on.h"
#include "analysis/roofline/roofline.h"

class TestRoofline : public QObject {
  Q_OBJECT
 private slots:
  void roof_and_ridge() {
    const bs::RooflineCeiling c{"vm",         "CPU", 400e9, "theoretical", 50e9, "triad", bs::DeviceKind::Other,
                                std::nullopt, "",    {}};
    QCOMPARE(*c.ridge_intensity(), 8.0);
    QCOMPARE(c.attainable(1.0), 50e9);     // memory-bound: I x bandwidth
    QCOMPARE(c.attainable(100.0), 400e9);  // compute-bound: the peak
    bs::RooflineCeiling no_bw = c;
    no_bw.bandwidth_bps.reset();
    QCOMPARE(no_bw.attainable(1.0), 400e9);
    QVERIFY(!no_bw.ridge_intensity());
  }
  void placement() {
    const bs::RooflineCeiling c{"vm",         "CPU", 400e9, "theoretical", 50e9, "triad", bs::DeviceKind::Other,
                                std::nullopt, "",    {}};
    // 2 GFLOP moving 1 GB in 0.1 s: I = 2, 20 GFLOP/s under a roof of 100 GFLOP/s.
    const auto p = bs::place_on_roofline(c, "stage", 2e9, 1e9, 0.1);
    QCOMPARE(p.intensity, 2.0);
    QCOMPARE(p.flops, 20e9);
    QCOMPARE(p.attainable, 100e9);
    QCOMPARE(p.fraction, 0.2);
    QVERIFY(p.memory_bound);
    // The rotation kernel, D = 4, N = 40000: 960000 flops per 68 bytes, far right of any ridge.
    QCOMPARE(bs::rotation_intensity(4, 40000), 6.0 * 4 * 40000 / 68.0);
    const auto r =
        bs::place_on_roofline(c, "rotation", 6.0 * 4 * 40000 * 1024, 68.0 * 1024, 6.0 * 4 * 40000 * 1024 / 350e9);
    QVERIFY(!r.memory_bound);
    QVERIFY(std::fabs(r.fraction - 350.0 / 400.0) < 1e-12);
  }
  void ceilings_from_runs_and_results() {
    auto run = bs::test::run_on<bs::FlopsRun>("vm", "CPU", "CPU SIMD");
    run.dims = 4;
    run.iterations = 1000;
    run.samples = {{1, {1e-3}}};
    run.theoretical_peak_flops = 400e9;
    bs::ResultSet set{"vm", "CPU", bs::DeviceKind::Cpu, "CPU SIMD", "benchscope-bandwidth", {}, {}};
    set.measurements.push_back({"stream-triad/128MiB", "bandwidth", "B/s", {40e9, 47e9, 45e9}, {}});
    set.measurements.push_back({"x", "time", "s", {1.0}, {}});
    bs::FlopsRun other = run;
    other.device = "GPU";
    other.theoretical_peak_flops.reset();  // falls back to the measured peak
    const std::vector<bs::FlopsRun> runs{run, other};
    const std::vector<bs::ResultSet> sets{set};
    const auto cs = bs::roofline_ceilings(runs, sets);
    QCOMPARE(cs.size(), std::size_t{2});
    QCOMPARE(cs[0].peak_flops, 400e9);
    QCOMPARE(*cs[0].bandwidth_bps, 47e9);  // the best repetition
    QVERIFY(!cs[1].bandwidth_bps);
    QCOMPARE(cs[1].peak_flops, 6.0 * 4 * 1000 * 1 / 1e-3);
  }
};

QTEST_APPLESS_MAIN(TestRoofline)
#include "test_roofline.moc"
