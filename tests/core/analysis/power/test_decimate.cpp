// SPDX-License-Identifier: GPL-3.0-or-later
// Min/max decimation of long traces (the power view draws 10-million-sample logs through it): at most two points
// per pixel column, and each column keeps exactly the true min and max of its samples, in time order.
#include <QTest>
#include <cmath>
#include <limits>
#include <random>

#include "analysis/power/decimate.h"

namespace {

struct Trace {
  std::vector<double> t, v;
};

// Irregular timestamps (jittered 10 kHz) and noisy values with rare spikes both ways.
Trace noisy_trace(std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> jitter(0.2e-4, 1.8e-4), noise(-0.3, 0.3), pick(0, 1);
  Trace tr;
  tr.t.reserve(n);
  tr.v.reserve(n);
  double t = 0;
  for (std::size_t i = 0; i < n; ++i) {
    t += jitter(rng);
    double v = 2.5 + noise(rng);
    if (pick(rng) < 1e-4) v += pick(rng) < 0.5 ? 5 : -2;
    tr.t.push_back(t);
    tr.v.push_back(v);
  }
  return tr;
}

std::size_t column_of(double t, double lo, double hi, std::size_t columns) {
  const double w = (hi - lo) / static_cast<double>(columns);
  return std::min(columns - 1, static_cast<std::size_t>((t - lo) / w));
}

// Checks the decimation of `tr` over [lo, hi] against a brute-force min/max per column.
void check_columns(const Trace& tr, double lo, double hi, std::size_t columns) {
  const bs::DecimatedSeries d = bs::decimate_min_max(tr.t, tr.v, lo, hi, columns);
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> want_min(columns, inf), want_max(columns, -inf), got_min(columns, inf), got_max(columns, -inf);
  std::vector<int> got_count(columns, 0);
  for (std::size_t i = 0; i < tr.t.size(); ++i) {
    if (tr.t[i] < lo || tr.t[i] > hi) continue;
    const std::size_t c = column_of(tr.t[i], lo, hi, columns);
    want_min[c] = std::min(want_min[c], tr.v[i]);
    want_max[c] = std::max(want_max[c], tr.v[i]);
  }
  std::size_t inside = 0;
  for (std::size_t k = 0; k < d.t.size(); ++k) {
    if (k > 0) QVERIFY(d.t[k] >= d.t[k - 1]);  // time order kept
    if (d.t[k] < lo || d.t[k] > hi) continue;  // the neighbours kept outside the range
    ++inside;
    const std::size_t c = column_of(d.t[k], lo, hi, columns);
    ++got_count[c];
    got_min[c] = std::min(got_min[c], d.v[k]);
    got_max[c] = std::max(got_max[c], d.v[k]);
  }
  QVERIFY(inside <= 2 * columns);
  QVERIFY(d.t.size() <= 2 * columns + 2);
  for (std::size_t c = 0; c < columns; ++c) {
    QVERIFY2(got_count[c] <= 2, qPrintable(QString("column %1 has %2 points").arg(c).arg(got_count[c])));
    QCOMPARE(got_min[c], want_min[c]);  // exact: the decimated points are samples of the trace
    QCOMPARE(got_max[c], want_max[c]);
  }
}

}  // namespace

class TestDecimate : public QObject {
  Q_OBJECT
 private slots:
  void whole_trace_keeps_every_column_extreme() {
    const Trace tr = noisy_trace(1'000'000, 1);
    check_columns(tr, tr.t.front(), tr.t.back(), 1000);
  }

  void zoomed_range_and_neighbours() {
    const Trace tr = noisy_trace(200'000, 2);
    const double lo = tr.t[50'000] + 1e-5, hi = tr.t[150'000] - 1e-5;
    check_columns(tr, lo, hi, 317);
    const bs::DecimatedSeries d = bs::decimate_min_max(tr.t, tr.v, lo, hi, 317);
    // The samples just outside the view are kept, so the line reaches the plot's edges.
    QCOMPARE(d.t.front(), tr.t[50'000]);
    QCOMPARE(d.t.back(), tr.t[150'000]);
  }

  void few_samples_pass_through() {
    const Trace tr = noisy_trace(500, 3);
    const bs::DecimatedSeries d = bs::decimate_min_max(tr.t, tr.v, tr.t.front(), tr.t.back(), 400);
    QCOMPARE(d.t, tr.t);
    QCOMPARE(d.v, tr.v);
  }

  void gaps_and_nan() {
    // Samples only in the first and the last tenth of the range, one NaN among them.
    Trace tr;
    for (int i = 0; i < 1000; ++i) tr.t.push_back(i * 1e-3), tr.v.push_back(i % 7);
    for (int i = 0; i < 1000; ++i) tr.t.push_back(9 + i * 1e-3), tr.v.push_back(-(i % 5));
    tr.v[10] = std::nan("");
    const bs::DecimatedSeries d = bs::decimate_min_max(tr.t, tr.v, 0, 10, 100);
    for (double v : d.v) QVERIFY(!std::isnan(v));
    QVERIFY(d.t.size() <= 2 * 20);  // only the 20 non-empty columns give points
    QCOMPARE(*std::max_element(d.v.begin(), d.v.end()), 6.0);
    QCOMPARE(*std::min_element(d.v.begin(), d.v.end()), -4.0);
  }

  void bad_arguments() {
    const std::vector<double> t{0, 1}, v{1};
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, bs::decimate_min_max(t, v, 0, 1, 10));
    const std::vector<double> v2{1, 2};
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, bs::decimate_min_max(t, v2, 0, 1, 0));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, bs::decimate_min_max(t, v2, 1, 0, 10));
  }
};

QTEST_MAIN(TestDecimate)
#include "test_decimate.moc"
