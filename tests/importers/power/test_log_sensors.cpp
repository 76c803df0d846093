// SPDX-License-Identifier: GPL-3.0-or-later
// Clocks and temperatures beside the power of a log (#53), on project fixtures and small texts: offline cores,
// tegrastats' -256C and PMIC, garbage tokens, a last line cut without its line ending, JetPack 3's shared CPU clock,
// jtop and nvidia-smi sensor columns, bad cells (warnings naming file, line and field, never a crash).
#include <QTest>

#include <cmath>

#include "power/jtop_csv.h"
#include "power/nvidia_smi.h"
#include "power/power_import.h"
#include "power/tegrastats.h"
#include "workspace/registry.h"

#include "../../support/find_item.h"
#include "../../support/import_errors.h"

namespace {

const std::string kData = BENCHSCOPE_TEST_DATA_DIR "/power/";

const bs::ClockSeries& clock(const bs::SustainRun& r, const std::string& name) {
  return bs::test::item_of(r.clocks, &bs::ClockSeries::name, name, "clock " + name);
}

const bs::TemperatureSeries& temperature(const bs::SustainRun& r, const std::string& name) {
  return bs::test::item_of(r.temperatures, &bs::TemperatureSeries::name, name, "temperature " + name);
}

bool has_clock(const bs::SustainRun& r, const std::string& name) {
  return bs::test::find_item(r.clocks, &bs::ClockSeries::name, name) != nullptr;
}

std::size_t warnings_with(const bs::ImportBatch& b, const std::string& text) {
  std::size_t n = 0;
  for (const auto& w : b.warnings) n += w.find(text) != std::string::npos;
  return n;
}

// NaN-aware equality of a series with the expected values.
bool same(const std::vector<double>& got, const std::vector<double>& want) {
  if (got.size() != want.size()) return false;
  for (std::size_t i = 0; i < got.size(); ++i)
    if (std::isnan(want[i]) ? !std::isnan(got[i]) : got[i] != want[i]) return false;
  return true;
}

const double kNaN = std::nan("");

}  // namespace

