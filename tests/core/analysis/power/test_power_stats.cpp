// SPDX-License-Identifier: GPL-3.0-or-later
#include <QTest>
#include <cmath>

#include "analysis/platform/efficiency.h"
#include "analysis/power/power.h"
#include "analysis/power/power_phases.h"
#include "analysis/power/power_stats.h"
#include "analysis/power/power_time.h"

namespace {

bs::PowerTrace current_trace(std::vector<double> t, std::vector<double> amps, std::optional<double> supply) {
  bs::PowerTrace trace;
  trace.time_s = std::move(t);
  trace.channels.push_back({"I", bs::PowerQuantity::Current, std::move(amps)});
  trace.supply_voltage_v = supply;
  return trace;
}

}  // namespace

class TestPowerStats : public QObject {
  Q_OBJECT
 private slots:
  void missing_samples_are_skipped_never_zero() {
    // Power 1, (missing), 3, 5 W at 0, 1, 2, 3 s.
    const double nan = std::nan("");
    bs::PowerTrace trace;
    trace.time_s = {0, 1, 2, 3};
    trace.channels.push_back({"P", bs::PowerQuantity::Power, {1, nan, 3, 5}});
    // Present samples 1, 3, 5: n = 3, mean 3 W, SD 2 W, median 3 W (as 0 it would be n 4, mean 2.25 W).
    const bs::PowerStats s = bs::power_stats(trace);
    QCOMPARE(s.n, std::size_t{3});     // readings present (issue #32.5), not rows
    QCOMPARE(s.rows, std::size_t{4});  // rows in the range
    QCOMPARE(s.power_w->summary.n, std::size_t{3});
    QCOMPARE(s.power_w->summary.mean, 3.0);
    QCOMPARE(s.power_w->summary.sd, 2.0);
    QCOMPARE(s.power_w->summary.min, 1.0);
    QCOMPARE(s.power_w->pct.p50, 3.0);
    // Energy bridges the gap: 0..2 s (1 + 3) / 2 x 2 = 4 J, 2..3 s (3 + 5) / 2 x 1 = 4 J -> 8 J.
    QCOMPARE(*s.energy_j, 8.0);
    QCOMPARE(bs::integrate_trapezoid(trace.time_s, trace.channels[0].values), 8.0);
    const bs::TraceStats ts = bs::trace_stats(trace);
    QCOMPARE(ts.power_w->n, std::size_t{3});
    QCOMPARE(ts.power_w->mean, 3.0);
    QCOMPARE(ts.power_p50, 3.0);
    QCOMPARE(ts.energy_j, 8.0);
    // A window cut inside the gap: present (0, 1), (2, 3), (3, 5); at 0.5 s 1.5 W, at 2.5 s 4 W:
    // 0.5..2 s (1.5 + 3) / 2 x 1.5 = 3.375 J, 2..2.5 s (3 + 4) / 2 x 0.5 = 1.75 J -> 5.125 J.
    QVERIFY(std::abs(bs::integrate_range(trace.time_s, trace.channels[0].values, 0.5, 2.5) - 5.125) < 1e-12);
    // Missing at the ends: the integral covers the present span only (1..2 s: (2 + 4) / 2 = 3 J).
    QCOMPARE(bs::integrate_trapezoid({0, 1, 2, 3}, {nan, 2, 4, nan}), 3.0);
    QCOMPARE(bs::percentile({nan, 2, 4, nan}, 50), 3.0);
    // Nothing present: unknown, not 0 W.
    trace.channels[0].values = {nan, nan, nan, nan};
    QVERIFY(!bs::power_stats(trace).power_w);
    QVERIFY(!bs::power_stats(trace).energy_j);
    QVERIFY(!bs::trace_stats(trace).power_w);
  }
  void the_total_channel_is_the_power_of_the_trace() {
    // Two rails and their total: statistics use the named total wherever "the power" is asked for.
    bs::PowerTrace trace;
    trace.time_s = {0, 1};
    trace.channels.push_back({"CPU", bs::PowerQuantity::Power, {2, 2}});
    trace.channels.push_back({"TOT", bs::PowerQuantity::Power, {7, 9}});
    trace.total_channel = "TOT";
    QCOMPARE(bs::power_stats(trace).power_w->summary.mean, 8.0);
    QCOMPARE(bs::trace_stats(trace).power_w->mean, 8.0);
    QCOMPARE(bs::derive_power(trace).values, (std::vector<double>{7, 9}));
    QCOMPARE(bs::main_channel(trace, bs::PowerQuantity::Power)->name, std::string("TOT"));
    trace.total_channel.clear();  // none named: the first
    QCOMPARE(bs::power_stats(trace).power_w->summary.mean, 2.0);
  }
  void phases_skip_missing_samples() {
    // 0 W for 10 s, then 10 W for 10 s, every third sample missing: still two phases split at 10 s.
    std::vector<double> t, v;
    for (int k = 0; k < 200; ++k) {
      t.push_back(k * 0.1);
      v.push_back(k % 3 == 1 ? std::nan("") : (k < 100 ? 0.0 : 10.0));
    }
    const auto phases = bs::detect_phases(t, v, {});
    QCOMPARE(phases.size(), std::size_t{2});
    QVERIFY(std::abs(phases[1].start_s - 10.0) < 0.25);
    QVERIFY(std::abs(phases[1].mean - 10.0) < 1e-9);
  }
  void trapezoid_on_irregular_timestamps_vs_analytic() {
    // P(t) = 3 + 2t: the trapezoid rule is exact for a line, also for a window cut between samples.
    const std::vector<double> t = {0, 0.1, 0.35, 1.0, 1.05, 2.0, 3.7};
    std::vector<double> p;
    for (double x : t) p.push_back(3 + 2 * x);
    const auto exact = [](double a, double b) { return 3 * (b - a) + (b * b - a * a); };
    QVERIFY(std::abs(bs::integrate_range(t, p, 0, 3.7) - exact(0, 3.7)) < 1e-12);
    QVERIFY(std::abs(bs::integrate_range(t, p, 0.2, 1.9) - exact(0.2, 1.9)) < 1e-12);
    QVERIFY(std::abs(bs::integrate_range(t, p, -5, 0.05) - exact(0, 0.05)) < 1e-12);  // clamped to the trace
    QCOMPARE(bs::integrate_range(t, p, 2, 1), 0.0);
    // A curve: sin over irregular samples converges to 1 - cos with the mesh.
    std::vector<double> ts, vs;
    for (int k = 0; k <= 4000; ++k) {
      const double x = 3.0 * std::pow(k / 4000.0, 1.5);  // denser at the start
      ts.push_back(x);
      vs.push_back(std::sin(x));
    }
    QVERIFY(std::abs(bs::integrate_range(ts, vs, 0, 3) - (1 - std::cos(3.0))) < 1e-5);
  }
  void percentiles_interpolate() {
    const std::vector<double> v = {5, 1, 4, 2, 3};  // sorted 1..5
    const bs::Percentiles p = bs::percentiles(v);
    QCOMPARE(p.p50, 3.0);
    QCOMPARE(p.p5, 1.2);  // pos 0.2 between 1 and 2
    QCOMPARE(p.p95, 4.8);
    QCOMPARE(p.p99, 4.96);
    std::vector<double> ramp;
    for (int k = 0; k <= 1000; ++k) ramp.push_back(k);
    QCOMPARE(bs::percentiles(ramp).p99, 990.0);
    QCOMPARE(bs::percentiles(std::vector<double>{7}).p5, 7.0);
  }
  void stats_over_a_range_and_power_sources() {
    bs::PowerTrace t = current_trace({0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10}, {1, 1, 1, 1, 1, 3, 3, 3, 3, 3, 3}, 10.0);
    bs::PowerStatsOptions o;
    o.from_s = 5;
    o.to_s = 10;
    bs::PowerStats s = bs::power_stats(t, o);
    QCOMPARE(s.n, std::size_t{6});
    QCOMPARE(s.duration_s, 5.0);
    QCOMPARE(s.power_w->summary.mean, 30.0);
    QCOMPARE(*s.energy_j, 150.0);
    QCOMPARE(*s.charge_c, 15.0);
    QCOMPARE(s.power_source, bs::PowerSource::CurrentTimesSupply);
    QCOMPARE(*s.supply_v, 10.0);
    // A window cut between samples: energy from the interpolated ends (10 * (1 + 3)/2 ... ).
    o.from_s = 4.5;
    o.to_s = 5.5;
    s = bs::power_stats(t, o);
    QCOMPARE(s.n, std::size_t{1});
    QVERIFY(std::abs(*s.energy_j - (0.5 * (20 + 30) / 2 + 0.5 * 30)) < 1e-12);
    // Override of the supply, no supply at all, a voltage channel.
    o = {};
    o.supply_v = 5.0;
    QCOMPARE(bs::power_stats(t, o).power_w->summary.max, 15.0);
    t.supply_voltage_v.reset();
    s = bs::power_stats(t);
    QVERIFY(!s.power_w && !s.energy_j);
    QCOMPARE(s.power_source, bs::PowerSource::Unknown);
    t.channels.push_back({"V", bs::PowerQuantity::Voltage, std::vector<double>(11, 12.0)});
    s = bs::power_stats(t);
    QCOMPARE(s.power_source, bs::PowerSource::CurrentTimesVoltage);
    QCOMPARE(s.power_w->summary.max, 36.0);
    QCOMPARE(s.channels.size(), std::size_t{2});
    QCOMPARE(std::string(bs::unit_of(s.channels[1].quantity)), std::string("V"));
    o = {};
    o.from_s = 3;
    o.to_s = 2;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, bs::power_stats(t, o));
  }
  void phases_of_a_step_signal() {
    // idle 1 A for 10 s, load 3 A for 20 s, mid 2 A for 8 s, idle 1 A for 12 s; 10 Hz, +-0.05 A noise, one spike.
    std::vector<double> t, v;
    unsigned seed = 12345;
    const auto noise = [&] {
      seed = seed * 1103515245u + 12345u;
      return ((seed >> 16) % 1000) / 1000.0 * 0.1 - 0.05;
    };
    for (int k = 0; k < 500; ++k) {
      const double x = k * 0.1;
      t.push_back(x);
      const double level = x < 10 ? 1 : x < 30 ? 3 : x < 38 ? 2 : 1;
      v.push_back(level + noise());
    }
    v[100 + 55] = 6.0;  // a 0.1 s spike inside the load phase is not a phase
    const auto phases = bs::detect_phases(t, v);
    QCOMPARE(phases.size(), std::size_t{4});
    const double starts[] = {0, 10, 30, 38};
    const char* names[] = {"idle", "load", "load", "idle"};
    for (std::size_t i = 0; i < 4; ++i) {
      QVERIFY2(std::abs(phases[i].start_s - starts[i]) <= 0.2, qPrintable(QString::number(phases[i].start_s)));
      QCOMPARE(phases[i].name, std::string(names[i]));
    }
    QVERIFY(std::abs(phases[1].mean - 3.0) < 0.05);
    QCOMPARE(phases.back().end_s, t.back());
    // A flat noisy log is one phase; a minimum phase longer than the load merges it away.
    std::vector<double> flat;
    for (std::size_t k = 0; k < t.size(); ++k) flat.push_back(2 + noise());
    QCOMPARE(bs::detect_phases(t, flat).size(), std::size_t{1});
    bs::PhaseOptions longer;
    longer.min_phase_s = 25;
    QVERIFY(bs::detect_phases(t, v, longer).size() < 4);
    // Matching a benchmark of about 20 s to the load phase when clocks were not shared.
    const auto match = bs::match_load_phase(phases, 19.0);
    QVERIFY(match.has_value());
    QCOMPARE(match->first, phases[1].first);
    QVERIFY(!bs::match_load_phase(phases, 60.0).has_value());
  }
  void align_a_run_by_absolute_times() {
    bs::PowerTrace t = current_trace({0, 1, 2, 3, 4, 5}, {1, 1, 2, 2, 1, 1}, 16.0);
    QVERIFY(!bs::align_run(t, "2026-11-22T10:00:02Z", "2026-11-22T10:00:04Z"));  // no absolute start
    t.start_time = "2026-11-22T09:59:59.500Z";
    const auto w = bs::align_run(t, "2026-11-22T10:00:01.5Z", "2026-11-22T11:00:03+01:00");
    QVERIFY(w.has_value());
    QCOMPARE(w->from_s, 2.0);
    QCOMPARE(w->to_s, 3.5);
    QVERIFY(!bs::align_run(t, "2026-11-22T12:00:00Z", "2026-11-22T12:00:01Z"));  // outside the trace
  }
  void iso_times() {
    QCOMPARE(*bs::parse_iso8601("1970-01-01T00:00:00Z"), 0.0);
    QCOMPARE(*bs::parse_iso8601("2000-03-01 00:00:00") - *bs::parse_iso8601("2000-02-28T00:00:00"), 2 * 86400.0);
    QCOMPARE(*bs::parse_iso8601("2026-11-22T10:00:01,25"), *bs::parse_iso8601("2026-11-22T10:00:01.250"));
    QVERIFY(!bs::parse_iso8601("2026-02-29T00:00:00"));  // not a leap year
    QVERIFY(!bs::parse_iso8601("2026-11-22"));
    QVERIFY(!bs::parse_iso8601("2026-11-22T25:00:00"));
    QCOMPARE(*bs::parse_month_day_year("11-22-2026", "10:00:01"), *bs::parse_iso8601("2026-11-22T10:00:01"));
    QCOMPARE(bs::format_iso8601(*bs::parse_iso8601("2026-11-22T10:00:01.250")), std::string("2026-11-22T10:00:01.250"));
  }
  void efficiency_figures_are_labelled() {
    QCOMPARE(std::round(bs::paper_gflops_per_watt(5.25e12, 16, 3.135751) * 100) / 100, 104.64);
    QCOMPARE(bs::gflops_per_watt_at_mean_power(1e12, 50), 20.0);
    QCOMPARE(bs::joules_per_gflop(1e12, 50), 0.05);
    QCOMPARE(bs::joules_per_gflop_measured(100, 4e12), 0.025);
    bs::EfficiencyInputs in;
    in.peak_flops = 1e12;
    in.supply_v = 16;
    in.max_current_a = 2.5;
    in.mean_power_w = 32;
    const auto figures = bs::efficiency_figures(in);
    QCOMPARE(figures.size(), std::size_t{3});
    QCOMPARE(figures[0].value, 25.0);
    QVERIFY(figures[0].label.find("paper") != std::string::npos &&
            figures[0].label.find("16.0 V") != std::string::npos);
    QCOMPARE(figures[1].unit, std::string("GFLOPS/W"));
    QCOMPARE(figures[2].unit, std::string("J/GFLOP"));
    in.mean_power_w = 0;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, bs::efficiency_figures(in));
  }
};

QTEST_APPLESS_MAIN(TestPowerStats)
#include "test_power_stats.moc"
