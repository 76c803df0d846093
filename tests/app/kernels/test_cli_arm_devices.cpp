// SPDX-License-Identifier: GPL-3.0-or-later
// `benchscope-cli devices --proc-root DIR` on the real files of ARM boards (third-party: the shared folder's
// tests/data/platform/arm, SOURCES.md there; the board functions skip without it): core types by name, a peak per
// cluster and their sum (issue #30.3), and what it says about bad or missing files.
#include <QDir>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

#include "../../support/cli_harness.h"
#include "../../support/public_data.h"

namespace {

using bs::test::cli;
constexpr const char* kBoardsFolder = "tests/data/platform/arm";
const QString kBoards = QString::fromStdString(bs::test::public_data(kBoardsFolder)) + "/";

}  // namespace

class TestCliArmDevices : public QObject {
  Q_OBJECT
 private slots:
  void tx2_names_both_clusters_with_peaks() {
    BENCHSCOPE_REQUIRE_PUBLIC_DATA(kBoardsFolder);
    const auto r = cli({"devices", "--proc-root", kBoards + "tx2-hrw"});
    QCOMPARE(r.code, 0);
    const QString out = QString::fromUtf8(r.out);
    QVERIFY2(out.startsWith("ARM CPU: NVIDIA Jetson TX2 Developer Kit: 3x Cortex-A57 + 2x Denver 2"), r.out);
    QVERIFY2(out.contains("8 FP32 FLOP/cycle/core x 2.00 GHz"), r.out);   // A57: one 128-bit FMA
    QVERIFY2(out.contains("16 FP32 FLOP/cycle/core x 2.00 GHz"), r.out);  // Denver 2: two (upper bound)
    QVERIFY2(out.contains("= FP32 peak 48.00 GFLOPS"), r.out);            // 3 x 8 x 2 GHz
    QVERIFY2(out.contains("= FP32 peak 64.00 GFLOPS"), r.out);            // 2 x 16 x 2 GHz
    QVERIFY2(out.contains("FP32 peak, all clusters: 112.00 GFLOPS"), r.out);
    QVERIFY2(out.contains("device table nvidia-jetson-tx2-cpu"), r.out);
    QVERIFY2(out.contains("source: ") && out.contains("https://"), r.out);
  }

  void every_board_is_named_data() {
    QTest::addColumn<QString>("dir");
    QTest::addColumn<QString>("first_line");
    QTest::newRow("xavier") << "xavier-agx"
                            << "ARM CPU: Jetson-AGX: 8x Carmel";
    QTest::newRow("orin") << "orin-agx"
                          << "ARM CPU: NVIDIA Jetson AGX Orin Developer Kit: 1x Cortex-A78AE";
    QTest::newRow("pi4") << "pi4"
                         << "ARM CPU: Raspberry Pi 4 Model B Rev 1.5: 4x Cortex-A72";
    QTest::newRow("pi5") << "pi5"
                         << "ARM CPU: Raspberry Pi 5 Model B Rev 1.0: 4x Cortex-A76";
    QTest::newRow("tx2 denver off") << "tx2-denver-off"
                                    << "ARM CPU: NVIDIA Jetson TX2 Developer Kit: 4x Cortex-A57";
  }
  void every_board_is_named() {
    BENCHSCOPE_REQUIRE_PUBLIC_DATA(kBoardsFolder);
    QFETCH(QString, dir);
    QFETCH(QString, first_line);
    const auto r = cli({"devices", "--proc-root", kBoards + dir});
    QCOMPARE(r.code, 0);
    QVERIFY2(QString::fromUtf8(r.out).startsWith(first_line), r.out);
  }

  void json_has_clusters_and_the_sum() {
    BENCHSCOPE_REQUIRE_PUBLIC_DATA(kBoardsFolder);
    const auto r = cli({"devices", "--proc-root", kBoards + "pi5", "--json"});
    QCOMPARE(r.code, 0);
    const QJsonObject doc = QJsonDocument::fromJson(r.out).object();
    QCOMPARE(doc["format"].toString(), QString("benchscope-arm-cpu"));
    const QJsonObject cpu = doc["cpu"].toObject();
    QCOMPARE(cpu["board"].toString(), QString("Raspberry Pi 5 Model B Rev 1.0"));
    QCOMPARE(cpu["device_table_entry"].toString(), QString("raspberry-pi-5-cpu"));
    const QJsonArray clusters = cpu["clusters"].toArray();
    QCOMPARE(clusters.size(), 1);
    const QJsonObject c = clusters[0].toObject();
    QCOMPARE(c["core"].toString(), QString("Cortex-A76"));
    QCOMPARE(c["part"].toString(), QString("0xd0b"));
    QCOMPARE(c["cores"].toInt(), 4);
    QCOMPARE(c["core_type"].toObject()["fma_units"].toInt(), 2);
    QCOMPARE(cpu["fp32_peak_flops"].toDouble(), 4 * 16 * 2.4e9);
    QVERIFY(cpu["peak_complete"].toBool());
  }

  void cpufreq_under_the_sysfs_root_sets_the_clock() {
    BENCHSCOPE_REQUIRE_PUBLIC_DATA(kBoardsFolder);
    QTemporaryDir sys;
    QVERIFY(QDir().mkpath(sys.filePath("sys/devices/system/cpu/cpu0/cpufreq")));
    QFile f(sys.filePath("sys/devices/system/cpu/cpu0/cpufreq/cpuinfo_max_freq"));
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("1500000\n");
    f.close();
    const auto r = cli({"devices", "--proc-root", kBoards + "pi4", "--sysfs-root", sys.path()});
    QCOMPARE(r.code, 0);
    QVERIFY2(r.out.contains("x 1.50 GHz (cpufreq cpuinfo_max_freq of cpu0)"), r.out);
    QVERIFY2(r.out.contains("= FP32 peak 48.00 GFLOPS"), r.out);
  }

  void bad_or_missing_files_are_errors_naming_the_file() {
    QTemporaryDir dir;
    auto r = cli({"devices", "--proc-root", dir.path()});
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains("proc/cpuinfo: cannot open"), r.err);

    QVERIFY(QDir().mkpath(dir.filePath("proc")));
    QFile f(dir.filePath("proc/cpuinfo"));
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("processor\t: 0\nCPU implementer\t: 0x41\nCPU part\t: banana\n");
    f.close();
    r = cli({"devices", "--proc-root", dir.path()});
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains("line 3") && r.err.contains("banana"), r.err);

    QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
    f.write("processor\t: 0\nvendor_id\t: GenuineIntel\nmodel name\t: Intel(R) Core(TM) i7-7567U\n");
    f.close();
    r = cli({"devices", "--proc-root", dir.path()});
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains("not ARM"), r.err);

    QCOMPARE(cli({"devices", "--sysfs-root", dir.path()}).code, 2);  // only with --proc-root
  }
};

QTEST_GUILESS_MAIN(TestCliArmDevices)
#include "test_cli_arm_devices.moc"
