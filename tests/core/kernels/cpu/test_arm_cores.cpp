// SPDX-License-Identifier: GPL-3.0-or-later
// ARM CPUs by name (issue #30.3): real /proc/cpuinfo and device-tree model files of a Jetson TX2, AGX Xavier, AGX
// Orin, Raspberry Pi 4 and 5 (third-party: the shared folder's tests/data/platform/arm, SOURCES.md there; the board
// functions skip without it), the core table and the per-cluster peaks.
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "analysis/peaks/device_table.h"
#include "kernels/cpu/arm_cores.h"

#include "../../../support/near.h"
#include "../../../support/public_data.h"

namespace fs = std::filesystem;
using bs::test::near;
using namespace bs::kernels;

namespace {

constexpr const char* kBoardsFolder = "tests/data/platform/arm";
const fs::path kBoards = bs::test::public_data(kBoardsFolder);

ArmCpu board(const char* name, const fs::path& sysfs_root = "/nonexistent") {
  const auto cpu = detect_arm_cpu(kBoards / name, sysfs_root);
  if (!cpu) qFatal("%s: not described as ARM", name);
  return *cpu;
}

}  // namespace

class TestArmCores : public QObject {
  Q_OBJECT
 private slots:
  void core_table_names_every_required_core_with_its_source() {
    const ArmCoreTable& t = bundled_arm_core_table();
    const struct {
      std::uint32_t impl, part;
      const char* name;
      double flop_per_cycle;
    } want[] = {{0x41, 0xd07, "Cortex-A57", 8},    {0x4e, 0x003, "Denver 2", 16},  {0x4e, 0x004, "Carmel", 16},
                {0x41, 0xd42, "Cortex-A78AE", 16}, {0x41, 0xd08, "Cortex-A72", 8}, {0x41, 0xd0b, "Cortex-A76", 16}};
    for (const auto& w : want) {
      const ArmCoreType* c = find_arm_core(t, w.impl, w.part);
      QVERIFY2(c, w.name);
      QCOMPARE(QString::fromStdString(c->name), QString(w.name));
      QCOMPARE(c->fp32_lanes, 4);  // 128-bit NEON
      QCOMPARE(c->fp32_flop_per_cycle(), w.flop_per_cycle);
      QVERIFY(c->source_url.starts_with("https://"));
      QVERIFY(!c->source_title.empty());
    }
  }

  // The device table's per-core figures (its peak terms) and the core table agree for every board entry.
  void device_table_terms_agree_with_core_table() {
    const bs::BundledDeviceTable& b = bs::bundled_device_table();
    QVERIFY2(b.error.empty(), b.error.c_str());
    int checked = 0;
    for (const ArmCoreType& c : bundled_arm_core_table().cores)
      for (const bs::DeviceSpec& s : b.table.devices)
        for (const bs::PeakTerm& t : s.peak_terms)
          if (t.unit == c.name + " cores") {
            QVERIFY2(t.flop_per_unit_per_cycle == c.fp32_flop_per_cycle(), (s.id + " / " + c.name).c_str());
            ++checked;
          }
    QVERIFY(checked >= 6);
  }

  void tx2_is_two_clusters_with_a_peak_each_and_the_sum() {
    BENCHSCOPE_REQUIRE_PUBLIC_DATA(kBoardsFolder);
    const ArmCpu cpu = board("tx2-hrw");
    QCOMPARE(QString::fromStdString(cpu.board), QString("NVIDIA Jetson TX2 Developer Kit"));
    QVERIFY(cpu.board_spec);
    QCOMPARE(QString::fromStdString(cpu.board_spec->id), QString("nvidia-jetson-tx2-cpu"));
    QCOMPARE(cpu.clusters.size(), std::size_t(2));
    const ArmCluster& a57 = cpu.clusters[0];
    const ArmCluster& denver = cpu.clusters[1];
    QCOMPARE(QString::fromStdString(a57.core_name), QString("Cortex-A57"));
    QCOMPARE(a57.cpus, (std::vector<int>{0, 3, 4}));  // the stored excerpt ends inside processor 4
    QCOMPARE(QString::fromStdString(denver.core_name), QString("Denver 2"));
    QCOMPARE(denver.cpus, (std::vector<int>{1, 2}));
    // No cpufreq here: each clock is the device table's for that core type.
    QCOMPARE(a57.clock_ghz, 2.0);
    QVERIFY(a57.clock_source.find("nvidia-jetson-tx2-cpu") != std::string::npos);
    QVERIFY(near(a57.fp32_peak_flops, 3 * 8 * 2.0e9));
    QVERIFY(near(denver.fp32_peak_flops, 2 * 16 * 2.0e9));
    QVERIFY(near(cpu.fp32_peak_flops, 48e9 + 64e9));
    QVERIFY(cpu.peak_complete);
    QCOMPARE(QString::fromStdString(cpu.summary()), QString("3x Cortex-A57 + 2x Denver 2"));
  }

