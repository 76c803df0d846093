// SPDX-License-Identifier: GPL-3.0-or-later
// What a sustained run concludes (#53), on synthetic records whose answer is known: stability as worst / best,
// the first slow interval, the sustained rate (last third) and the time to steady state, throttling by a clock
// below its threshold or a zone at its trip point with the onset and what throttled, and "unknown" (never "no
// throttling") when nothing is exposed.
#include <QTest>

#include <cmath>
#include <limits>

#include "sustain/sustain_analysis.h"

using namespace bs;
using namespace bs::sustain;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// n intervals of 1 s with the given rates.
SustainRun with_rates(const std::vector<double>& rates) {
  SustainRun r;
  r.rate_unit = "GFLOPS";
  r.interval_s = 1;
  r.rate = rates;
  for (std::size_t i = 0; i < rates.size(); ++i) r.t_s.push_back(static_cast<double>(i + 1));
  return r;
}

void add_clock(SustainRun& r, double max_hz, std::size_t drop_at, double dropped_hz) {
  ClockSeries c{"cpu0", max_hz, {}};
  for (std::size_t i = 0; i < r.t_s.size(); ++i) c.hz.push_back(i < drop_at ? max_hz : dropped_hz);
  r.clocks.push_back(c);
}

void add_zone(SustainRun& r, std::optional<double> trip, std::size_t hot_at, double hot_c) {
  TemperatureSeries t{"thermal_zone0 x86_pkg_temp", trip, {}};
  for (std::size_t i = 0; i < r.t_s.size(); ++i) t.celsius.push_back(i < hot_at ? 60.0 : hot_c);
  r.temperatures.push_back(t);
}

}  // namespace

class TestSustainAnalysis : public QObject {
  Q_OBJECT
 private slots:
  void stability_is_worst_over_best() {
    const SustainAnalysis a = analyse(with_rates({100, 99, 98, 100, 97.5, 99}));
    QVERIFY(a.has_rate);
    QCOMPARE(*a.peak_rate, 100.0);
    QCOMPARE(*a.stability_percent, 97.5);
    QVERIFY(a.stable);  // >= 97 %
    QVERIFY(!a.first_slow);
    QCOMPARE(a.rate.n, std::size_t{6});
  }

  void a_settable_threshold_decides_stable() {
    AnalysisOptions o;
    o.stable_percent = 98;
    const SustainAnalysis a = analyse(with_rates({100, 99, 98, 100, 97.5, 99}), o);
    QVERIFY(!a.stable);
    QVERIFY(a.first_slow);
    QCOMPARE(a.first_slow->index, std::size_t{4});
    QCOMPARE(a.first_slow->start_s, 4.0);
    QCOMPARE(a.first_slow->end_s, 5.0);
  }

  void a_competing_load_halfway_is_located() {
    std::vector<double> rates(20, 10.0);
    for (std::size_t i = 10; i < 20; ++i) rates[i] = 5.0;
    const SustainAnalysis a = analyse(with_rates(rates));
    QCOMPARE(*a.stability_percent, 50.0);
    QVERIFY(!a.stable);
    QCOMPARE(a.first_slow->index, std::size_t{10});
    QCOMPARE(a.first_slow->start_s, 10.0);
    // Sustained: the last third (6 of 20 intervals) at 5; steady from the slowdown on.
    QCOMPARE(a.sustained.mean, 5.0);
    QCOMPARE(a.sustained.n, std::size_t{6});
    QCOMPARE(*a.sustained_percent_of_peak, 50.0);
    QCOMPARE(*a.steady_s, 10.0);
  }

  void a_warm_up_is_not_the_first_slow_interval() {
    // Slow while starting (50, 70), at speed from 2 s, slowed by something else at 6 s.
    const SustainAnalysis a = analyse(with_rates({50, 70, 100, 99, 100, 98, 60, 60}));
    QVERIFY(a.first_slow);
    QCOMPARE(a.first_slow->index, std::size_t{6});
    QCOMPARE(a.first_slow->start_s, 6.0);
    QCOMPARE(*a.stability_percent, 50.0);  // stability still counts the warm-up: worst / best of every interval
    // At speed from the first interval: the next slow one is the first slow interval.
    const SustainAnalysis b = analyse(with_rates({100, 50, 50}));
    QCOMPARE(b.first_slow->index, std::size_t{1});
  }

  void steady_state_waits_for_the_rate_to_settle() {
    // Warming up: 50, 70, 90, then within ±3 % of 100.
    const SustainAnalysis a = analyse(with_rates({50, 70, 90, 99, 101, 100, 100, 99.5, 100.5}));
    QCOMPARE(*a.steady_s, 3.0);
    // A last interval off the band: never settled.
    const SustainAnalysis b = analyse(with_rates({100, 100, 100, 100, 100, 100, 100, 100, 80}));
    QVERIFY(!b.steady_s);
  }

  void intervals_without_work_are_left_out() {
    const SustainAnalysis a = analyse(with_rates({10, kNaN, 10, 8}));
    QCOMPARE(a.rate.n, std::size_t{3});
    QCOMPARE(*a.stability_percent, 80.0);
    QCOMPARE(a.first_slow->index, std::size_t{3});
  }

