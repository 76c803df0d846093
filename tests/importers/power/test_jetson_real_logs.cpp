// SPDX-License-Identifier: GPL-3.0-or-later
// Real tegrastats logs and jtop records from nine Jetson boards and JetPack 3 to 7 (third-party files: the shared
// folder's tests/data/power/real/, SOURCES there): the board total each one must give, checked by hand from the
// file's own numbers (mW in the file, W here). Skipped without that folder.
#include <QTest>

#include <cmath>

#include "analysis/power/power.h"
#include "power/power_import.h"
#include "workspace/registry.h"

#include "../../support/find_item.h"
#include "../../support/public_data.h"
#include "../../support/text_lines.h"

using bs::test::any_line_contains;

namespace {

const std::string kReal = bs::test::public_data("tests/data/power/real/");

bs::ImportBatch load(const std::string& name) {
  bs::ImportBatch b = bs::import_file(kReal + name, bs::CancelToken{});
  if (b.power_traces.size() != 1) throw std::runtime_error(name + ": expected one trace");
  return b;
}

const bs::PowerChannel& channel(const bs::PowerTrace& t, const std::string& name) {
  return bs::test::item_of(t.channels, &bs::PowerChannel::name, name, "channel " + name);
}

double mean(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x;
  return s / static_cast<double>(v.size());
}

}  // namespace

