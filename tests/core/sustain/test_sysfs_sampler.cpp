// SPDX-License-Identifier: GPL-3.0-or-later
// The sustained run's sysfs sampler (#53) on fixture trees written into a temporary folder: CPU clocks (kHz) and
// devfreq clocks (Hz) against their maxima, thermal zones with their lowest passive/hot/critical trip point, hwmon
// temperatures with their labels; values that change between samples are read anew; junk, huge and empty values
// are NaN with a warning naming the file, never a crash; what is missing is said in words.
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "../../support/text_lines.h"
#include "sustain/sysfs_sampler.h"

using bs::test::any_line_contains;
using namespace bs::sustain;
namespace fs = std::filesystem;

namespace {

void put(const fs::path& file, const std::string& text) {
  fs::create_directories(file.parent_path());
  std::ofstream(file) << text;
}

// A machine with two CPUs (3.0 GHz maximum), a GPU devfreq node, one thermal zone and one hwmon sensor, its sysfs
// under `dir`: the root to sample.
fs::path machine_in(const QTemporaryDir& dir) {
  const fs::path root = dir.path().toStdString();
  for (int c = 0; c < 2; ++c) {
    const fs::path cpu = root / "sys/devices/system/cpu" / ("cpu" + std::to_string(c)) / "cpufreq";
    put(cpu / "scaling_cur_freq", "3000000\n");
    put(cpu / "cpuinfo_max_freq", "3000000\n");
  }
  put(root / "sys/devices/system/cpu/cpufreq/policy0/scaling_cur_freq", "1");  // not a cpuN: ignored
  put(root / "sys/class/devfreq/17000000.gv11b/cur_freq", "1300500000\n");
  put(root / "sys/class/devfreq/17000000.gv11b/max_freq", "1300500000\n");
  const fs::path zone = root / "sys/class/thermal/thermal_zone0";
  put(zone / "type", "x86_pkg_temp\n");
  put(zone / "temp", "61000\n");
  put(zone / "trip_point_0_type", "active\n");  // a fan's trip: not a throttling limit
  put(zone / "trip_point_0_temp", "50000\n");
  put(zone / "trip_point_1_type", "critical\n");
  put(zone / "trip_point_1_temp", "105000\n");
  put(zone / "trip_point_2_type", "passive\n");
  put(zone / "trip_point_2_temp", "95000\n");
  put(root / "sys/class/thermal/cooling_device0/type", "Processor\n");  // not a zone
  const fs::path hw = root / "sys/class/hwmon/hwmon3";
  put(hw / "name", "coretemp\n");
  put(hw / "temp1_input", "62000\n");
  put(hw / "temp1_label", "Package id 0\n");
  put(hw / "temp2_input", "58000\n");  // no label: named by its attribute
  return root;
}

}  // namespace

class TestSysfsSampler : public QObject {
  Q_OBJECT
 private slots:
  void finds_every_source_with_its_limit() {
    QTemporaryDir dir;
    const fs::path root = machine_in(dir);
    const SysfsSampler s(root);
    QCOMPARE(s.clocks().size(), std::size_t{3});
    QCOMPARE(s.clocks()[0].name, std::string("cpu0"));
    QCOMPARE(*s.clocks()[0].max_hz, 3.0e9);
    QCOMPARE(s.clocks()[2].name, std::string("devfreq 17000000.gv11b"));
    QCOMPARE(*s.clocks()[2].max_hz, 1.3005e9);
    QCOMPARE(s.temperatures().size(), std::size_t{3});
    QCOMPARE(s.temperatures()[0].name, std::string("thermal_zone0 x86_pkg_temp"));
    QCOMPARE(*s.temperatures()[0].trip_c, 95.0);  // the lowest passive/hot/critical, not the fan's 50
    QCOMPARE(s.temperatures()[1].name, std::string("hwmon coretemp Package id 0"));
    QVERIFY(!s.temperatures()[1].trip_c);
    QCOMPARE(s.temperatures()[2].name, std::string("hwmon coretemp temp2"));
    QVERIFY(s.not_exposed().empty());
    QVERIFY(s.discovery_warnings().empty());

    const SysfsSample a = s.sample();
    QCOMPARE(a.clock_hz, (std::vector<double>{3.0e9, 3.0e9, 1.3005e9}));
    QCOMPARE(a.temperature_c, (std::vector<double>{61.0, 62.0, 58.0}));
    QVERIFY(a.warnings.empty());
  }

