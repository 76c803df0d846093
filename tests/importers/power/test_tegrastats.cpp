// SPDX-License-Identifier: GPL-3.0-or-later
#include <QTest>

#include "power/tegrastats.h"
#include "workspace/registry.h"

class TestTegrastats : public QObject {
  Q_OBJECT
 private slots:
  void a_board_family_is_no_platform_and_a_cut_line_is_named() {
    // Issue #43.3: tegrastats names no board model, so the log has no platform (the import asks or guesses; a TX2's
    // and an Orin's logs must not both become "Jetson"). Issue #43.7: a last line without its line ending may be
    // cut where the number still parses ("3642/36" of "3642/3633"): the warning names the file and the line.
    const std::string line1 =
        "RAM 2633/7850MB (lfb 3x4MB) CPU [0%@2035,0%@2035] VDD_IN 3624/3624 VDD_CPU 696/696 VDD_GPU 371/371\n";
    const std::string line2 =
        "RAM 2631/7850MB (lfb 3x4MB) CPU [18%@2035,0%@2035] VDD_IN 3642/3633 VDD_CPU 695/695 VDD_GPU 370/36";
    const bs::ImportBatch cut = bs::kTegrastatsFileFormat.parse_text(line1 + line2, "board.log");
    QVERIFY(cut.power_traces.at(0).platform.empty());
    bool named = false;
    for (const std::string& w : cut.warnings)
      named = named || (w.rfind("board.log:2:", 0) == 0 && w.find("no line ending") != std::string::npos);
    QVERIFY2(named, cut.warnings.empty() ? "no warnings" : cut.warnings.front().c_str());
    // With its line ending nothing is said about it.
    const bs::ImportBatch whole = bs::kTegrastatsFileFormat.parse_text(line1 + line2 + "\n", "board.log");
    for (const std::string& w : whole.warnings) QVERIFY2(w.find("no line ending") == std::string::npos, w.c_str());
    // A platform given with the import (--platform) is taken.
    bs::ParseOptions given;
    given.platform = "Jetson TX2";
    QCOMPARE(bs::kTegrastatsFileFormat.parse_text(line1, "board.log", given).power_traces.at(0).platform,
             std::string("Jetson TX2"));
  }
  void jetpack4_tx2() {
    const auto batch =
        bs::import_file(BENCHSCOPE_TEST_DATA_DIR "/power/tegrastats-tx2-jetpack4.log", bs::CancelToken{});
    QCOMPARE(batch.format, std::string("tegrastats"));
    const bs::PowerTrace& t = batch.power_traces.at(0);
    QCOMPARE(t.time_s.size(), std::size_t{3});        // the cut-off last line is skipped with a warning
    QCOMPARE(batch.warnings.size(), std::size_t{2});  // ... and one says the times assume a 1 s interval
    QVERIFY(batch.warnings[0].find(":4:") != std::string::npos);
    QVERIFY(batch.warnings[1].find("no timestamps") != std::string::npos);
    QCOMPARE(t.time_s[2], 2.0);  // no timestamps: tegrastats' 1 s interval
    QCOMPARE(t.channels.size(), std::size_t{6});
    QCOMPARE(t.channels[0].name, std::string("VDD_IN"));  // input rail first
    QCOMPARE(t.total_channel, std::string("VDD_IN"));
    QCOMPARE(t.channels[0].values[2], 9.648);  // mW -> W, the current (not average) value
    QCOMPARE(t.channels[0].quantity, bs::PowerQuantity::Power);
  }
  void jetpack5_orin_with_timestamps() {
    const auto batch =
        bs::import_file(BENCHSCOPE_TEST_DATA_DIR "/power/tegrastats-orin-jetpack5.log", bs::CancelToken{});
    const bs::PowerTrace& t = batch.power_traces.at(0);
    QCOMPARE(t.time_s.size(), std::size_t{3});
    QCOMPARE(t.time_s[1], 1.0);
    QCOMPARE(t.time_s[2], 3.0);  // the log's own times, including the skipped second
    // AGX Orin has no input rail: VIN_SYS_5V0 is the module's 5 V rail, not the board's input. The total is the sum.
    QCOMPARE(t.channels[0].name, std::string("sum of rails"));
    QCOMPARE(t.total_channel, std::string("sum of rails"));
    QCOMPARE(t.channels[1].name, std::string("VDD_GPU_SOC"));
    QCOMPARE(t.channels[1].values[1], 9.120);
    QCOMPARE(t.channels[0].values[1], 9.120 + 1.592 + 3.428);
    QCOMPARE(batch.warnings.size(), std::size_t{1});
    QVERIFY(batch.warnings[0].find("no board input rail") != std::string::npos);
  }
  void inconsistent_rails_and_no_rails() {
    try {
      bs::kTegrastatsFileFormat.parse_text(
          "RAM 1/2MB VDD_IN 100/100 VDD_CPU 50/50\nRAM 1/2MB VDD_IN 100/100\nRAM 1/2MB VDD_IN 100/100 VDD_CPU 50/50\n",
          "t.log");
      QFAIL("accepted");
    } catch (const bs::ImportError& e) {
      QCOMPARE(e.location().line, std::size_t{2});
    }
    QVERIFY_THROWS_EXCEPTION(bs::ImportError,
                             bs::kTegrastatsFileFormat.parse_text("RAM 1/2MB CPU [1%@100]\n", "t.log"));
  }
};

QTEST_APPLESS_MAIN(TestTegrastats)
#include "test_tegrastats.moc"
