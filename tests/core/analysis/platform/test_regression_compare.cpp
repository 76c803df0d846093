// SPDX-License-Identifier: GPL-3.0-or-later
// Mann-Whitney U against values worked out by hand, and the regression compare on synthetic repeated runs:
// a 10 % slowdown with enough repetitions is flagged, noise is not, and too few repetitions are not enough.
#include <random>

#include <QTest>

#include "../../../support/run_on.h"
#include "analysis/peaks/flops.h"
#include "analysis/platform/regression_compare.h"

namespace {

// A FLOPS run with `reps` repetitions per worker count; time = base * (1 + noise).
bs::FlopsRun make_run(double slowdown, int reps, double noise_sd, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, noise_sd);
  auto r = bs::test::run_on<bs::FlopsRun>("NUC", "NUC GPU", "OpenCL");
  r.dims = 4;
  r.iterations = 40000;
  for (std::int64_t w : {256, 512, 1024}) {
    bs::WorkerSample s{w, {}};
    const double base = 0.01 * static_cast<double>(w) / (w == 1024 ? 1.3 : 1.0);  // the peak is at 1024 workers
    for (int k = 0; k < reps; ++k) s.seconds.push_back(base * (1 + slowdown) * (1 + noise(rng)));
    r.samples.push_back(s);
  }
  return r;
}

bs::ResultSet make_set(double slowdown, int reps, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, 0.01);
  bs::ResultSet s{"NUC", "i7-7567U", bs::DeviceKind::Cpu, "CPU", "google-benchmark-json", {}, {}};
  bs::Measurement m{"BM_Rotate/4096", "real_time", "s", {}, {}};
  for (int k = 0; k < reps; ++k) m.values.push_back(1e-3 * (1 + slowdown) * (1 + noise(rng)));
  s.measurements.push_back(m);
  return s;
}

const bs::MeasureComparison& only_row(const std::vector<bs::MeasureComparison>& rows) {
  if (rows.size() != 1) throw std::runtime_error("expected one row, got " + std::to_string(rows.size()));
  return rows.front();
}

}  // namespace

class TestRegressionCompare : public QObject {
  Q_OBJECT
 private slots:
  void mann_whitney_exact_small_samples() {
    const std::vector<double> a{1, 2, 3}, b{4, 5, 6};
    auto r = bs::mann_whitney_u(a, b);
    QVERIFY(r.exact);
    QCOMPARE(r.u, 0.0);
    QVERIFY(std::fabs(r.p_value - 0.1) < 1e-12);  // 2 x 1/20 arrangements
    const std::vector<double> c{1, 2, 3, 4, 5}, d{6, 7, 8, 9, 10};
    r = bs::mann_whitney_u(d, c);
    QCOMPARE(r.u, 25.0);
    QVERIFY(std::fabs(r.p_value - 2.0 / 252.0) < 1e-12);
    const std::vector<double> e{1, 4, 5}, f{2, 3, 6};  // interleaved: no evidence
    QVERIFY(bs::mann_whitney_u(e, f).p_value > 0.5);
  }

  void mann_whitney_normal_approximation_with_ties() {
    // Worked by hand: rank sum of a 31.5, U = 3.5, tie term 96, var 59.096, z = 2.6667 -> p = 0.00766.
    const std::vector<double> a{1, 2, 2, 3, 3, 3, 4}, b{3, 4, 4, 5, 5, 6, 7};
    const auto r = bs::mann_whitney_u(a, b);
    QVERIFY(!r.exact);
    QCOMPARE(r.u, 3.5);
    QVERIFY2(std::fabs(r.p_value - 0.00766) < 2e-4, qPrintable(QString::number(r.p_value)));
    const std::vector<double> same{2, 2, 2};
    QCOMPARE(bs::mann_whitney_u(same, same).p_value, 1.0);
    QCOMPARE(bs::mann_whitney_u({}, same).p_value, 1.0);
  }

  void ten_percent_slowdown_with_repeats_is_a_regression() {
    const std::vector<bs::FlopsRun> a{make_run(0.0, 10, 0.01, 1)}, b{make_run(0.10, 10, 0.01, 2)};
    const auto rows = bs::compare_results({a, {}}, {b, {}});
    const auto& row = only_row(rows);
    QVERIFY(row.key.ends_with("W=1024"));  // compared at A's peak
    QCOMPARE(row.verdict, bs::CompareVerdict::Regression);
    QVERIFY(row.change < -0.07 && row.change > -0.12);  // FLOPS fall by 1 - 1/1.1 = 9.1 %
    QVERIFY(row.test.p_value < 0.001);
    QCOMPARE(row.a.n, std::size_t{10});
  }

  void noise_alone_is_not_flagged() {
    int flagged = 0;
    for (unsigned seed = 0; seed < 50; ++seed) {
      const std::vector<bs::FlopsRun> a{make_run(0.0, 10, 0.02, 100 + seed)}, b{make_run(0.0, 10, 0.02, 200 + seed)};
      for (const auto& row : bs::compare_results({a, {}}, {b, {}}, {.every_point = true}))
        if (row.verdict == bs::CompareVerdict::Regression || row.verdict == bs::CompareVerdict::Improvement) ++flagged;
    }
    QCOMPARE(flagged, 0);
  }

  void a_large_change_without_repeats_is_not_significant() {
    const std::vector<bs::FlopsRun> a{make_run(0.0, 1, 0.0, 1)}, b{make_run(0.30, 1, 0.0, 2)};
    QCOMPARE(only_row(bs::compare_results({a, {}}, {b, {}})).verdict, bs::CompareVerdict::NotSignificant);
  }

  void benchmark_times_lower_is_better() {
    const std::vector<bs::ResultSet> a{make_set(0.0, 12, 5)}, slower{make_set(0.10, 12, 6)},
        faster{make_set(-0.10, 12, 7)};
    QCOMPARE(only_row(bs::compare_results({{}, a}, {{}, slower})).verdict, bs::CompareVerdict::Regression);
    QCOMPARE(only_row(bs::compare_results({{}, a}, {{}, faster})).verdict, bs::CompareVerdict::Improvement);
    const auto t = bs::compare_results({{}, a}, {{}, a}, {.threshold = 0.05});
    QCOMPARE(only_row(t).verdict, bs::CompareVerdict::Unchanged);
  }

  void unmatched_measures_are_listed_on_their_side() {
    const std::vector<bs::FlopsRun> a{make_run(0.0, 3, 0.01, 1)};
    std::vector<bs::FlopsRun> b{make_run(0.0, 3, 0.01, 2)};
    b[0].backend = "CUDA";
    const auto rows = bs::compare_results({a, {}}, {b, {}});
    QCOMPARE(rows.size(), std::size_t{2});
    QVERIFY(rows[0].verdict == bs::CompareVerdict::OnlyInB && rows[1].verdict == bs::CompareVerdict::OnlyInA);
  }

  void units_decide_the_better_direction() {
    QCOMPARE(bs::higher_is_better_for_unit("s"), std::optional<bool>(false));
    QCOMPARE(bs::higher_is_better_for_unit("FLOP/s"), std::optional<bool>(true));
    QCOMPARE(bs::higher_is_better_for_unit(""), std::optional<bool>());
  }
};

QTEST_APPLESS_MAIN(TestRegressionCompare)
#include "test_regression_compare.moc"
