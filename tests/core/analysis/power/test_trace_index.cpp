// SPDX-License-Identifier: GPL-3.0-or-later
// TraceIndex and PowerIndex: range statistics with interpolated ends against analytic values (a ramp, a sine) and
// against a brute-force rescan over many random ranges (with missing samples), so the prefix sums and the min/max
// sparse table cannot drift from the definition.
#include <QTest>
#include <cmath>
#include <memory>
#include <random>

#include "analysis/power/power.h"
#include "analysis/power/power_stats.h"
#include "analysis/power/range_table.h"
#include "analysis/power/trace_index.h"
#include "analysis/stats/stats.h"

namespace {

bool near(double a, double b, double tol) {
  return std::abs(a - b) <= tol * std::max(1.0, std::max(std::abs(a), std::abs(b)));
}

}  // namespace

class TestTraceIndex : public QObject {
  Q_OBJECT
 private slots:
  void ramp_between_samples_is_exact() {
    // P(t) = 3 + 2t W on irregular timestamps; the range [0.2, 1.9] s starts and ends between samples.
    const std::vector<double> t = {0, 0.1, 0.35, 1.0, 1.05, 2.0, 3.7};
    std::vector<double> p;
    for (double x : t) p.push_back(3 + 2 * x);
    const bs::TraceIndex index(t, p);
    const bs::RangeSummary r = index.summary(0.2, 1.9);
    QCOMPARE(r.from_s, 0.2);
    QCOMPARE(r.to_s, 1.9);
    QVERIFY(near(r.duration_s, 1.7, 1e-15));
    QVERIFY(near(r.integral, 3 * 1.7 + (1.9 * 1.9 - 0.2 * 0.2), 1e-13));  // ∫ 3 + 2t dt
    // Samples inside: 0.35, 1.0, 1.05 s -> 3.7, 5, 5.1 W.
    QCOMPARE(r.samples.n, std::size_t{3});
    QVERIFY(near(r.samples.mean, (3.7 + 5 + 5.1) / 3, 1e-14));
    QVERIFY(near(r.samples.min, 3.7, 0) && near(r.samples.max, 5.1, 0));
    QVERIFY(near(index.value_at(0.2), 3.4, 1e-14));
    // Reversed ends are the same range; outside the trace it is clamped.
    QCOMPARE(index.summary(1.9, 0.2).integral, r.integral);
    QVERIFY(near(index.integral(-5, 0.05), 3 * 0.05 + 0.05 * 0.05, 1e-14));
    // Both ends between the same two samples: one trapezoid of the interpolated values, no sample inside.
    const bs::RangeSummary inside = index.summary(2.1, 2.3);
    QCOMPARE(inside.samples.n, std::size_t{0});
    QVERIFY(near(inside.integral, 3 * 0.2 + (2.3 * 2.3 - 2.1 * 2.1), 1e-13));
  }
  void sine_integral_and_moments() {
    // sin over [0, 2π) at 100 kHz: the integral over [0.5, 2.5] is cos 0.5 − cos 2.5; the samples' mean over a
    // whole period is 0 and their SD 1/√2 (the sine's RMS).
    const std::size_t n = 628'319;
    std::vector<double> t(n), v(n);
    for (std::size_t k = 0; k < n; ++k) t[k] = k * 1e-5, v[k] = std::sin(t[k]);
    const bs::TraceIndex index(t, v);
    QVERIFY(std::abs(index.integral(0.5, 2.5) - (std::cos(0.5) - std::cos(2.5))) < 1e-9);
    const bs::RangeSummary whole = index.summary(0, 2 * M_PI);
    QVERIFY(std::abs(whole.samples.mean) < 1e-5);
    QVERIFY(std::abs(whole.samples.sd - 1 / std::sqrt(2.0)) < 1e-5);
    QVERIFY(near(whole.samples.max, 1, 1e-9) && near(whole.samples.min, -1, 1e-9));
    const bs::RangeSummary quarter = index.summary(0.3, M_PI / 2);
    QVERIFY(near(quarter.samples.min, std::sin(0.3), 1e-4) && near(quarter.samples.max, 1, 1e-9));
  }
  void random_ranges_match_a_rescan() {
    // 300k samples with missing ones: every query equals the plain computation over the same present samples.
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> dt(1e-4, 3e-4), val(-2, 50), unit(0, 1);
    const std::size_t n = 300'000;
    std::vector<double> t(n), v(n);
    double now = 0;
    for (std::size_t k = 0; k < n; ++k) {
      now += dt(rng);
      t[k] = now;
      v[k] = unit(rng) < 0.01 ? std::nan("") : val(rng);
    }
    const bs::TraceIndex index(t, v);
    std::vector<double> tp, vp;  // present samples
    for (std::size_t k = 0; k < n; ++k)
      if (!std::isnan(v[k])) tp.push_back(t[k]), vp.push_back(v[k]);
    for (int q = 0; q < 200; ++q) {
      double a = unit(rng) * now, b = unit(rng) * now;
      if (q % 10 == 0) b = a + unit(rng) * 0.01;  // short ranges: within one or two blocks
      if (a > b) std::swap(a, b);
      const bs::RangeSummary r = index.summary(a, b);
      std::vector<double> in;
      for (std::size_t k = 0; k < tp.size(); ++k)
        if (tp[k] >= a && tp[k] <= b) in.push_back(vp[k]);
      const bs::Summary ref = bs::summarize_samples(in);
      QCOMPARE(r.samples.n, ref.n);
      if (ref.n == 0) continue;
      QVERIFY(near(r.samples.mean, ref.mean, 1e-10));
      QVERIFY(near(r.samples.sd, ref.sd, 1e-9));
      QCOMPARE(r.samples.min, ref.min);
      QCOMPARE(r.samples.max, ref.max);
      // The integral: a straight trapezoid walk over the present samples with interpolated ends.
      const auto lerp = [&](double at) {
        const auto hi = static_cast<std::size_t>(std::lower_bound(tp.begin(), tp.end(), at) - tp.begin());
        if (hi == 0) return vp.front();
        if (hi >= tp.size()) return vp.back();
        return vp[hi - 1] + (vp[hi] - vp[hi - 1]) * (at - tp[hi - 1]) / (tp[hi] - tp[hi - 1]);
      };
      double pt = a, pv = lerp(a), sum = 0;
      for (std::size_t k = 0; k < tp.size(); ++k)
        if (tp[k] >= a && tp[k] <= b) sum += (tp[k] - pt) * (vp[k] + pv) / 2, pt = tp[k], pv = vp[k];
      sum += (b - pt) * (lerp(b) + pv) / 2;
      QVERIFY(near(r.integral, sum, 1e-9));
      if (q % 20 == 0) {
        const bs::Percentiles p = index.percentiles(a, b);
        QCOMPARE(p.p5, bs::percentile(in, 5));
        QCOMPARE(p.p50, bs::percentile(in, 50));
        QCOMPARE(p.p95, bs::percentile(in, 95));
        QCOMPARE(p.p99, bs::percentile(in, 99));
      }
    }
  }
  void power_stats_duration_and_energy_use_interpolated_ends() {
    // I(t) = 1 + t A at 1 s steps from 0 to 10 s, 12 V supply; [2.5, 7.25] s falls between samples.
    bs::PowerTrace trace;
    for (int k = 0; k <= 10; ++k) trace.time_s.push_back(k);
    std::vector<double> amps;
    for (double x : trace.time_s) amps.push_back(1 + x);
    trace.channels.push_back({"I", bs::PowerQuantity::Current, amps});
    trace.supply_voltage_v = 12;
    const bs::PowerStats s = bs::power_stats(trace, {.from_s = 2.5, .to_s = 7.25});
    QCOMPARE(s.n, std::size_t{5});  // 3, 4, 5, 6, 7 s
    QCOMPARE(s.duration_s, 4.75);
    const double charge = 4.75 + (7.25 * 7.25 - 2.5 * 2.5) / 2;  // ∫ 1 + t dt
    QVERIFY(near(*s.charge_c, charge, 1e-14));
    QVERIFY(near(*s.energy_j, 12 * charge, 1e-14));
    QVERIFY(near(*s.mean_power_w, 12 * charge / 4.75, 1e-14));
    QCOMPARE(s.current_a->summary.mean, 6.0);  // the samples' mean: 4..8 A
    // The thin wrapper and the whole-trace integral agree with the one definition.
    QCOMPARE(bs::trace_stats(trace, std::nullopt, 2.5, 7.25).energy_j, *s.energy_j);
    QCOMPARE(bs::trace_stats(trace, std::nullopt, 2.5, 7.25).duration_s, 4.75);
    // The table row: charge in C and mAh, energy in J and Wh, p2p.
    const std::vector<std::string> head = bs::range_headers(bs::RangeSignal::Current);
    const std::vector<std::string> row = bs::range_cells(s, bs::RangeSignal::Current);
    QCOMPARE(head.size(), row.size());
    QCOMPARE(head[6], std::string("p2p (A)"));
    QCOMPARE(row[6], std::string("4.0000"));
    QCOMPARE(head[11], std::string("charge (mAh)"));
    QVERIFY(near(std::stod(row[11]), charge / 3.6, 1e-4));
    QCOMPARE(bs::to_tsv({"a", "b (W)"}, {{"1", "2"}}), std::string("a\tb (W)\n1\t2\n"));
  }

