// SPDX-License-Identifier: GPL-3.0-or-later
#include <QTest>
#include <cmath>
#include <random>

#include "analysis/stats/stats.h"

class TestStats : public QObject {
  Q_OBJECT
 private slots:
  void matches_two_pass_reference_with_large_offset() {
    // Welford must stay accurate where the naive sum-of-squares formula cancels catastrophically.
    std::mt19937 rng(42);
    std::normal_distribution<double> noise(0.0, 0.5);
    std::vector<double> v;
    for (int i = 0; i < 10000; ++i) v.push_back(1e9 + noise(rng));
    // The reference works on offsets from 1e9 so its own rounding does not dominate.
    double mean = 0;
    for (double x : v) mean += x - 1e9;
    mean = 1e9 + mean / static_cast<double>(v.size());
    double ss = 0;
    for (double x : v) ss += (x - mean) * (x - mean);
    const double sd = std::sqrt(ss / static_cast<double>(v.size() - 1));
    const bs::Summary s = bs::summarize(v);
    QCOMPARE(s.n, v.size());
    QVERIFY(std::abs(s.mean - mean) / mean < 1e-13);  // a few ULPs of 1e9
    QVERIFY(std::abs(s.sd - sd) / sd < 1e-6);
    QCOMPARE(s.min, *std::min_element(v.begin(), v.end()));
    QCOMPARE(s.max, *std::max_element(v.begin(), v.end()));
  }
  void small_counts() {
    QCOMPARE(bs::summarize({}).n, std::size_t{0});
    const double one[] = {3.5};
    const bs::Summary s1 = bs::summarize(one);
    QCOMPARE(s1.mean, 3.5);
    QCOMPARE(s1.sd, 0.0);
    const double two[] = {1.0, 3.0};
    const bs::Summary s2 = bs::summarize(two);
    QCOMPARE(s2.mean, 2.0);
    QCOMPARE(s2.sd, std::sqrt(2.0));  // sample SD (n - 1)
  }
};

QTEST_APPLESS_MAIN(TestStats)
#include "test_stats.moc"
