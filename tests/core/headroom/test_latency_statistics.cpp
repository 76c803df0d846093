// SPDX-License-Identifier: GPL-3.0-or-later
// The headroom statistics on synthetic latency series whose answers are known by construction or by an independent
// computation over the raw series (sorting, two-pass SD, a direct scan for runs of misses).
#include <QTest>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "headroom/headroom_measurement.h"
#include "headroom/latency_histogram.h"
#include "headroom/latency_recorder.h"
#include "headroom/thread_latency.h"

using namespace bs::headroom;

namespace {

// Nearest-rank percentile of the raw series, truncated to whole bins: what the histogram must reproduce.
std::int64_t nearest_rank(std::vector<std::int64_t> v, double q, std::int64_t bin_ns) {
  std::sort(v.begin(), v.end());
  auto rank = static_cast<std::size_t>(std::ceil(q / 100.0 * static_cast<double>(v.size()) - 1e-9));
  rank = std::clamp<std::size_t>(rank, 1, v.size());
  return v[rank - 1] / bin_ns * bin_ns;
}

}  // namespace

class TestLatencyStatistics : public QObject {
  Q_OBJECT
 private slots:
  void percentiles_of_a_ramp() {
    // 1000 cycles at 1, 2, ..., 1000 us: nearest rank k is the k-th value.
    LatencyRecorder r(2'000'000, 1000, 1'000'000);
    for (int us = 1000; us >= 1; --us) r.add(us * 1000LL);  // order must not matter
    const LatencySummary s = summarize(r.result());
    QCOMPARE(s.cycles, std::uint64_t{1000});
    QCOMPARE(s.p50.ns, 500'000LL);
    QCOMPARE(s.p99.ns, 990'000LL);
    QCOMPARE(s.p999.ns, 999'000LL);
    QCOMPARE(s.p9999.ns, 1'000'000LL);  // rank ceil(99.99) = 1000 = n: the true maximum
    QCOMPARE(*s.max_ns, 1'000'000LL);
    QCOMPARE(*s.min_ns, 1'000LL);
    QVERIFY(!s.p99.at_least);
  }

  void percentiles_match_the_sorted_series() {
    // A heavy-tailed series (most wake-ups early, a few late) with sub-microsecond resolution.
    std::mt19937_64 rng(7);
    std::lognormal_distribution<double> dist(std::log(8000.0), 0.6);
    std::vector<std::int64_t> raw;
    LatencyRecorder r(5'000'000, 1000, 100'000);
    for (int i = 0; i < 54321; ++i) {
      const auto ns = static_cast<std::int64_t>(dist(rng));
      raw.push_back(ns);
      r.add(ns);
    }
    const LatencyHistogram& h = r.histogram();
    for (double q : {0.0, 1.0, 50.0, 90.0, 99.0, 99.9, 99.99}) {
      const HistogramPercentile p = h.percentile(q);
      QCOMPARE(p.ns, nearest_rank(raw, q, 1000));
      QVERIFY(!p.at_least);
    }
    QCOMPARE(h.percentile(100).ns, *std::max_element(raw.begin(), raw.end()));  // exact, not binned
    QVERIFY(h.bookkeeping_error().empty());
  }

  void overflows_keep_the_true_maximum() {
    // Limit 100 us; 990 cycles at 10 us, 10 beyond the limit, the worst at 12.345 ms.
    LatencyRecorder r(100'000, 1000, 1'000'000);
    for (int i = 0; i < 990; ++i) r.add(10'000);
    for (int i = 0; i < 9; ++i) r.add(150'000 + i);
    r.add(12'345'000);
    const LatencyHistogram& h = r.histogram();
    QCOMPARE(h.overflows, std::uint64_t{10});
    QCOMPARE(h.binned(), std::uint64_t{990});
    QCOMPARE(h.cycles, h.binned() + h.overflows);
    QCOMPARE(*h.max_ns, 12'345'000LL);
    QCOMPARE(h.percentile(99).ns, 10'000LL);     // rank 990: still in the bins
    QCOMPARE(h.percentile(99.9).ns, 100'000LL);  // rank 999: among the overflows, only "at least the limit"
    QVERIFY(h.percentile(99.9).at_least);
    QCOMPARE(h.percentile(100).ns, 12'345'000LL);  // the maximum, beyond the last bin
    QVERIFY(!h.percentile(100).at_least);
    QVERIFY(h.bookkeeping_error().empty());
  }

  void bookkeeping_errors_are_named() {
    LatencyHistogram h = make_histogram(50'000);
    for (int i = 0; i < 20; ++i) h.add(i * 1000);
    h.add(70'000);
    QVERIFY(h.bookkeeping_error().empty());
    h.cycles += 3;  // a source that lost three cycles somewhere
    QCOMPARE(QString::fromStdString(h.bookkeeping_error()), QString("cycles 24 != 20 in bins + 1 overflows"));
    h.cycles -= 3;
    h.max_ns = 30'000;  // a maximum inside the bins although a cycle overflowed
    QVERIFY(QString::fromStdString(h.bookkeeping_error()).contains("below the limit"));

    HeadroomMeasurement m;
    m.phases.resize(2);
    m.phases[0].name = "idle";
    m.phases[1].name = "pipeline@30fps";
    ThreadLatency t;
    t.index = 2;
    t.histogram = h;
    m.phases[1].threads.push_back(t);
    QVERIFY(QString::fromStdString(m.bookkeeping_error()).startsWith("phase 'pipeline@30fps' thread 2: "));
  }

  void deadline_misses_and_runs() {
    // 1 kHz loop, 300 us of computation: a cycle misses when latency > 700 us. Pattern of misses: a single one,
    // a run of three, a run of two; a cycle exactly at the deadline is NOT a miss (the rule is "greater than").
    const std::int64_t period = 1'000'000, comp = 300'000;
    LatencyRecorder r(2'000'000, 1000, period);
    const std::vector<std::int64_t> lat_us = {5, 900, 5, 5, 701, 800, 1500, 700, 5, 750, 710, 5, 5};
    std::uint64_t expect_misses = 0, run = 0, longest = 0;
    for (std::int64_t us : lat_us) {
      r.add(us * 1000, comp);
      if (us * 1000 + comp > period) {
        ++expect_misses;
        longest = std::max(longest, ++run);
      } else {
        run = 0;
      }
    }
    QCOMPARE(expect_misses, std::uint64_t{6});  // the scan above is the independent reference; 700 us is no miss
    const ThreadLatency t = r.result();
    QCOMPARE(t.misses->count, std::uint64_t{6});
    QCOMPARE(t.misses->longest_run, std::uint64_t{3});
    QCOMPARE(longest, std::uint64_t{3});
    QCOMPARE(*t.max_response_ns, 1'800'000LL);
    const LatencySummary s = summarize(t);
    QCOMPARE(*s.misses, std::uint64_t{6});
    QCOMPARE(s.miss_percent(), 100.0 * 6 / 13);
    QCOMPARE(*s.longest_miss_run, std::uint64_t{3});
  }

  void misses_from_a_histogram_alone() {
    // An imported histogram (no per-cycle misses): counted from the bins, with no run length.
    ThreadLatency t;
    t.period_ns = 1'000'000;
    t.deadline_ns = 200'000;  // user deadline 200 us on a wake-up test
    t.histogram = make_histogram(400'000);
    for (int i = 0; i < 100; ++i) t.histogram.add(10'000);
    for (int i = 0; i < 4; ++i) t.histogram.add(250'000);
    for (int i = 0; i < 2; ++i) t.histogram.add(500'000);  // overflows: beyond 400 us, so above 200 us too
    LatencySummary s = summarize(t);
    QCOMPARE(*s.misses, std::uint64_t{6});
    QVERIFY(s.misses_exact);
    QVERIFY(!s.longest_miss_run);
    QVERIFY(s.mean_from_bins);
    // A deadline inside an occupied bin cannot be decided for that bin: flagged, not guessed.
    t.deadline_ns = 250'500;
    s = summarize(t);
    QCOMPARE(*s.misses, std::uint64_t{2});
    QVERIFY(!s.misses_exact);
    // The bin's last nanosecond as the threshold decides it.
    t.deadline_ns = 250'999;
    s = summarize(t);
    QCOMPARE(*s.misses, std::uint64_t{2});
    QVERIFY(s.misses_exact);
  }

  void count_above_beyond_the_limit() {
    LatencyHistogram h = make_histogram(100'000);
    h.add(5'000);
    h.add(300'000);
    QCOMPARE(h.count_above(200'000).count, std::uint64_t{1});  // the one overflow is the maximum, 300 us
    QVERIFY(h.count_above(200'000).exact);
    QCOMPARE(h.count_above(400'000).count, std::uint64_t{0});
    QVERIFY(h.count_above(400'000).exact);
    h.add(150'000);  // now two overflows: which of them is above 200 us is unknown beyond the maximum
    QCOMPARE(h.count_above(200'000).count, std::uint64_t{1});
    QVERIFY(!h.count_above(200'000).exact);
    QCOMPARE(h.count_above(99'999).count, std::uint64_t{2});
    QVERIFY(h.count_above(99'999).exact);
  }

  void exact_mean_and_sd_without_samples() {
    std::mt19937_64 rng(3);
    std::uniform_int_distribution<std::int64_t> dist(2'000, 90'000);
    LatencyRecorder r(100'000, 1000, 1'000'000);
    std::vector<double> raw;
    for (int i = 0; i < 10'000; ++i) {
      const std::int64_t ns = dist(rng);
      raw.push_back(static_cast<double>(ns));
      r.add(ns);
    }
    double mean = 0;
    for (double x : raw) mean += x;
    mean /= static_cast<double>(raw.size());
    double ss = 0;
    for (double x : raw) ss += (x - mean) * (x - mean);
    const double sd = std::sqrt(ss / static_cast<double>(raw.size() - 1));
    const ThreadLatency t = r.result();
    QVERIFY(std::abs(*t.mean_ns - mean) < 1e-6 * mean);
    QVERIFY(std::abs(*t.sd_ns - sd) < 1e-6 * sd);
    // The binned estimate is within half a bin of the exact mean for data this wide.
    QVERIFY(std::abs(*t.histogram.binned_mean_ns() - mean) <= 500.0);
  }

  void merge_adds_counts_and_extremes() {
    LatencyHistogram a = make_histogram(10'000), b = make_histogram(10'000);
    a.add(1'000);
    a.add(2'500);
    b.add(500);
    b.add(40'000);
    a.merge(b);
    QCOMPARE(a.cycles, std::uint64_t{4});
    QCOMPARE(a.overflows, std::uint64_t{1});
    QCOMPARE(*a.min_ns, 500LL);
    QCOMPARE(*a.max_ns, 40'000LL);
    QVERIFY(a.bookkeeping_error().empty());
    LatencyHistogram c = make_histogram(20'000);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, a.merge(c));
  }

  void empty_and_negative() {
    LatencyRecorder r(10'000, 1000, 1'000'000);
    QCOMPARE(summarize(r.result()).cycles, std::uint64_t{0});
    QCOMPARE(r.histogram().percentile(99).ns, 0LL);
    r.add(-250);  // a clock read before the target: counted as 0, never a negative bin
    QCOMPARE(r.histogram().bins[0], std::uint64_t{1});
    QCOMPARE(*r.histogram().min_ns, 0LL);
  }

  void flags_say_non_real_time() {
    HeadroomMeasurement m;
    m.kernel.preempt_rt = false;
    m.kernel.preemption = "PREEMPT_DYNAMIC";
    m.kernel.governor = "powersave";
    Phase idle;
    idle.name = "idle";
    ThreadLatency t;
    t.policy = "SCHED_OTHER";
    t.memory_locked = false;
    t.histogram = make_histogram(1000);
    t.misses = DeadlineMisses{};
    idle.threads.push_back(t);
    m.phases.push_back(idle);
    QVERIFY(!m.realtime());
    std::vector<std::string> f = flags(m);
    QCOMPARE(QString::fromStdString(f.at(0)),
             QString("non-real-time (SCHED_OTHER): not comparable with real-time results"));
    QVERIFY(std::find(f.begin(), f.end(), "kernel not PREEMPT_RT (PREEMPT_DYNAMIC)") != f.end());
    QVERIFY(std::find(f.begin(), f.end(), "memory not locked") != f.end());
    QVERIFY(std::find(f.begin(), f.end(), "CPU governor powersave") != f.end());

    HeadroomMeasurement rt = m;
    rt.phases[0].threads[0].policy = "SCHED_FIFO";
    rt.phases[0].threads[0].priority = 80;
    rt.phases[0].threads[0].memory_locked = true;
    QVERIFY(rt.realtime());
    f = flags(rt);
    QVERIFY(std::none_of(f.begin(), f.end(), [](const std::string& s) { return s.find("non-real-time") == 0; }));
    QCOMPARE(QString::fromStdString(comparability_problem(m, rt)),
             QString("one ran real-time (SCHED_FIFO/RR), the other did not"));
    rt.kind = LatencyKind::SystemWakeup;
    QVERIFY(QString::fromStdString(comparability_problem(m, rt)).startsWith("different quantities"));
  }
};

QTEST_APPLESS_MAIN(TestLatencyStatistics)
#include "test_latency_statistics.moc"