class TestJetsonRealLogs : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() { BENCHSCOPE_REQUIRE_PUBLIC_DATA("tests/data/power/real"); }

  void nano_jetpack4_total_is_pom_5v_in() {
    const auto b = load("tegrastats-nano-jetpack4.log");
    QCOMPARE(b.format, std::string("tegrastats"));
    const bs::PowerTrace& t = b.power_traces[0];
    QCOMPARE(t.total_channel, std::string("POM_5V_IN"));
    QCOMPARE(t.channels.size(), std::size_t{3});
    const auto p = bs::power_series(t);
    QCOMPARE(p.size(), std::size_t{34});
    QCOMPARE(p[0], 0.920);   // line 1: POM_5V_IN 920/920
    QCOMPARE(p[28], 5.143);  // line 29, GPU at 99 %: POM_5V_IN 5143/2615 (not the running average 2615)
    // Not POM_5V_IN + POM_5V_GPU + POM_5V_CPU (5143 + 2949 + 179 = 8271 mW): GPU and CPU are parts of the input.
    QCOMPARE(channel(t, "POM_5V_GPU").values[28], 2.949);
    QCOMPARE(t.time_s[28], 28.0);  // no timestamps: line n at (n - 1) s, tegrastats' default interval
    QVERIFY(any_line_contains(b.warnings, "no timestamps in the log: times assume one line every 1 s"));
    QCOMPARE(t.provenance.measurement, bs::MeasurementKind::OnBoardSensor);
    QCOMPARE(t.provenance.sensor, std::string("INA3221 (tegrastats)"));
  }
  void tx1_and_tx2_jetpack3_total_is_vdd_in() {
    auto b = load("tegrastats-tx1-jetpack3.log");
    QCOMPARE(bs::power_series(b.power_traces[0]).at(0), 2.532);  // VDD_IN 2532/2698, not + VDD_CPU 76 + VDD_GPU 19
    b = load("tegrastats-tx2-jetpack3.log");
    const bs::PowerTrace& t = b.power_traces[0];
    QCOMPARE(t.total_channel, std::string("VDD_IN"));
    QCOMPARE(t.channels.size(), std::size_t{6});  // VDD_IN, VDD_CPU, VDD_GPU, VDD_SOC, VDD_WIFI, VDD_DDR
    QCOMPARE(bs::power_series(t).at(18), 3.987);  // line 19: VDD_IN 3987/3645 while VDD_WIFI reads 345
    QCOMPARE(channel(t, "VDD_WIFI").values[18], 0.345);
  }
  void xavier_nx_total_is_vdd_in_on_jetpack4_and_5() {
    auto b = load("tegrastats-xavier-nx-jetpack4.log");
    QCOMPARE(bs::power_series(b.power_traces[0]).at(0), 4.067);  // VDD_IN 4067; the rails 738 + 1353 are its parts
    b = load("tegrastats-xavier-nx-jetpack5.log");
    const bs::PowerTrace& t = b.power_traces[0];
    QCOMPARE(t.total_channel, std::string("VDD_IN"));
    const auto p = bs::power_series(t);
    QCOMPARE(p.size(), std::size_t{24});
    QCOMPARE(p[0], 5.542);         // 20:05:55 VDD_IN 5542mW/5542mW (CPU burn)
    QCOMPARE(p[11], 9.315);        // 20:06:06 VDD_IN 9315mW/5909mW (GPU burn starts)
    QCOMPARE(p[23], 13.711);       // 20:06:19 VDD_IN 13711mW/9773mW
    QCOMPARE(t.time_s[16], 17.0);  // 20:06:12 - 20:05:55: the log's clock, which skipped 20:06:11
    QCOMPARE(t.start_time, std::string("2025-10-01T20:05:55"));
    QVERIFY(b.warnings.empty());  // an input rail and timestamps: nothing to assume
  }
  void orin_nx_jetpack5_total_is_vdd_in() {
    const auto b = load("tegrastats-orin-nx-jetpack5.log");
    QCOMPARE(bs::power_series(b.power_traces[0]).at(0), 5.299);  // VDD_IN 5299mW/5299mW
  }
  void agx_xavier_total_is_the_sum_of_its_rails() {
    const auto b = load("tegrastats-agx-xavier-jetpack4.log");
    const bs::PowerTrace& t = b.power_traces[0];
    QCOMPARE(t.total_channel, std::string("sum of rails"));
    // GPU 0 + CPU 311 + SOC 932 + CV 0 + VDDRQ 621 + SYS5V 1482 = 3346 mW. Before: the GPU rail alone (0 W here).
    QCOMPARE(bs::power_series(t).at(0), 3.346);
    QCOMPARE(t.channels.size(), std::size_t{7});
    QVERIFY(any_line_contains(b.warnings, "no board input rail"));
    QVERIFY(t.provenance.note.find("lower bound") != std::string::npos);
  }
  void agx_orin_total_is_the_sum_of_its_rails() {
    auto b = load("tegrastats-agx-orin-jetpack6.log");
    const bs::PowerTrace& t = b.power_traces[0];
    QCOMPARE(t.total_channel, std::string("sum of rails"));
    const auto p = bs::power_series(t);
    QCOMPARE(p.size(), std::size_t{15});
    QCOMPARE(p[0], 6.912);   // 16:33:42: VDD_GPU_SOC 2798 + VDD_CPU_CV 799 + VIN_SYS_5V0 3315 = 6912 mW
    QCOMPARE(p[11], 5.510);  // 16:33:54: 2399 + 399 + 2712 = 5510 mW
    // Per line: 6912 6811 6812 6711 6812 6812 6711 6711 6711 6711 6311 5510 5510 5611 5611, sum 96267 mW over
    // 15 lines: mean 6417.8 mW. VIN_SYS_5V0 alone (what was reported before) averages about 3.1 W.
    QVERIFY(std::abs(mean(p) - 6.4178) < 1e-9);
    QCOMPARE(t.time_s.back(), 15.0);  // 16:33:42 to 16:33:57
    QCOMPARE(channel(t, "VIN_SYS_5V0").values[0], 3.315);
    // AGX Orin 32GB, JetPack 6, with runs of spaces between fields: 3205 + 4405 + 4767 = 12377 mW.
    b = load("tegrastats-agx-orin-32gb-jetpack6.log");
    QCOMPARE(bs::power_series(b.power_traces[0]).at(0), 12.377);
  }
  void jetpack7_cur_avg_max() {
    // AGX Orin on JetPack 7.2 prints cur/avg/max: the instantaneous values 4385 + 1196 + 5552 = 11133 mW (the
    // averages would give 3787 + 897 + 5274 = 9958, the maxima the same 11133 by chance of this line).
    auto b = load("tegrastats-agx-orin-jetpack7.log");
    const bs::PowerTrace& t = b.power_traces[0];
    QCOMPARE(t.total_channel, std::string("sum of rails"));
    QCOMPARE(bs::power_series(t).at(0), 11.133);
    QCOMPARE(channel(t, "VDD_CPU_CV").values[0], 1.196);
    // AGX Thor: VIN is the board input (26686 mW); the module rails 3561 + 7910 + 7620 = 19091 mW are less.
    b = load("tegrastats-thor-jetpack7.log");
    const bs::PowerTrace& thor = b.power_traces[0];
    QCOMPARE(thor.total_channel, std::string("VIN"));
    QCOMPARE(bs::power_series(thor).at(0), 26.686);
    QCOMPARE(thor.channels.size(), std::size_t{4});
    QVERIFY(!any_line_contains(b.warnings, "no board input rail"));
  }
  void jtop_orin_nano_total_is_power_tot() {
    const auto b = load("jtop-orin-nano-jetson-stats-4.csv");
    QCOMPARE(b.format, std::string("jtop-csv"));
    const bs::PowerTrace& t = b.power_traces[0];
    QCOMPARE(t.total_channel, std::string("Power TOT"));
    // Power TOT 3852 mW; the rails 881 + 1121 = 2002 mW are parts of it (adding them would give 5854 mW).
    QCOMPARE(bs::power_series(t).at(0), 3.852);
    QCOMPARE(channel(t, "Power VDD_CPU_GPU_CV").values[0], 0.881);
    QCOMPARE(channel(t, "Power VDD_SOC").values[0], 1.121);
    QCOMPARE(t.channels.size(), std::size_t{3});
    QCOMPARE(t.start_time, std::string("2025-12-16T17:14:33.703"));
    const std::vector<std::pair<std::string, std::string>> settings{{"jetson_clocks", "OFF"}, {"nvp model", "15W"}};
    QCOMPARE(t.provenance.settings, settings);
    QCOMPARE(t.provenance.measurement, bs::MeasurementKind::OnBoardSensor);
    QVERIFY(b.warnings.empty());
  }
  void jtop_agx_xavier_jetson_stats_3_total_is_power_cur() {
    const auto b = load("jtop-agx-xavier-jetson-stats-3.csv");
    QCOMPARE(b.format, std::string("jtop-csv"));
    const bs::PowerTrace& t = b.power_traces[0];
    QCOMPARE(t.total_channel, std::string("power cur"));
    QCOMPARE(t.channels.size(), std::size_t{1});  // "power avg" is jtop's running average, not a sample
    QCOMPARE(bs::power_series(t).at(0), 4.859);
    const std::vector<std::pair<std::string, std::string>> settings{{"jetson_clocks", "OFF"}, {"nvp model", "MAXN"}};
    QCOMPARE(t.provenance.settings, settings);
  }
  void power_log_entry_point_picks_jtop_over_power_csv() {
    const auto b = bs::import_power_log(kReal + "jtop-orin-nano-jetson-stats-4.csv");
    QCOMPARE(b.format, std::string("jtop-csv"));
  }
};

QTEST_APPLESS_MAIN(TestJetsonRealLogs)
#include "test_jetson_real_logs.moc"