  void reads_values_anew_each_sample() {
    QTemporaryDir dir;
    const fs::path root = machine_in(dir);
    const SysfsSampler s(root);
    put(root / "sys/devices/system/cpu/cpu1/cpufreq/scaling_cur_freq", "1800000\n");
    put(root / "sys/class/thermal/thermal_zone0/temp", "97000\n");
    const SysfsSample a = s.sample();
    QCOMPARE(a.clock_hz[1], 1.8e9);
    QCOMPARE(a.temperature_c[0], 97.0);
  }

  void bad_values_are_nan_with_a_warning() {
    QTemporaryDir dir;
    const fs::path root = machine_in(dir);
    const SysfsSampler s(root);
    put(root / "sys/devices/system/cpu/cpu0/cpufreq/scaling_cur_freq", "garbage\n");
    put(root / "sys/devices/system/cpu/cpu1/cpufreq/scaling_cur_freq", "999999999999999999999999999\n");
    put(root / "sys/class/devfreq/17000000.gv11b/cur_freq", "");
    put(root / "sys/class/thermal/thermal_zone0/temp", "900000000\n");  // 900,000 °C: a misread
    fs::remove(root / "sys/class/hwmon/hwmon3/temp1_input");
    const SysfsSample a = s.sample();
    QVERIFY(std::isnan(a.clock_hz[0]));
    QVERIFY(std::isnan(a.clock_hz[1]));
    QVERIFY(std::isnan(a.clock_hz[2]));
    QVERIFY(std::isnan(a.temperature_c[0]));
    QVERIFY(std::isnan(a.temperature_c[1]));
    QCOMPARE(a.temperature_c[2], 58.0);
    QCOMPARE(a.warnings.size(), std::size_t{5});
    QVERIFY(
        any_line_contains(a.warnings, "cpu0: /sys/devices/system/cpu/cpu0/cpufreq/scaling_cur_freq: 'garbage' is not"));
    QVERIFY(any_line_contains(a.warnings, "cpu1: /sys/devices/system/cpu/cpu1/cpufreq/scaling_cur_freq: '9999"));
    QVERIFY(any_line_contains(a.warnings, "cur_freq: empty (NaN this interval)"));
    QVERIFY(any_line_contains(a.warnings, "900000000 is not a plausible temperature"));
    QVERIFY(any_line_contains(a.warnings, "temp1_input: No such file"));
  }

  void bad_limits_are_left_out_with_a_warning() {
    QTemporaryDir dir;
    const fs::path root = machine_in(dir);
    put(root / "sys/devices/system/cpu/cpu0/cpufreq/cpuinfo_max_freq", "-5\n");
    put(root / "sys/class/thermal/thermal_zone0/trip_point_2_temp", "hot\n");
    const SysfsSampler s(root);
    QVERIFY(!s.clocks()[0].max_hz);
    QCOMPARE(*s.temperatures()[0].trip_c, 105.0);  // the passive trip was junk: the critical one remains
    QCOMPARE(s.discovery_warnings().size(), std::size_t{2});
    QVERIFY(
        any_line_contains(s.discovery_warnings(), "cpu0: /sys/devices/system/cpu/cpu0/cpufreq/cpuinfo_max_freq: -5"));
    QVERIFY(any_line_contains(s.discovery_warnings(), "trip point left out"));
  }

  void what_is_missing_is_said() {
    QTemporaryDir dir;
    const SysfsSampler s(dir.path().toStdString());
    QVERIFY(s.clocks().empty());
    QVERIFY(s.temperatures().empty());
    QCOMPARE(s.not_exposed().size(), std::size_t{4});
    QVERIFY(any_line_contains(s.not_exposed(), "no cpufreq under /sys/devices/system/cpu: no CPU clock"));
    QVERIFY(any_line_contains(s.not_exposed(), "no devfreq device"));
    QVERIFY(any_line_contains(s.not_exposed(), "no thermal zone under /sys/class/thermal"));
    QVERIFY(any_line_contains(s.not_exposed(), "no hwmon temperature"));
    const SysfsSample a = s.sample();
    QVERIFY(a.clock_hz.empty() && a.temperature_c.empty() && a.warnings.empty());
  }
};

QTEST_APPLESS_MAIN(TestSysfsSampler)
#include "test_sysfs_sampler.moc"
