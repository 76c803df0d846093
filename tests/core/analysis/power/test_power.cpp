// SPDX-License-Identifier: GPL-3.0-or-later
// The paper's power, efficiency and battery numbers, computed from sample_data through the importer and core.
#include <QTest>
#include <cmath>

#include "analysis/power/power.h"
#include "workspace/registry.h"

namespace {

bs::PowerTrace load(const char* name) {
  return bs::import_file(std::string(BENCHSCOPE_SOURCE_DIR "/sample_data/paper-2018/power/") + name, bs::CancelToken{})
      .power_traces.at(0);
}

double round2(double v) { return std::round(v * 100) / 100; }

}  // namespace

class TestPower : public QObject {
  Q_OBJECT
 private slots:
  void reproduces_the_paper() {
    struct Case {
      const char* file;
      double mean_a, sd_a, mean_w, gflops_per_w, minutes, peak_flops;
    };
    const Case cases[] = {{"nuc-current.csv", 2.53, 0.35, 40.52, 104.64, 84.36, 5.25e12},
                          {"jetson-current.csv", 0.59, 0.09, 9.48, 41.26, 360.48, 0.49e12}};
    for (const Case& c : cases) {
      const bs::TraceStats s = bs::trace_stats(load(c.file));  // supply voltage from the log: 16 V
      QCOMPARE(round2(s.current_a->mean), c.mean_a);
      QCOMPARE(round2(s.current_a->sd), c.sd_a);
      QCOMPARE(round2(s.power_w->mean), c.mean_w);
      QCOMPARE(round2(bs::paper_flops_per_watt(c.peak_flops, 16.0, s.current_a->max) / 1e9), c.gflops_per_w);
      QCOMPARE(round2(bs::constant_power_runtime_h(14.8, 3.85, s.power_w->mean) * 60), c.minutes);
    }
  }
  void trapezoid_on_irregular_timestamps() {
    // P(t) = 2t on irregular samples: the trapezoid rule is exact for a linear function.
    const std::vector<double> t = {0, 0.1, 0.35, 1.0, 1.05, 2.0};
    std::vector<double> p;
    for (double x : t) p.push_back(2 * x);
    QVERIFY(std::abs(bs::integrate_trapezoid(t, p) - 4.0) < 1e-12);
  }
  void percentiles_and_ranges() {
    QCOMPARE(bs::percentile({1, 2, 3, 4, 5}, 50), 3.0);
    QCOMPARE(bs::percentile({1, 2, 3, 4}, 50), 2.5);
    QCOMPARE(bs::percentile({5, 1, 3}, 100), 5.0);
    bs::PowerTrace t;
    t.supply_voltage_v = 10;
    for (int i = 0; i <= 10; ++i) t.time_s.push_back(i);
    t.channels.push_back({"I", bs::PowerQuantity::Current, {1, 1, 1, 1, 1, 3, 3, 3, 3, 3, 3}});
    const auto s = bs::trace_stats(t, std::nullopt, 5.0, 10.0);
    QCOMPARE(s.n, std::size_t{6});
    QCOMPARE(s.power_w->mean, 30.0);
    QCOMPARE(s.energy_j, 150.0);
    QCOMPARE(bs::trace_stats(t, 5.0).power_w->max, 15.0);  // an explicit supply overrides the log's
    t.supply_voltage_v.reset();
    QVERIFY(!bs::trace_stats(t).power_w.has_value());  // current only and no supply: power unknown
  }
  void battery_model_checks_its_inputs() {
    QCOMPARE(bs::constant_power_runtime_h(10, 2, 20, 0.5), 0.5);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, bs::constant_power_runtime_h(10, 2, 0));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, bs::constant_power_runtime_h(10, 2, 5, 1.5));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, bs::paper_flops_per_watt(1e12, 16, 0));
  }
};

QTEST_APPLESS_MAIN(TestPower)
#include "test_power.moc"