  void tx2_with_denver_offline_lists_the_a57_cluster_only() {
    BENCHSCOPE_REQUIRE_PUBLIC_DATA(kBoardsFolder);
    const ArmCpu cpu = board("tx2-denver-off");
    QCOMPARE(QString::fromStdString(cpu.summary()), QString("4x Cortex-A57"));
    QVERIFY(near(cpu.fp32_peak_flops, 4 * 8 * 2.0e9));
  }

  // The board entries' peaks are reproduced from the fixtures where the fixture lists every core.
  void whole_boards_match_their_device_table_peak_data() {
    QTest::addColumn<QString>("dir");
    QTest::addColumn<QString>("summary");
    QTest::addColumn<QString>("entry");
    QTest::addColumn<double>("peak");
    QTest::newRow("AGX Xavier") << "xavier-agx"
                                << "8x Carmel"
                                << "nvidia-jetson-agx-xavier-cpu" << 8 * 16 * 2.26e9;
    QTest::newRow("Pi 4") << "pi4"
                          << "4x Cortex-A72"
                          << "raspberry-pi-4-cpu" << 4 * 8 * 1.8e9;
    QTest::newRow("Pi 5") << "pi5"
                          << "4x Cortex-A76"
                          << "raspberry-pi-5-cpu" << 4 * 16 * 2.4e9;
    // An excerpt of one CPU's lines (no full Orin cpuinfo is public): one core at the table's clock.
    QTest::newRow("AGX Orin excerpt") << "orin-agx"
                                      << "1x Cortex-A78AE"
                                      << "nvidia-jetson-agx-orin-cpu" << 16 * 2.2016e9;
  }
  void whole_boards_match_their_device_table_peak() {
    BENCHSCOPE_REQUIRE_PUBLIC_DATA(kBoardsFolder);
    QFETCH(QString, dir);
    QFETCH(QString, summary);
    QFETCH(QString, entry);
    QFETCH(double, peak);
    const ArmCpu cpu = board(dir.toStdString().c_str());
    QCOMPARE(QString::fromStdString(cpu.summary()), summary);
    QVERIFY(cpu.board_spec);
    QCOMPARE(QString::fromStdString(cpu.board_spec->id), entry);
    QVERIFY2(near(cpu.fp32_peak_flops, peak), std::to_string(cpu.fp32_peak_flops).c_str());
    if (dir != "orin-agx") QVERIFY(near(cpu.fp32_peak_flops, cpu.board_spec->fp32_peak_flops));
  }

  void pi_without_device_tree_model_is_named_by_the_cpuinfo_model_line() {
    BENCHSCOPE_REQUIRE_PUBLIC_DATA(kBoardsFolder);
    std::ifstream in(kBoards / "pi4/proc/cpuinfo");
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const ProcCpuInfo info = parse_proc_cpuinfo(text, "pi4");
    QCOMPARE(QString::fromStdString(info.model), QString("Raspberry Pi 4 Model B Rev 1.5"));
    QCOMPARE(info.cpus.size(), std::size_t(4));
    QVERIFY(info.cpus[0].model_name.empty());  // no "model name" on these kernels
    const auto cpu = describe_arm_cpu(info, "", bundled_arm_core_table(), &bs::bundled_device_table().table, "/x");
    QVERIFY(cpu && cpu->board_spec);
    QCOMPARE(QString::fromStdString(cpu->board_spec->id), QString("raspberry-pi-4-cpu"));
  }

  void cpufreq_clock_wins_over_the_device_table() {
    BENCHSCOPE_REQUIRE_PUBLIC_DATA(kBoardsFolder);
    QTemporaryDir sys;
    for (int c = 0; c < 4; ++c) {
      const fs::path d =
          fs::path(sys.path().toStdString()) / "sys/devices/system/cpu" / ("cpu" + std::to_string(c)) / "cpufreq";
      fs::create_directories(d);
      std::ofstream(d / "cpuinfo_max_freq") << "1500000\n";  // kHz: an early Pi 4's 1.5 GHz
    }
    const ArmCpu cpu = board("pi4", sys.path().toStdString());
    QCOMPARE(cpu.clusters[0].clock_ghz, 1.5);
    QVERIFY(cpu.clusters[0].clock_source.find("cpufreq") != std::string::npos);
    QVERIFY(near(cpu.fp32_peak_flops, 4 * 8 * 1.5e9));
  }