class TestLogSensors : public QObject {
  Q_OBJECT
 private slots:
  void tegrastats_edges_fixture() {
    const auto b = bs::import_file(kData + "tegrastats-sensors-edges.log", bs::CancelToken{});
    QCOMPARE(b.sustain_runs.size(), std::size_t{1});
    const bs::SustainRun& r = b.sustain_runs[0];
    QCOMPARE(r.t_s, (std::vector<double>{0, 1, 2}));
    QCOMPARE(r.power_w, (std::vector<double>{5.0, 9.0, 9.5}));
    QCOMPARE(r.power_sensor, std::string("tegrastats VDD_IN"));
    QCOMPARE(r.label, std::string("tegrastats-sensors-edges.log"));
    QCOMPARE(r.provenance.tool, std::string("tegrastats"));
    // Cores: "off" is NaN, never 0 Hz; cores off on every line are left out and named.
    QVERIFY(same(clock(r, "cpu0").hz, {729e6, 2201e6, 1420e6}));
    QVERIFY(same(clock(r, "cpu1").hz, {729e6, 2201e6, kNaN}));
    QVERIFY(!has_clock(r, "cpu2") && !has_clock(r, "cpu3"));
    QVERIFY(r.provenance.note.find("cpu2, cpu3") != std::string::npos);
    // GR3D per GPC; 0 MHz is a stopped clock (NaN), so GPC1 (0 throughout) is left out.
    QVERIFY(same(clock(r, "GR3D GPC0").hz, {kNaN, 1300e6, 1100e6}));
    QVERIFY(!has_clock(r, "GR3D GPC1"));
    QVERIFY(same(clock(r, "NVENC").hz, {kNaN, 1190e6, kNaN}));
    QVERIFY(same(clock(r, "VIC").hz, {729e6, 729e6, 729e6}));
    QVERIFY(same(clock(r, "EMC").hz, {2133e6, 2133e6, 2133e6}));
    // -256C is "no reading"; CPU@abcC is a warning naming file:line:column and the sensor; PMIC is not imported.
    QVERIFY(same(temperature(r, "GPU").celsius, {kNaN, 52.5, 58.0}));
    QVERIFY(same(temperature(r, "CPU").celsius, {47.968, kNaN, 60.5}));
    QVERIFY(same(temperature(r, "tj").celsius, {47.968, 53.0, 61.25}));
    QCOMPARE(r.temperatures.size(), std::size_t{3});
    QCOMPARE(warnings_with(b, "tegrastats-sensors-edges.log:2:157: CPU: 'CPU@abcC' is not a temperature"),
             std::size_t{1});
    QVERIFY(r.provenance.note.find("-256 C") != std::string::npos);
    QVERIFY(r.provenance.note.find("PMIC") != std::string::npos);
    // The last line has no line ending: imported, with the power importers' warning naming it.
    QCOMPARE(warnings_with(b, "tegrastats-sensors-edges.log:3: the last line has no line ending"), std::size_t{1});
    QVERIFY(r.not_exposed.empty());
  }
  void tegrastats_jetpack3_shared_cpu_clock_and_garbage() {
    const auto b = bs::kTegrastatsFileFormat.parse_text(
        "RAM 1/2MB CPU [12%,off,3%]@1734 GR3D_FREQ 5%@x EMC_FREQ 1%@99999999 AO@1e9C VDD_IN 3981/3981\n"
        "RAM 1/2MB CPU [12%@abc,off,3%@204 GR3D_FREQ 7%@76 AO@40C VDD_IN 3000/3500\n"
        "RAM 1/2MB CPU [1%@abc,off] AO@41C VDD_IN 3000/3500\n",
        "t.log");
    const bs::SustainRun& r = b.sustain_runs.at(0);
    QVERIFY(same(clock(r, "cpu0").hz, {1734e6, kNaN, kNaN}));
    QVERIFY(same(clock(r, "cpu2").hz, {1734e6, kNaN, kNaN}));
    QVERIFY(same(clock(r, "GR3D").hz, {kNaN, 76e6, kNaN}));
    QVERIFY(same(temperature(r, "AO").celsius, {kNaN, 40.0, 41.0}));
    QCOMPARE(warnings_with(b, "t.log:1:"), std::size_t{3});  // GR3D_FREQ 5%@x, EMC 99999999 MHz, AO@1e9C
    QCOMPARE(warnings_with(b, "t.log:1:43: GR3D_FREQ: '5%@x' is not a load and clock"), std::size_t{1});
    QCOMPARE(warnings_with(b, "t.log:2:15: CPU: '[12%@abc,off,3%@204' has no closing ']'"), std::size_t{1});
    QCOMPARE(warnings_with(b, "t.log:3:"), std::size_t{0});  // the last line: a cut token there is expected
  }
  void tegrastats_many_bad_tokens_are_counted_not_listed() {
    std::string text;
    for (int i = 0; i < 30; ++i) text += "RAM 1/2MB CPU@zzC VDD_IN 3981/3981\n";
    const auto b = bs::kTegrastatsFileFormat.parse_text(text, "t.log");
    QCOMPARE(warnings_with(b, "is not a temperature"), std::size_t{10});
    QCOMPARE(warnings_with(b, "19 more clock or temperature tokens"), std::size_t{1});  // line 30 is the last
    QVERIFY(b.sustain_runs.empty());  // CPU never read: nothing but power
  }
  void jtop_sensor_cells() {
    const auto b = bs::kJtopCsvFileFormat.parse_text(
        "time,CPU1,GPU,APE,NVDEC,Temp cpu,Temp gpu,Temp PMIC,Power TOT\n"
        "2025-01-01 00:00:00,5,10,OFF,115200,40.5,-256,100,5000\n"
        "2025-01-01 00:00:01,5,10,OFF,OFF,hot,39.0,100,5100\n",
        "j.csv");
    const bs::SustainRun& r = b.sustain_runs.at(0);
    QVERIFY(same(clock(r, "NVDEC").hz, {115.2e6, kNaN}));  // kHz since jetson-stats 4.2
    QVERIFY(!has_clock(r, "APE") && !has_clock(r, "CPU1") && !has_clock(r, "GPU"));
    QVERIFY(same(temperature(r, "cpu").celsius, {40.5, kNaN}));
    QVERIFY(same(temperature(r, "gpu").celsius, {kNaN, 39.0}));
    QCOMPARE(r.temperatures.size(), std::size_t{2});  // no PMIC
    QCOMPARE(warnings_with(b, "j.csv:3:"), std::size_t{1});
    QCOMPARE(warnings_with(b, "Temp cpu: 'hot' is not a temperature"), std::size_t{1});
    QCOMPARE(r.power_w, (std::vector<double>{5.0, 5.1}));
  }
  void nvidia_smi_clocks_with_their_maximum_and_throttle_reasons() {
    const auto b = bs::kNvidiaSmiFileFormat.parse_text(
        "timestamp, name, power.draw [W], clocks.sm [MHz], clocks.max.sm [MHz], clocks.mem [MHz], temperature.gpu, "
        "clocks_throttle_reasons.sw_thermal_slowdown, clocks_throttle_reasons.active\n"
        "2024/01/01 00:00:00.000, NVIDIA A2, 50.00 W, 1770 MHz, 1770 MHz, 6251 MHz, 60, Not Active, "
        "0x0000000000000001\n"
        "2024/01/01 00:00:01.000, NVIDIA A2, 60.00 W, 1410 MHz, 1770 MHz, [N/A], 85, Active, 0x0000000000000020\n"
        "2024/01/01 00:00:02.000, NVIDIA A2, 60.00 W, fast, 1770 MHz, 6251 MHz, 86, Active, 0x0000000000000020\n",
        "smi.csv");
    const bs::SustainRun& r = b.sustain_runs.at(0);
    QVERIFY(same(clock(r, "SM").hz, {1770e6, 1410e6, kNaN}));
    QCOMPARE(clock(r, "SM").max_hz, std::optional<double>(1770e6));
    QVERIFY(same(clock(r, "memory").hz, {6251e6, kNaN, 6251e6}));
    QVERIFY(!clock(r, "memory").max_hz);
    QVERIFY(same(temperature(r, "GPU").celsius, {60.0, 85.0, 86.0}));
    QVERIFY(r.provenance.note.find("sw_thermal_slowdown active in 2 of 3 samples, first at 1 s") != std::string::npos);
    QVERIFY(r.provenance.note.find("clocks_throttle_reasons.active active in 2 of 3") != std::string::npos);
    QCOMPARE(warnings_with(b, "smi.csv:4: clocks.sm: 'fast' is not a clock in MHz"), std::size_t{1});
    QCOMPARE(r.power_w, (std::vector<double>{50.0, 60.0, 60.0}));
    QVERIFY(r.not_exposed.empty());
    // A clock in another unit is refused, like a power in another unit.
    const bs::ImportError e = bs::test::import_error_of(
        [] { return bs::kNvidiaSmiFileFormat.parse_text("timestamp, power.draw [W], clocks.sm [GHz]\n", "u.csv"); });
    QCOMPARE(e.category(), bs::ImportErrorCategory::Unsupported);
    QCOMPARE(e.location().file, std::string("u.csv"));
    QCOMPARE(e.location().line, std::size_t{1});
    QCOMPARE(e.location().field, std::string("clocks.sm"));
    QVERIFY(e.reason().find("unit 'GHz'") != std::string::npos);
  }
};

QTEST_APPLESS_MAIN(TestLogSensors)
#include "test_log_sensors.moc"
