// SPDX-License-Identifier: GPL-3.0-or-later
#include <QTest>
#include <cmath>

#include "analysis/power/battery.h"
#include "analysis/power/power.h"

namespace {

bs::BatteryPack paper_pack() { return *bs::find_battery_preset("paper-4s-3850"); }

bs::DischargeOptions lipo(double step = 1.0) {
  bs::DischargeOptions o;
  o.model = bs::BatteryModel::Lipo;
  o.step_s = step;
  return o;
}

}  // namespace

class TestBatteryModels : public QObject {
  Q_OBJECT
 private slots:
  void constant_power_equals_the_formula() {
    const bs::BatteryPack pack = paper_pack();
    QCOMPARE(pack.nominal_v(), 14.8);
    for (const double watts : {9.484, 40.524, 265.5}) {
      const bs::DischargeResult r = bs::simulate_discharge(pack, bs::constant_load(watts));
      QVERIFY(std::abs(r.runtime_s / 3600 - bs::constant_power_runtime_h(14.8, 3.85, watts)) < 1e-9);
      QCOMPARE(r.stop_reason, std::string("depth of discharge reached"));
      QVERIFY(std::abs(r.energy_wh - 14.8 * 3.85) < 1e-9);
      QVERIFY(std::abs(r.series.back().soc) < 1e-9);
    }
    bs::DischargeOptions half;
    half.depth_of_discharge = 0.8;
    QVERIFY(std::abs(bs::simulate_discharge(pack, bs::constant_load(40), half).runtime_s -
                     14.8 * 3.85 * 0.8 / 40 * 3600) < 1e-6);
    // A parallel load (servos) adds to every phase.
    QVERIFY(std::abs(bs::simulate_discharge(pack, bs::constant_load(40.5, 225)).runtime_s -
                     14.8 * 3.85 / 265.5 * 3600) < 1e-6);
  }
  void mission_profile_repeats_its_phases() {
    const bs::Mission m = bs::parse_mission("idle:60:10,walk:30:100,kick:10:200");
    QCOMPARE(m.phases.size(), std::size_t{3});
    QCOMPARE(m.mean_load_w(), (600 + 3000 + 2000) / 100.0);
    const bs::DischargeResult r = bs::simulate_discharge(paper_pack(), m);
    // 56.98 Wh = 205128 J; one pass takes 5600 J: 36 passes (201600 J, 3600 s), then 3528 J more:
    // idle 600 J (60 s), walk 2928 J of 3000 (29.28 s).
    QVERIFY(std::abs(r.runtime_s - (3600 + 60 + 29.28)) < 1e-6);
    QCOMPARE(r.series.back().phase, std::size_t{1});
    // The state of charge falls monotonically from 1 to 0.
    for (std::size_t k = 1; k < r.series.size(); ++k) QVERIFY(r.series[k].soc <= r.series[k - 1].soc + 1e-12);
    QCOMPARE(r.series.front().soc, 1.0);
    // A mission that is not repeated can end before the battery does.
    bs::Mission once = m;
    once.repeat = false;
    const bs::DischargeResult short_run = bs::simulate_discharge(paper_pack(), once);
    QCOMPARE(short_run.runtime_s, 100.0);
    QCOMPARE(short_run.stop_reason, std::string("mission ended"));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, bs::parse_mission("idle:60"));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, bs::parse_mission("idle:-1:5"));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, bs::parse_mission("idle:x:5"));
  }
  void lipo_with_a_flat_curve_and_no_resistance_is_the_constant_power_model() {
    bs::BatteryPack pack = paper_pack();
    pack.ocv = {{0, 3.7}, {1, 3.7}};
    pack.internal_resistance_ohm = 0;
    pack.cutoff_cell_v = 0;
    const double lipo_s = bs::simulate_discharge(pack, bs::constant_load(40.524), lipo()).runtime_s;
    const double ideal_s = bs::simulate_discharge(pack, bs::constant_load(40.524)).runtime_s;
    QVERIFY(std::abs(lipo_s - ideal_s) < 1e-6 * ideal_s);
  }
  void lipo_runtime_is_the_curves_energy_without_losses() {
    // With R = 0 and no cut-off the time is capacity x the curve's mean voltage / power, exactly.
    bs::BatteryPack pack = paper_pack();
    pack.internal_resistance_ohm = 0;
    pack.cutoff_cell_v = 0;
    const double watts = 40.524;
    const double expected = 3.85 * 3600 * 4 * bs::mean_ocv_per_cell(bs::typical_lipo_ocv()) / watts;
    const double got = bs::simulate_discharge(pack, bs::constant_load(watts), lipo(0.5)).runtime_s;
    QVERIFY2(std::abs(got - expected) < 1e-3 * expected, qPrintable(QString("%1 vs %2").arg(got).arg(expected)));
  }
  void voltage_sag_costs_runtime() {
    const bs::BatteryPack base = paper_pack();
    const double watts = 40.524 + 225;  // the NUC with the servos at full load
    double previous = 1e30;
    for (const double r_ohm : {0.0, 0.02, 0.04, 0.08, 0.16}) {
      bs::BatteryPack pack = base;
      pack.internal_resistance_ohm = r_ohm;
      const bs::DischargeResult r = bs::simulate_discharge(pack, bs::constant_load(watts), lipo());
      QVERIFY2(r.runtime_s < previous, qPrintable(QString::number(r_ohm)));  // more resistance, less time
      previous = r.runtime_s;
      // Under constant power the current rises as the terminal voltage falls.
      for (std::size_t k = 1; k < r.series.size(); ++k) {
        QVERIFY(r.series[k].terminal_v <= r.series[k - 1].terminal_v + 1e-9);
        QVERIFY(r.series[k].current_a >= r.series[k - 1].current_a - 1e-9);
      }
    }
    // With sag and a cut-off, the LiPo model delivers less energy than the curve holds.
    bs::BatteryPack lossless = base;
    lossless.internal_resistance_ohm = 0;
    lossless.cutoff_cell_v = 0;
    const auto sagging = bs::simulate_discharge(base, bs::constant_load(watts), lipo());
    const auto ideal = bs::simulate_discharge(lossless, bs::constant_load(watts), lipo());
    QVERIFY(sagging.energy_wh < ideal.energy_wh);
    QCOMPARE(sagging.stop_reason, std::string("cut-off voltage reached"));
    // A load the pack cannot carry through its resistance collapses at once.
    bs::BatteryPack weak = base;
    weak.internal_resistance_ohm = 5;
    const auto collapse = bs::simulate_discharge(weak, bs::constant_load(watts), lipo());
    QVERIFY(collapse.stop_reason.find("collapse") != std::string::npos);
    QCOMPARE(collapse.runtime_s, 0.0);
  }
  void depth_of_discharge_and_inputs() {
    bs::DischargeOptions o = lipo();
    o.depth_of_discharge = 0.5;
    const auto half = bs::simulate_discharge(paper_pack(), bs::constant_load(40), o);
    QCOMPARE(half.stop_reason, std::string("depth of discharge reached"));
    QVERIFY(std::abs(half.series.back().soc - 0.5) < 1e-9);
    QVERIFY(half.runtime_s < bs::simulate_discharge(paper_pack(), bs::constant_load(40), lipo()).runtime_s);
    QCOMPARE(bs::ocv_per_cell(bs::typical_lipo_ocv(), 1.0), 4.2);
    QCOMPARE(bs::ocv_per_cell(bs::typical_lipo_ocv(), 0.525), 3.845);
    o.depth_of_discharge = 1.5;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, bs::simulate_discharge(paper_pack(), bs::constant_load(40), o));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, bs::simulate_discharge(paper_pack(), bs::Mission{}));
    QVERIFY(bs::find_battery_preset("6s-10000") && !bs::find_battery_preset("9s"));
  }
};

QTEST_APPLESS_MAIN(TestBatteryModels)
#include "test_battery_models.moc"
