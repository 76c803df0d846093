// SPDX-License-Identifier: GPL-3.0-or-later
// Clocks and temperatures (#53) from real tegrastats, jtop and nvidia-smi logs (third-party files: the shared
// folder's tests/data/power/real/, SOURCES there): each value below is read by hand off the named line of the file.
// Skipped without that folder.
#include <QTest>

#include <cmath>

#include "power/power_import.h"
#include "workspace/registry.h"

#include "../../support/find_item.h"
#include "../../support/public_data.h"
#include "../../support/text_lines.h"

using bs::test::any_line_contains;

namespace {

const std::string kReal = bs::test::public_data("tests/data/power/real/");

bs::SustainRun sustain(const std::string& name) {
  bs::ImportBatch b = bs::import_file(kReal + name, bs::CancelToken{});
  if (b.sustain_runs.size() != 1 || b.power_traces.size() != 1)
    throw std::runtime_error(name + ": expected one record");
  if (b.sustain_runs[0].t_s != b.power_traces[0].time_s) throw std::runtime_error(name + ": not the trace's time axis");
  return std::move(b.sustain_runs[0]);
}

const bs::ClockSeries* clock(const bs::SustainRun& r, const std::string& name) {
  return bs::test::find_item(r.clocks, &bs::ClockSeries::name, name);
}

const bs::TemperatureSeries* temperature(const bs::SustainRun& r, const std::string& name) {
  return bs::test::find_item(r.temperatures, &bs::TemperatureSeries::name, name);
}

double hz(const bs::SustainRun& r, const std::string& name, std::size_t sample) {
  return bs::test::item_of(r.clocks, &bs::ClockSeries::name, name, "clock " + name).hz.at(sample);
}

double celsius(const bs::SustainRun& r, const std::string& name, std::size_t sample) {
  return bs::test::item_of(r.temperatures, &bs::TemperatureSeries::name, name, "temperature " + name)
      .celsius.at(sample);
}

}  // namespace