  void a_record_without_rate_has_no_stability() {
    SustainRun r = with_rates({});
    r.t_s = {1, 2, 3};
    add_clock(r, 3e9, 1, 1.5e9);
    const SustainAnalysis a = analyse(r);
    QVERIFY(!a.has_rate);
    QVERIFY(!a.stability_percent);
    QVERIFY(a.throttle.detected);  // the clocks still tell
  }

  void a_clock_below_its_threshold_throttles() {
    SustainRun r = with_rates(std::vector<double>(20, 10.0));
    add_clock(r, 3.0e9, 10, 1.8e9);  // 60 % of its maximum from interval 10 (10 .. 11 s)
    const SustainAnalysis a = analyse(r);
    QVERIFY(a.throttle.known);
    QVERIFY(a.throttle.detected);
    QCOMPARE(*a.throttle.onset_index, std::size_t{10});
    QCOMPARE(*a.throttle.onset_s, 10.0);
    QCOMPARE(a.throttle.what.size(), std::size_t{1});
    QVERIFY(QString::fromStdString(a.throttle.what[0]).contains("cpu0 at 1.80 GHz"));
    QVERIFY(QString::fromStdString(a.throttle.what[0]).contains("60 %"));
    QCOMPARE(a.throttle.clock_at_onset->value, 1.8e9);
    QCOMPARE(*a.throttle.clock_at_onset->limit, 3.0e9);
    QCOMPARE(a.throttle.spans.size(), std::size_t{1});
    QCOMPARE(a.throttle.spans[0].first, 10.0);
    QCOMPARE(a.throttle.spans[0].second, 20.0);
    QCOMPARE(a.throttle.throttled_s, 10.0);
    QCOMPARE(a.throttle.notes.size(), std::size_t{1});  // judged by clocks only
  }

  void the_threshold_is_settable() {
    SustainRun r = with_rates(std::vector<double>(6, 10.0));
    add_clock(r, 3.0e9, 3, 2.5e9);  // 83 %: not throttled at 0.8, throttled at 0.9
    QVERIFY(!analyse(r).throttle.detected);
    AnalysisOptions o;
    o.throttle_threshold = 0.9;
    QVERIFY(analyse(r, o).throttle.detected);
  }

  void a_zone_at_its_trip_point_throttles() {
    SustainRun r = with_rates(std::vector<double>(20, 10.0));
    add_clock(r, 3.0e9, 100, 0);  // never drops
    add_zone(r, 95.0, 12, 97.0);
    const SustainAnalysis a = analyse(r);
    QVERIFY(a.throttle.detected);
    QCOMPARE(*a.throttle.onset_s, 12.0);
    QCOMPARE(a.throttle.temperature_at_onset->value, 97.0);
    QCOMPARE(*a.throttle.temperature_at_onset->limit, 95.0);
    QVERIFY(QString::fromStdString(a.throttle.what[0]).contains(">= trip 95.0"));
    QCOMPARE(a.throttle.clock_at_onset->value, 3.0e9);  // the clock at the onset, though not throttled
  }

  void no_throttling_when_everything_holds() {
    SustainRun r = with_rates(std::vector<double>(10, 10.0));
    add_clock(r, 3.0e9, 100, 0);
    add_zone(r, 95.0, 100, 0);
    const SustainAnalysis a = analyse(r);
    QVERIFY(a.throttle.known);
    QVERIFY(!a.throttle.detected);
    QVERIFY(!a.throttle.onset_s);
    QVERIFY(a.throttle.notes.empty());
  }

  void nothing_exposed_is_unknown_never_no_throttling() {
    SustainRun r = with_rates(std::vector<double>(10, 10.0));
    r.not_exposed = {"no cpufreq under /sys/devices/system/cpu: no CPU clock",
                     "no thermal zone under /sys/class/thermal"};
    const SustainAnalysis a = analyse(r);
    QVERIFY(!a.throttle.known);
    QVERIFY(!a.throttle.detected);
    QVERIFY(a.throttle.unknown_reason.rfind("unknown: ", 0) == 0);
    QVERIFY(QString::fromStdString(a.throttle.unknown_reason).contains("no CPU clock"));
    QVERIFY(QString::fromStdString(a.throttle.unknown_reason).contains("not exposed"));
  }

  void a_clock_without_maximum_and_a_zone_without_trip_cannot_judge() {
    SustainRun r = with_rates(std::vector<double>(4, 10.0));
    r.clocks.push_back({"cpu0", std::nullopt, {1e9, 1e9, 1e9, 1e9}});
    add_zone(r, std::nullopt, 2, 120);
    const SustainAnalysis a = analyse(r);
    QVERIFY(!a.throttle.known);
    QVERIFY(QString::fromStdString(a.throttle.unknown_reason).contains("no clock with a stated maximum"));
  }

  void unread_values_are_not_throttling() {
    SustainRun r = with_rates(std::vector<double>(4, 10.0));
    r.clocks.push_back({"cpu0", 3e9, {3e9, kNaN, kNaN, 3e9}});
    const SustainAnalysis a = analyse(r);
    QVERIFY(a.throttle.known);
    QVERIFY(!a.throttle.detected);
  }
};

QTEST_APPLESS_MAIN(TestSustainAnalysis)
#include "test_sustain_analysis.moc"