  void in_place_and_scaled_indexes_answer_as_copies_do() {
    // Issue #19 "Scale": a view reads a long log in place (no copy) and power = current x supply is the current's
    // index scaled; both must give the numbers a copied index of the same values gives.
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.5, 3.0);
    auto samples = std::make_shared<std::vector<std::vector<double>>>(2);
    std::vector<double>&t = (*samples)[0], &amps = (*samples)[1];
    for (int k = 0; k < 5000; ++k) t.push_back(k * 0.01 + (k % 7) * 1e-4), amps.push_back(u(rng));
    const bs::TraceIndex copied(t, amps);
    const bs::TraceIndex in_place(t, amps, samples);
    QCOMPARE(in_place.time().data(), t.data());  // read in place, not copied
    QVERIFY(copied.time().data() != t.data());
    const double volts = 15.2;
    std::vector<double> watts;
    for (double a : amps) watts.push_back(a * volts);
    const bs::TraceIndex product(t, watts);
    const bs::TraceIndex scaled = in_place.scaled(volts);
    QCOMPARE(scaled.time().data(), t.data());  // shares the samples
    QCOMPARE(scaled.scale(), volts);
    for (auto [from, to] : {std::pair{0.0, 50.0}, std::pair{1.234, 1.2345}, std::pair{3.005, 41.777}}) {
      const bs::RangeSummary a = copied.summary(from, to), b = in_place.summary(from, to);
      QCOMPARE(b.samples.n, a.samples.n);
      QCOMPARE(b.samples.mean, a.samples.mean);
      QCOMPARE(b.integral, a.integral);
      QCOMPARE(b.samples.max, a.samples.max);
      const bs::RangeSummary p = product.summary(from, to), s = scaled.summary(from, to);
      QCOMPARE(s.samples.n, p.samples.n);
      QVERIFY(near(s.samples.mean, p.samples.mean, 1e-13));
      QVERIFY(near(s.samples.sd, p.samples.sd, 1e-12));
      QVERIFY(near(s.samples.min, p.samples.min, 1e-15));
      QVERIFY(near(s.samples.max, p.samples.max, 1e-15));
      QVERIFY(near(s.integral, p.integral, 1e-13));
      QVERIFY(near(scaled.percentiles(from, to).p95, product.percentiles(from, to).p95, 1e-15));
      QVERIFY(near(scaled.value_at(from), product.value_at(from), 1e-15));
    }
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, in_place.scaled(0));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, in_place.scaled(-2));
    // The owner keeps the samples alive after everyone else let go of them.
    const std::vector<double>* held = &t;
    samples.reset();
    QCOMPARE(in_place.time().data(), held->data());
    QCOMPARE(in_place.summary(0, 50).samples.n, std::size_t{5000});
    // With a missing sample the index copies the present ones (so it never reads NaN in place).
    auto gappy = std::make_shared<std::vector<double>>(std::vector<double>{1, std::nan(""), 3});
    const std::vector<double> tt = {0, 1, 2};
    const bs::TraceIndex g(tt, *gappy, gappy);
    QCOMPARE(g.size(), std::size_t{2});
    QVERIFY(g.unscaled_values().data() != gappy->data());
    QCOMPARE(g.integral(0, 2), 4.0);
  }

  void power_index_in_place_matches_the_copying_one() {
    auto trace = std::make_shared<bs::PowerTrace>();
    for (int k = 0; k <= 2000; ++k) trace->time_s.push_back(k * 0.001);
    std::vector<double> amps;
    for (double x : trace->time_s) amps.push_back(1 + std::sin(7 * x));
    trace->channels.push_back({"I", bs::PowerQuantity::Current, amps});
    trace->supply_voltage_v = 16;
    const bs::PowerIndex copying(*trace), in_place{std::shared_ptr<const bs::PowerTrace>(trace)};
    QCOMPARE(in_place.power_source(), bs::PowerSource::CurrentTimesSupply);
    QCOMPARE(in_place.power()->time().data(), trace->time_s.data());  // neither current nor power copied
    const bs::PowerStats a = copying.stats(0.1234, 1.777), b = in_place.stats(0.1234, 1.777);
    QCOMPARE(b.n, a.n);
    QCOMPARE(*b.energy_j, *a.energy_j);
    QCOMPARE(*b.charge_c, *a.charge_c);
    QCOMPARE(b.power_w->summary.mean, a.power_w->summary.mean);
    QCOMPARE(b.power_w->pct.p50, a.power_w->pct.p50);
    // And both equal current x 16 V computed per sample (power_stats of a trace with a power channel).
    bs::PowerTrace as_power = *trace;
    std::vector<double> watts;
    for (double a_i : amps) watts.push_back(16 * a_i);
    as_power.channels = {{"P", bs::PowerQuantity::Power, watts}};
    const bs::PowerStats w = bs::power_stats(as_power, {.from_s = 0.1234, .to_s = 1.777});
    QVERIFY(near(*w.energy_j, *b.energy_j, 1e-13));
    QVERIFY(near(w.power_w->summary.sd, b.power_w->summary.sd, 1e-12));
  }
};

QTEST_APPLESS_MAIN(TestTraceIndex)
#include "test_trace_index.moc"
