// SPDX-License-Identifier: GPL-3.0-or-later
// The flagging of FLOPS figures against the computed peak and the empirical ceiling, on synthetic numbers.
#include <QTest>

#include "analysis/peaks/ceiling_check.h"
#include "analysis/peaks/peak_ceilings.h"

class TestCeilingCheck : public QObject {
  Q_OBJECT
  static bool has(const std::vector<bs::PlausibilityFlag>& f, const char* code) {
    for (const auto& x : f)
      if (x.code == code) return true;
    return false;
  }
 private slots:
  void below_both_is_not_flagged() {
    const auto c = bs::compare_to_ceilings(300e9, 333e9, 380e9, "throughput variant");
    QVERIFY(c.flags.empty());
    QVERIFY(std::abs(*c.fraction_of_peak - 300.0 / 333.0) < 1e-12);
    QVERIFY(std::abs(*c.fraction_of_ceiling - 300.0 / 380.0) < 1e-12);
  }
  void above_the_computed_peak_within_the_ceiling_says_the_model_understates() {
    // The case: 376 GFLOPS by hand against a stated 333 and a measured mix ceiling of 381.
    const auto c = bs::compare_to_ceilings(376e9, 333e9, 381e9, "hand kernel", "rotation mix, 2026-11-23");
    QCOMPARE(c.flags.size(), std::size_t{1});
    QCOMPARE(c.flags.front().code, std::string(bs::flag_code::kAboveComputedPeak));
    QVERIFY2(c.flags.front().reason.find("112.9 %") != std::string::npos, c.flags.front().reason.c_str());
    QVERIFY(c.flags.front().reason.find("model understates") != std::string::npos);
    QVERIFY(c.flags.front().reason.find("rotation mix, 2026-11-23") != std::string::npos);
    // Just above 100 % is flagged as well: nothing is shown silently above the computed peak.
    QVERIFY(has(bs::compare_to_ceilings(333.5e9, 333e9, 381e9, "x").flags, bs::flag_code::kAboveComputedPeak));
    QVERIFY(bs::compare_to_ceilings(333e9, 333e9, 381e9, "x").flags.empty());
  }
  void above_both_and_without_a_ceiling() {
    const auto both = bs::compare_to_ceilings(400e9, 333e9, 381e9, "x");
    QVERIFY(has(both.flags, bs::flag_code::kAboveComputedPeak));
    QVERIFY(has(both.flags, bs::flag_code::kAboveEmpiricalCeiling));
    QVERIFY(both.flags.front().reason.find("above the empirical ceiling") != std::string::npos);
    const auto none = bs::compare_to_ceilings(400e9, 333e9, std::nullopt, "x");
    QCOMPARE(none.flags.size(), std::size_t{1});
    QVERIFY(none.flags.front().reason.find("No empirical ceiling") != std::string::npos);
    QVERIFY(!none.fraction_of_ceiling);
  }
  void above_the_ceiling_only_and_unknown_peaks() {
    const auto c = bs::compare_to_ceilings(390e9, 400e9, 381e9, "x");
    QCOMPARE(c.flags.size(), std::size_t{1});
    QCOMPARE(c.flags.front().code, std::string(bs::flag_code::kAboveEmpiricalCeiling));
    const auto u = bs::compare_to_ceilings(1e12, 0.0, std::nullopt, "x");
    QVERIFY(u.flags.empty() && !u.fraction_of_peak);
    QCOMPARE(bs::fraction_text(0.9834), std::string("98.3 %"));
    QCOMPARE(bs::fraction_text(std::nullopt), std::string("n/a"));
    QCOMPARE(bs::fraction_text(1.04, true), std::string("\xE2\x9A\xA0 104.0 %"));
  }
  void peak_rows_get_the_ceiling_of_their_device() {
    // A stored ceiling set (as kernels::ceiling_result_set writes it) for host "h", device "cpu".
    bs::ResultSet set;
    set.platform = "h";
    set.device = "cpu";
    set.backend = "CPU SIMD (AVX2+FMA)";
    set.source_format = bs::kCeilingSource;
    set.provenance.date = "2026-11-23T22:00:00Z";
    set.measurements.push_back({});
    set.measurements.back().name = "rotation-mix/avx2";
    set.measurements.back().metric = bs::kRotationMixMetric;
    set.measurements.back().unit = "FLOP/s";
    set.measurements.back().values = {100e9, 110e9};  // mean 105 GFLOPS
    bs::PeakRow row;
    row.platform = "h";
    row.device = "cpu";
    row.backend = "CPU SIMD (AVX2+FMA)";
    row.peak.flops = 102e9;
    row.theoretical_flops = 100e9;
    bs::PeakRow other = row;
    other.device = "gpu";
    other.peak.flops = 50e9;
    std::vector<bs::PeakRow> rows{row, other};
    const std::vector<bs::ResultSet> sets{set};
    bs::apply_empirical_ceilings(rows, sets);
    QVERIFY(std::abs(*rows[0].fraction_of_ceiling - 102.0 / 105.0) < 1e-12);
    QCOMPARE(*rows[0].empirical_ceiling_flops, 105e9);
    QVERIFY(rows[0].ceiling_how.find("2026-11-23T22:00:00Z") != std::string::npos);
    // 102 % of the computed peak, within the ceiling: flagged, and the reason says the model understates the core.
    QVERIFY(has(rows[0].flags, bs::flag_code::kAboveComputedPeak));
    QVERIFY(rows[0].flags.back().reason.find("model understates") != std::string::npos);
    QVERIFY(!rows[1].fraction_of_ceiling && !rows[1].empirical_ceiling_flops);  // another device: no ceiling
    QVERIFY(rows[1].flags.empty());
  }
};

QTEST_GUILESS_MAIN(TestCeilingCheck)
#include "test_ceiling_check.moc"