  void measured_clock_is_the_last_resort_and_unknown_cores_have_no_peak() {
    const ProcCpuInfo info = parse_proc_cpuinfo(
        "processor\t: 0\nCPU implementer\t: 0x41\nCPU part\t: 0xd07\n\nprocessor\t: 1\nCPU implementer\t: 0x61\n"
        "CPU part\t: 0x022\n",
        "mixed");
    const auto cpu = describe_arm_cpu(info, "", bundled_arm_core_table(), nullptr, "/x", 1.2e9);
    QVERIFY(cpu);
    QCOMPARE(cpu->clusters.size(), std::size_t(2));
    QCOMPARE(QString::fromStdString(cpu->clusters[0].clock_source), QString("measured"));
    QVERIFY(near(cpu->clusters[0].fp32_peak_flops, 8 * 1.2e9));
    QCOMPARE(QString::fromStdString(cpu->clusters[1].core_name),
             QString("unknown core (implementer 0x61, part 0x022)"));
    QCOMPARE(cpu->clusters[1].fp32_peak_flops, 0.0);
    QVERIFY(!cpu->peak_complete);
  }

  void x86_cpuinfo_is_not_arm() {
    const ProcCpuInfo info = parse_proc_cpuinfo(
        "processor\t: 0\nvendor_id\t: GenuineIntel\nmodel name\t: Intel(R) Core(TM) i7-7567U CPU @ 3.50GHz\n", "x86");
    QCOMPARE(info.cpus.size(), std::size_t(1));
    QVERIFY(!describe_arm_cpu(info, "", bundled_arm_core_table(), nullptr, "/x"));
  }

  void malformed_ids_are_rejected_with_the_line_data() {
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("expect");
    QTest::newRow("not hex") << "processor : 0\nCPU part : 0xzz\n"
                             << "line 2";
    QTest::newRow("implementer too wide") << "CPU implementer : 0x1234\n"
                                          << "line 1";
    QTest::newRow("no 0x") << "processor : 0\nCPU implementer : 65\n"
                           << "not a hexadecimal";
  }
  void malformed_ids_are_rejected_with_the_line() {
    QFETCH(QString, text);
    QFETCH(QString, expect);
    try {
      parse_proc_cpuinfo(text.toStdString(), "bad.cpuinfo");
      QFAIL("accepted");
    } catch (const std::runtime_error& e) {
      QVERIFY2(QString(e.what()).contains("bad.cpuinfo") && QString(e.what()).contains(expect), e.what());
    }
  }

  void bad_core_tables_are_rejected_naming_the_field() {
    const char* ok_source = R"("source": {"title": "t", "url": "https://x"})";
    const struct {
      std::string json;
      const char* expect;
    } cases[] = {
        {"{}", "format"},
        {R"({"format": "benchscope-cpu-cores", "version": 2, "cores": []})", "version"},
        {std::string(
             R"({"format": "benchscope-cpu-cores", "version": 1, "cores": [{"implementer": "0x41", "part": "0xd07", "name": "A", "fp32_lanes": 4, "fma_units": 0, )") +
             ok_source + "}]}",
         "cores[0].fma_units"},
        {R"({"format": "benchscope-cpu-cores", "version": 1, "cores": [{"implementer": "0x41", "part": "0xd07", "name": "A", "fp32_lanes": 4, "fma_units": 1}]})",
         "cores[0].source"},
        {std::string(
             R"({"format": "benchscope-cpu-cores", "version": 1, "cores": [{"implementer": "41", "part": "0xd07", "name": "A", "fp32_lanes": 4, "fma_units": 1, )") +
             ok_source + "}]}",
         "cores[0].implementer"},
        {"[", "JSON"},
    };
    for (const auto& c : cases) {
      try {
        parse_arm_core_table(c.json, "t.json");
        QFAIL(c.json.c_str());
      } catch (const std::runtime_error& e) {
        QVERIFY2(QString(e.what()).contains(c.expect), e.what());
      }
    }
  }

  void device_tree_model_drops_its_nul() {
    QCOMPARE(QString::fromStdString(read_device_tree_model("/nonexistent")), QString());
    BENCHSCOPE_REQUIRE_PUBLIC_DATA(kBoardsFolder);
    QCOMPARE(QString::fromStdString(read_device_tree_model(kBoards / "xavier-agx")), QString("Jetson-AGX"));
  }
};

QTEST_GUILESS_MAIN(TestArmCores)
#include "test_arm_cores.moc"
