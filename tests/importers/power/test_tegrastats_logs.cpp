// SPDX-License-Identifier: GPL-3.0-or-later
// tegrastats from three Jetson generations, the interval option and the rules for broken logs.
#include <QTest>

#include "power/power_import.h"
#include "power/tegrastats.h"
#include "workspace/registry.h"

#include "../../support/import_errors.h"

namespace {

const std::string kData = BENCHSCOPE_TEST_DATA_DIR "/power/";

const auto error_of = bs::test::import_errors_of(bs::kTegrastatsFileFormat, "t.log");

}  // namespace

class TestTegrastatsLogs : public QObject {
  Q_OBJECT
 private slots:
  void nano_jetpack4_pom_rails() {
    const auto b = bs::import_file(kData + "tegrastats-nano-jetpack4.log", bs::CancelToken{});
    QCOMPARE(b.format, std::string("tegrastats"));
    const bs::PowerTrace& t = b.power_traces.at(0);
    QCOMPARE(t.channels.size(), std::size_t{3});
    QCOMPARE(t.channels[0].name, std::string("POM_5V_IN"));
    QCOMPARE(t.channels[0].values[2], 6.421);  // instantaneous, not the running average 4283 mW
    QCOMPARE(t.channels[1].values[3], 2.851);
    QCOMPARE(t.time_s[3], 3.0);
    QVERIFY(t.start_time.empty());
    QCOMPARE(b.warnings.size(), std::size_t{1});  // no timestamps: what interval is assumed
    QVERIFY(b.warnings[0].find("one line every 1 s") != std::string::npos);
  }
  void agx_xavier_plain_rail_names_warn_about_the_missing_input_rail() {
    const auto b = bs::import_file(kData + "tegrastats-xavier-agx.log", bs::CancelToken{});
    const bs::PowerTrace& t = b.power_traces.at(0);
    QCOMPARE(t.channels.size(), std::size_t{7});  // sum, then GPU CPU SOC CV VDDRQ SYS5V
    QCOMPARE(t.channels[0].name, std::string("sum of rails"));
    QCOMPARE(t.total_channel, t.channels[0].name);
    QCOMPARE(t.channels[1].name, std::string("GPU"));
    QCOMPARE(t.channels[1].values[2], 4.955);
    QCOMPARE(t.channels[6].name, std::string("SYS5V"));
    // 4955 + 929 + 2167 + 0 + 310 + 1649 = 10010 mW, not the GPU rail's 4.955 W.
    QCOMPARE(t.channels[0].values[2], 4.955 + 0.929 + 2.167 + 0.0 + 0.310 + 1.649);
    QCOMPARE(b.warnings.size(), std::size_t{2});
    QVERIFY(b.warnings[0].find("no board input rail") != std::string::npos);
    QVERIFY(t.provenance.note.find("sum of rails (GPU + CPU + SOC + CV + VDDRQ + SYS5V)") != std::string::npos);
  }
  void orin_jetpack6_timestamps_across_the_new_year() {
    const auto b = bs::import_file(kData + "tegrastats-orin-jetpack6.log", bs::CancelToken{});
    const bs::PowerTrace& t = b.power_traces.at(0);
    QCOMPARE(t.channels[0].name, std::string("VDD_IN"));
    QCOMPARE(t.channels[1].name, std::string("VDD_CPU_GPU_CV"));
    QCOMPARE(t.channels[0].values[1], 7.52);
    QCOMPARE(t.time_s[1], 1.0);
    QCOMPARE(t.time_s[2], 3.0);  // the log's own clock: one line was never written
    QCOMPARE(t.start_time, std::string("2026-12-31T23:59:59"));
  }
  void interval_option() {
    bs::ParseOptions options;
    options.interval_s = 0.25;
    const auto b = bs::import_power_log(kData + "tegrastats-nano-jetpack4.log", options);
    QCOMPARE(b.format, std::string("tegrastats"));
    QCOMPARE(b.power_traces.at(0).time_s[3], 0.75);
    options.interval_s = 0.0;
    QVERIFY_THROWS_EXCEPTION(bs::ImportError,
                             bs::kTegrastatsFileFormat.parse_text("RAM 1/2MB VDD_IN 1/1\n", "t.log", options));
  }
  void broken_logs() {
    // Rails that change in the middle: an error at that line; at the very end: a cut-off line, skipped.
    auto e = error_of(
        "RAM 1/2MB VDD_IN 100/100 VDD_CPU 50/50\nRAM 1/2MB VDD_IN 100/100\nRAM 1/2MB VDD_IN 100/100 VDD_CPU 50/50\n");
    QCOMPARE(e.location().line, std::size_t{2});
    QCOMPARE(e.category(), bs::ImportErrorCategory::InvalidValue);
    const auto cut = bs::kTegrastatsFileFormat.parse_text(
        "RAM 1/2MB VDD_IN 100/100 VDD_CPU 50/50\nRAM 1/2MB VDD_IN 120/110\n\n", "t.log");
    QCOMPARE(cut.power_traces.at(0).time_s.size(), std::size_t{1});
    QVERIFY(cut.warnings.at(0).find("t.log:2: incomplete last line") != std::string::npos);
    // Timestamps going backwards, and on some lines only.
    e = error_of(
        "01-02-2027 10:00:05 RAM 1/2MB VDD_IN 1/1\n01-02-2027 10:00:04 RAM 1/2MB VDD_IN 1/1\n01-02-2027 10:00:06 RAM "
        "1/2MB VDD_IN 1/1\n");
    QCOMPARE(e.location().line, std::size_t{2});
    QVERIFY(std::string(e.what()).find("backwards") != std::string::npos);
    e = error_of("01-02-2027 10:00:05 RAM 1/2MB VDD_IN 1/1\nRAM 1/2MB VDD_IN 1/1\nRAM 1/2MB VDD_IN 1/1\n");
    QCOMPARE(e.location().line, std::size_t{2});
    // No rails at all (not run as root): an error that says why.
    e = error_of("RAM 1/2MB CPU [1%@100] EMC_FREQ 0%\n");
    QCOMPARE(e.category(), bs::ImportErrorCategory::MissingField);
    QVERIFY(std::string(e.what()).find("no lines with power rails") != std::string::npos);
    // Many rail-less lines: listed up to ten, then counted.
    std::string text = "RAM 1/2MB VDD_IN 1/1\n";
    for (int k = 0; k < 25; ++k) text += "RAM 1/2MB CPU [1%@100]\n";
    text += "RAM 1/2MB VDD_IN 2/1\n";
    const auto many = bs::kTegrastatsFileFormat.parse_text(text, "t.log");
    QCOMPARE(many.warnings.size(), std::size_t{12});  // 10 listed, 1 count, 1 about the assumed interval
    QVERIFY(many.warnings[10].find("15 more lines skipped") != std::string::npos);
  }
  void readings_beyond_a_rail_are_errors() {
    // A VDD_IN past int64 once became a "mean power" of 1.7e18 W; now it names the file, line, column and rail.
    auto e = error_of(
        "RAM 1/2MB VDD_IN 5000mW/5000mW VDD_SOC 1/1\nRAM 1/2MB VDD_IN 99999999999999999999mW/5000mW VDD_SOC 1/1\n"
        "RAM 1/2MB VDD_IN 5000mW/5000mW VDD_SOC 1/1\n");
    QCOMPARE(e.category(), bs::ImportErrorCategory::InvalidValue);
    QCOMPARE(e.location().line, std::size_t{2});
    QCOMPARE(e.location().column, std::size_t{18});
    QCOMPARE(e.location().field, std::string("VDD_IN"));
    QVERIFY(std::string(e.what()).find("between -2 W and 1 kW") != std::string::npos);
    // 1 kW is the bound, in the average as well; exactly 1 kW is accepted.
    QCOMPARE(error_of("RAM 1/2MB VDD_IN 1000001/5\nRAM 1/2MB VDD_IN 1/1\n").location().line, std::size_t{1});
    QCOMPARE(error_of("RAM 1/2MB VDD_IN 5/1000001\nRAM 1/2MB VDD_IN 1/1\n").location().line, std::size_t{1});
    QCOMPARE(bs::kTegrastatsFileFormat.parse_text("RAM 1/2MB VDD_IN 1000000/5\n", "t.log")
                 .power_traces.at(0)
                 .channels[0]
                 .values[0],
             1000.0);
    // A number too long even for a double.
    QCOMPARE(error_of("RAM 1/2MB VDD_IN " + std::string(400, '9') + "/1\nRAM 1/2MB VDD_IN 1/1\n").category(),
             bs::ImportErrorCategory::InvalidValue);
    // AGX Thor reads slightly negative on a power-gated rail ("VDD_GPU -392mW/-392mW", from a Thor script's
    // docstring): kept as printed. Far below zero is not a reading.
    const auto thor = bs::kTegrastatsFileFormat.parse_text(
        "05-14-2026 21:36:35 RAM 26063/125772MB (lfb 35x4MB) VDD_GPU -392mW/-392mW VDD_CPU_SOC_MSS 3924mW/3835mW "
        "VIN_SYS_5V0 5064mW/5055mW VIN 15004mW/15096mW\n",
        "t.log");
    const bs::PowerTrace& t = thor.power_traces.at(0);
    QCOMPARE(t.total_channel, std::string("VIN"));
    QCOMPARE(t.channels[0].values[0], 15.004);
    QCOMPARE(t.channels[1].values[0], -0.392);
    QCOMPARE(error_of("RAM 1/2MB VDD_IN -2001mW/1mW\nRAM 1/2MB VDD_IN 1/1\n").category(),
             bs::ImportErrorCategory::InvalidValue);
  }
  void jetpack7_three_values_and_four() {
    const auto b = bs::kTegrastatsFileFormat.parse_text(
        "RAM 1/2MB VDD_GPU_SOC 4385mW/3787mW/4385mW VDD_CPU_CV 1196mW/897mW/1196mW\n", "t.log");
    QCOMPARE(b.power_traces.at(0).channels[0].values[0], 4.385 + 1.196);  // sum of rails: no input rail
    // Four values are no tegrastats format: an error, not a guess.
    const auto e = error_of("RAM 1/2MB VDD_IN 1mW/2mW/3mW/4mW\nRAM 1/2MB VDD_IN 1/1\n");
    QCOMPARE(e.location().field, std::string("VDD_IN"));
  }
  void sniffing() {
    const bs::FormatImporter imp(bs::kTegrastatsFileFormat);
    QCOMPARE(imp.sniff("RAM 2448/7854MB (lfb 1x4MB) VDD_IN 3981/3981\n", "x.log"), 90);
    QCOMPARE(imp.sniff("RAM 8179/62817MB (lfb 1x4MB) VDD_GPU_SOC 4385mW/3787mW/4385mW\n", "x.log"), 90);
    // No rails: still recognised (weakly), so that the import says why nothing can be read instead of
    // "unknown format".
    QCOMPARE(imp.sniff("RAM 2448/7854MB (lfb 1x4MB) SWAP 0/3927MB CPU [3%@345]\n", "x.log"), 30);
    QCOMPARE(imp.sniff("RAM 2448/7854MB (lfb 1x4MB) SWAP 0/3927MB\n", "x.log"), 0);
    QCOMPARE(imp.sniff("time_s,current_A\n0,1\n", "x.csv"), 0);
  }
};

QTEST_APPLESS_MAIN(TestTegrastatsLogs)
#include "test_tegrastats_logs.moc"
