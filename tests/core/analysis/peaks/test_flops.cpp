// SPDX-License-Identifier: GPL-3.0-or-later
#include <QTest>

#include "../../../support/run_on.h"
#include "analysis/peaks/flops.h"

namespace {
bs::FlopsRun run_with(std::vector<bs::WorkerSample> samples, int dims = 4, std::int64_t n = 40000) {
  auto r = bs::test::run_on<bs::FlopsRun>("P", "D", "B");
  r.dims = dims;
  r.iterations = n;
  r.samples = std::move(samples);
  return r;
}
}  // namespace

class TestFlops : public QObject {
  Q_OBJECT
 private slots:
  void formula_is_six_d_n_w_over_t() {
    QCOMPARE(bs::rotation_flop_count(4, 40000, 256), 6.0 * 4 * 40000 * 256);
    QCOMPARE(bs::rotation_flops(2, 1000, 10, 0.5), 6.0 * 2 * 1000 * 10 / 0.5);
  }
  void curve_mean_and_sd_over_repetitions() {
    const auto r = run_with({{10, {1.0, 2.0}}}, 1, 100);
    const auto c = bs::flops_curve(r);
    QCOMPARE(c.size(), std::size_t{1});
    const double a = 6.0 * 100 * 10 / 1.0, b = 6.0 * 100 * 10 / 2.0;
    QCOMPARE(c[0].flops.n, std::size_t{2});
    QCOMPARE(c[0].flops.mean, (a + b) / 2);
    QVERIFY(std::abs(c[0].flops.sd - std::abs(a - b) / std::sqrt(2.0)) < 1e-9);
  }
  void peak_is_highest_mean_and_fewest_workers_on_ties() {
    // 10 workers in 1 s and 20 workers in 2 s give the same FLOPS: the tie goes to 10.
    const auto r = run_with({{10, {1.0}}, {20, {2.0}}, {30, {4.0}}}, 1, 1);
    const auto p = bs::find_peak(r);
    QVERIFY(p.has_value());
    QCOMPARE(p->workers, std::int64_t{10});
    QCOMPARE(p->flops, 60.0);
    QVERIFY(!bs::find_peak(run_with({})).has_value());
  }
  void peak_table_ratios() {
    auto r = run_with({{1, {6.0 * 4 * 40000 / 5.25e12}}});
    r.reported_peak_flops = 0.88e12;
    r.theoretical_peak_flops = 10.5e12;
    const std::vector<bs::FlopsRun> runs = {r, run_with({})};
    const auto rows = bs::peak_table(runs);
    QCOMPARE(rows.size(), std::size_t{1});  // the run without samples is skipped
    QVERIFY(std::abs(rows[0].peak.flops - 5.25e12) < 1);
    QVERIFY(std::abs(*rows[0].ratio_to_reported - 5.25 / 0.88) < 1e-9);
    QVERIFY(std::abs(*rows[0].fraction_of_theoretical - 0.5) < 1e-9);
  }
};

QTEST_APPLESS_MAIN(TestFlops)
#include "test_flops.moc"