class TestJetsonRealSensors : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() { BENCHSCOPE_REQUIRE_PUBLIC_DATA("tests/data/power/real"); }

  void nano_jetpack4_line_2() {
    // CPU [3%@1479,0%@1479,7%@1479,19%@1479] EMC_FREQ 0%@1600 GR3D_FREQ 0%@76 APE 25 PLL@24.5C CPU@27.5C PMIC@50C
    // GPU@28.5C AO@29C thermal@28C POM_5V_IN 1537/1228 ...
    const auto r = sustain("tegrastats-nano-jetpack4.log");
    QCOMPARE(r.t_s.size(), std::size_t{34});
    QCOMPARE(hz(r, "cpu0", 1), 1479e6);
    QCOMPARE(hz(r, "cpu3", 1), 1479e6);
    QCOMPARE(hz(r, "cpu0", 0), 102e6);  // line 1: CPU [10%@102,...]
    QCOMPARE(hz(r, "EMC", 1), 1600e6);
    QCOMPARE(hz(r, "GR3D", 1), 76e6);
    QCOMPARE(hz(r, "APE", 1), 25e6);
    QCOMPARE(celsius(r, "CPU", 1), 27.5);
    QCOMPARE(celsius(r, "GPU", 1), 28.5);
    QCOMPARE(celsius(r, "PLL", 1), 24.5);
    QVERIFY(!temperature(r, "PMIC"));  // PMIC@50C is a threshold state, not a reading
    QCOMPARE(r.power_w.at(1), 1.537);  // the board total POM_5V_IN, as the trace has it
    QCOMPARE(r.power_sensor, std::string("tegrastats POM_5V_IN"));
    QVERIFY(r.rate.empty() && r.rate_unit.empty() && r.load.empty());
    QVERIFY(!clock(r, "cpu0")->max_hz);  // tegrastats states no maximum
    QCOMPARE(r.interval_s, 1.0);
  }
  void tx2_jetpack3_line_10_and_no_gpu_clock() {
    // CPU [11%@2035,0%@2035,8%@2035,7%@2035,35%@2035,12%@2035] BCPU@35C MCPU@35C GPU@41C PLL@35C AO@32C Tboard@29C
    // Tdiode@31.25C PMIC@100C thermal@34C: no GR3D_FREQ at all in this log.
    const auto r = sustain("tegrastats-tx2-jetpack3.log");
    QCOMPARE(r.clocks.size(), std::size_t{6});
    QCOMPARE(hz(r, "cpu5", 9), 2035e6);
    QCOMPARE(celsius(r, "BCPU", 9), 35.0);
    QCOMPARE(celsius(r, "Tdiode", 9), 31.25);
    QCOMPARE(celsius(r, "thermal", 9), 34.0);
    QCOMPARE(r.temperatures.size(), std::size_t{8});  // BCPU MCPU GPU PLL AO Tboard Tdiode thermal, not PMIC
    QVERIFY(any_line_contains(r.not_exposed, "no GPU clock"));
  }
  void agx_orin_jetpack6_line_3_per_gpc_clock_and_offline_cores() {
    // 07-21-2025 16:33:44 ... CPU [9%@960,66%@960,1%@960,0%@960,3%@729,9%@729,7%@729,2%@729,off,off,off,off]
    // EMC_FREQ 12%@204 GR3D_FREQ 35%@[305,0] ... APE 174 cpu@43.468C soc2@40.562C soc0@41.062C gpu@39.781C
    // tj@43.75C soc1@40.281C VDD_GPU_SOC 2798mW/2798mW VDD_CPU_CV 799mW/799mW VIN_SYS_5V0 3215mW/3248mW
    const auto r = sustain("tegrastats-agx-orin-jetpack6.log");
    QCOMPARE(r.t_s.size(), std::size_t{15});
    QCOMPARE(r.t_s[2], 2.0);
    QCOMPARE(hz(r, "cpu1", 2), 960e6);
    QCOMPARE(hz(r, "cpu7", 2), 729e6);
    QVERIFY(!clock(r, "cpu8"));  // off on every line: no reading, left out and named in the note
    QVERIFY(r.provenance.note.find("cpu8") != std::string::npos);
    QCOMPARE(hz(r, "GR3D GPC0", 2), 305e6);
    QVERIFY(!clock(r, "GR3D GPC1"));  // 0 MHz on every line: a stopped clock, never a throttled one
    QCOMPARE(hz(r, "EMC", 2), 204e6);
    QVERIFY(!clock(r, "NVENC"));  // off throughout
    QCOMPARE(celsius(r, "tj", 2), 43.75);
    QCOMPARE(celsius(r, "gpu", 2), 39.781);
    // No input rail: the trace's total is the sum of the rails, 2798 + 799 + 3215 mW.
    QVERIFY(std::abs(r.power_w.at(2) - 6.812) < 1e-9);
    QCOMPARE(r.power_sensor, std::string("tegrastats sum of rails"));
  }
  void jetpack7_current_temperature_and_load_only_gpu() {
    // cpu@51.968C/51.968C soc2@48.968C/48.968C soc0@49.406C/49.5C gpu@47.125C/47.125C ... GR3D_FREQ 32%
    auto r = sustain("tegrastats-agx-orin-jetpack7.log");
    QCOMPARE(celsius(r, "soc0", 0), 49.406);  // the current value, not the maximum 49.5
    QCOMPARE(celsius(r, "gpu", 0), 47.125);
    QCOMPARE(hz(r, "cpu8", 0), 1113e6);
    QVERIFY(any_line_contains(r.not_exposed, "GR3D_FREQ as a load only"));
    // Thor: CPU [12%@972,10%@972,off,33%@1890] cpu@39.812C tj@39.906C soc012@38.812C
    r = sustain("tegrastats-thor-jetpack7.log");
    QCOMPARE(hz(r, "cpu3", 0), 1890e6);
    QVERIFY(!clock(r, "cpu2"));
    QCOMPARE(celsius(r, "soc012", 0), 38.812);
    QCOMPARE(r.power_sensor, std::string("tegrastats VIN"));
  }
  void xavier_and_orin_nx_lines() {
    // Xavier NX JetPack 5, line 5: CPU [100%@1189,97%@1189,100%@1190,100%@1190,off,off] ... GPU@38C PMIC@50C
    auto r = sustain("tegrastats-xavier-nx-jetpack5.log");
    QCOMPARE(hz(r, "cpu2", 4), 1190e6);
    QCOMPARE(celsius(r, "GPU", 4), 38.0);
    QCOMPARE(celsius(r, "AUX", 4), 36.5);
    // Orin NX JetPack 5: VIC_FREQ 729 APE 174 CV0@45.812C CPU@47.937C ... tj@48.875C
    r = sustain("tegrastats-orin-nx-jetpack5.log");
    QCOMPARE(hz(r, "VIC", 0), 729e6);
    QCOMPARE(hz(r, "GR3D", 0), 611e6);
    QCOMPARE(celsius(r, "CV0", 0), 45.812);
    QCOMPARE(celsius(r, "tj", 0), 48.875);
    // TX1, AGX Xavier JetPack 4 and AGX Orin 32GB (runs of spaces): one line each.
    r = sustain("tegrastats-tx1-jetpack3.log");
    QCOMPARE(celsius(r, "Tdiode", 0), 42.75);
    QCOMPARE(hz(r, "EMC", 0), 408e6);
    r = sustain("tegrastats-agx-xavier-jetpack4.log");
    QCOMPARE(hz(r, "GR3D", 0), 318e6);
    QCOMPARE(celsius(r, "Tboard", 0), 37.0);
    r = sustain("tegrastats-agx-orin-32gb-jetpack6.log");
    QCOMPARE(hz(r, "cpu4", 0), 2201e6);
    QCOMPARE(hz(r, "GR3D GPC1", 0), 305e6);
    QCOMPARE(celsius(r, "cpu", 0), 53.062);
  }
  void jtop_temperatures_and_engine_clocks() {
    // jetson-stats 4: ... Temp cpu 44.656, Temp cv0/cv1/cv2 -256 (no sensor), Temp gpu 43.718, Temp tj 44.656;
    // every engine OFF.
    auto r = sustain("jtop-orin-nano-jetson-stats-4.csv");
    QCOMPARE(celsius(r, "cpu", 0), 44.656);
    QCOMPARE(celsius(r, "gpu", 0), 43.718);
    QCOMPARE(celsius(r, "soc2", 0), 43.5);
    QVERIFY(!temperature(r, "cv0"));  // -256 throughout: no sensor, left out
    QVERIFY(r.clocks.empty());
    QVERIFY(any_line_contains(r.not_exposed, "no CPU or GPU clock"));
    QCOMPARE(r.power_w.at(0), 3.852);  // Power TOT 3852 mW
    // jetson-stats 3.0: APE 150 (MHz, copied from tegrastats), Temp CPU 46.0, Temp Tdiode 49.25.
    r = sustain("jtop-agx-xavier-jetson-stats-3.csv");
    QCOMPARE(hz(r, "APE", 0), 150e6);
    QVERIFY(!clock(r, "NVENC"));
    QCOMPARE(celsius(r, "CPU", 0), 46.0);
    QCOMPARE(celsius(r, "Tdiode", 0), 49.25);
    QCOMPARE(celsius(r, "thermal", 0), 45.4);
  }
  void nvidia_smi_gpu_temperature() {
    // GTX 1650: temperature.gpu 50 on all 12 rows, no clocks queried.
    const auto r = sustain("nvidia-smi-fletcher-gtx1650.csv");
    QCOMPARE(celsius(r, "GPU", 11), 50.0);
    QVERIFY(r.clocks.empty());
    QVERIFY(any_line_contains(r.not_exposed, "no SM clock"));
    QCOMPARE(r.power_w.at(9), 19.89);
    QCOMPARE(r.provenance.gpu_model, std::string("NVIDIA GeForce GTX 1650"));
    // Power only: no record (it would say nothing the trace does not).
    const auto b = bs::import_file(kReal + "nvidia-smi-flame-2col.csv", bs::CancelToken{});
    QVERIFY(b.sustain_runs.empty());
  }
};

QTEST_APPLESS_MAIN(TestJetsonRealSensors)
#include "test_jetson_real_sensors.moc"
