// SPDX-License-Identifier: GPL-3.0-or-later
// Every delimited power-log flavour BenchScope reads, from realistic fixtures, through the same entry points the
// app uses (import_file sniffing, import_power_log with options). The real_* functions read third-party logs (the
// shared folder's tests/data/power/real/, SOURCES there) and skip without them.
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include "analysis/power/power_stats.h"
#include "power/power_csv.h"
#include "power/power_import.h"
#include "workspace/registry.h"

#include "../../support/find_item.h"
#include "../../support/public_data.h"

namespace {

const std::string kData = BENCHSCOPE_TEST_DATA_DIR "/power/";

bs::ImportBatch import(const std::string& name) { return bs::import_file(kData + name, bs::CancelToken{}); }

// A third-party log of tests/data/power/real/ (the shared folder).
bs::ImportBatch import_real(const std::string& name) {
  return bs::import_file(bs::test::public_data("tests/data/power/real/" + name), bs::CancelToken{});
}

const bs::PowerChannel& channel(const bs::PowerTrace& t, bs::PowerQuantity q) {
  return bs::test::item_of(t.channels, &bs::PowerChannel::quantity, q, "such channel");
}

bool has_channel(const bs::PowerTrace& t, bs::PowerQuantity q) {
  return bs::test::find_item(t.channels, &bs::PowerChannel::quantity, q) != nullptr;
}

}  // namespace

class TestPowerFormats : public QObject {
  Q_OBJECT
 private slots:
  void real_intel_power_gadget_log() {
    BENCHSCOPE_REQUIRE_PUBLIC_DATA("tests/data/power/real");
    // SOURCES of tests/data/power/real: sunilkumar2000/Power-Monitoring-Tool PowerLog.csv, 10 rows, unquoted.
    const auto b = import_real("intel-power-gadget-windows.csv");
    QCOMPARE(b.format, std::string("power-csv"));
    const bs::PowerTrace& t = b.power_traces.at(0);
    // Time from "Elapsed Time (sec)" (0.108 .. 1.041 s), not the date-less "System Time".
    QCOMPARE(t.time_s.size(), std::size_t{10});
    QVERIFY(std::abs(t.time_s[9] - 0.933) < 1e-12);
    QVERIFY(t.start_time.empty());
    // Processor (package), IA, DRAM and GT power; limits, cumulative energies, temperatures are not channels.
    QCOMPARE(t.channels.size(), std::size_t{4});
    QCOMPARE(t.total_channel, std::string("Processor Power_0(Watt)"));
    QCOMPARE(t.provenance.measurement, bs::MeasurementKind::OnBoardSensor);
    QCOMPARE(t.provenance.sensor, std::string("Intel Power Gadget (RAPL)"));
    // The summary footer: 14 "name = value" lines, kept as settings.
    QCOMPARE(t.provenance.settings.size(), std::size_t{14});
    QCOMPARE(t.provenance.settings[0], (std::pair<std::string, std::string>{"Total Elapsed Time (sec)", "1.040852"}));
    bool footer_warned = false;
    for (const auto& w : b.warnings)
      footer_warned = footer_warned || w.find(":13: summary footer (14") != std::string::npos;
    QVERIFY(footer_warned);
    // By hand, package power 7.163 12.414 2.998 6.171 4.152 2.443 4.778 6.874 17.094 9.811 W:
    //   sum 73.898 W, mean 7.3898 W (n 10);
    //   trapezoids (dt s x mean of neighbours W): .109 x 9.7885 + .114 x 7.706 + .116 x 4.5845 + .115 x 5.1615
    //   + .125 x 3.2975 + .111 x 3.6105 + .137 x 5.826 + .105 x 11.984 + .001 x 13.4525 = 5.9536925 J.
    // Power Gadget's own counter says 7.237 - 0.774 = 6.463 J over the same span: its samples are averages over
    // the interval before each row, so sum(P_k x dt_k) = 6.470 J matches the counter, and the trapezoid (which
    // treats them as instantaneous) is 8 % lower on this jumpy 10-row log.
    const bs::PowerStats s = bs::power_stats(t);
    QCOMPARE(s.power_w->summary.n, std::size_t{10});
    QVERIFY(std::abs(s.power_w->summary.mean - 7.3898) < 1e-12);
    QVERIFY(std::abs(*s.energy_j - 5.9536925) < 1e-9);
  }
  void real_intel_power_gadget_log_quoted() {
    BENCHSCOPE_REQUIRE_PUBLIC_DATA("tests/data/power/real");
    // SOURCES of tests/data/power/real: platevoltage/machine-stats PowerLog.csv, every cell quoted, 6 rows.
    const auto b = import_real("intel-power-gadget-quoted.csv");
    const bs::PowerTrace& t = b.power_traces.at(0);
    QCOMPARE(t.time_s.size(), std::size_t{6});
    QVERIFY(std::abs(t.time_s[2] - 0.831) < 1e-12);  // the 0.72 s gap between rows 2 and 3 is kept
    QCOMPARE(t.channels.size(), std::size_t{3});     // Processor, IA, DRAM; "Package Power Limit_0(Watt)" is not
    QCOMPARE(t.total_channel, std::string("Processor Power_0(Watt)"));
    QCOMPARE(t.provenance.settings.size(), std::size_t{11});
    QCOMPARE(t.provenance.settings[4],
             (std::pair<std::string, std::string>{"Average Package Power_0 (Watt)", "62.575186"}));
    // By hand, package power 86.324 92.903 57.964 59.288 58.359 46.596 W: sum 401.434, mean 66.905667 W;
    //   trapezoids .109 x 89.6135 + .722 x 75.4335 + .102 x 58.626 + .102 x 58.8235 + .104 x 52.4775
    //   = 9.7678715 + 54.462987 + 5.979852 + 5.999997 + 5.45766 = 81.6683675 J.
    // Cross-check with the file's counter: interval averages sum(P_k x dt_k) = 68.822 J against
    // 77.782 - 8.954 = 68.828 J cumulative, so the columns and times are read right; the trapezoid is higher
    // because the 0.72 s gap is bridged from 92.9 W, while the chip drew ~58 W through most of it.
    const bs::PowerStats s = bs::power_stats(t);
    QVERIFY(std::abs(s.power_w->summary.mean - 401.434 / 6) < 1e-12);
    QVERIFY(std::abs(*s.energy_j - 81.6683675) < 1e-9);
  }
  void real_powerlog_samples() {
    BENCHSCOPE_REQUIRE_PUBLIC_DATA("tests/data/power/real");
    // SOURCES of tests/data/power/real: arsho/powerlog's documented samples CSV (Unix ns beside an elapsed clock).
    const auto b = import_real("powerlog-samples-doc.csv");
    const bs::PowerTrace& t = b.power_traces.at(0);
    QVERIFY(std::abs(t.time_s[1] - 0.1035) < 1e-12);  // from "Elapsed (s)": 0.2086 - 0.1051
    QCOMPARE(QString::fromStdString(t.start_time),
             QStringLiteral("2026-09-09T15:14:01.539Z"));  // 1788966841539282000 ns
    QCOMPARE(t.channels.size(), std::size_t{4});
    QVERIFY(t.total_channel.empty());  // "GPU Power (W)" sums the GPUs, not the machine: no total named
    bool said = false;
    for (const auto& w : b.warnings)
      said = said || w.find("statistics use 'CPU Power (W)' (the first)") != std::string::npos;
    QVERIFY(said);
    // Mean of the first power column: (77.42 + 78.10) / 2 = 77.76 W; energy 0.1035 s x 77.76 W = 8.04816 J.
    const bs::PowerStats s = bs::power_stats(t);
    QVERIFY(std::abs(s.power_w->summary.mean - 77.76) < 1e-12);
    QVERIFY(std::abs(*s.energy_j - 8.04816) < 1e-9);
    // The README's one-sample "Timestamp (ns),Power Draw (W)": time from the integer nanoseconds, exactly.
    const bs::PowerTrace one = import_real("powerlog-readme.csv").power_traces.at(0);
    QCOMPARE(QString::fromStdString(one.start_time), QStringLiteral("2025-07-11T01:47:20.221Z"));
    QCOMPARE(one.channels.at(0).values, (std::vector<double>{12.84}));
  }
  void joulescope_export() {
    const auto b = import("joulescope-export.csv");
    QCOMPARE(b.format, std::string("power-csv"));
    const bs::PowerTrace& t = b.power_traces.at(0);
    QCOMPARE(t.time_s.size(), std::size_t{50});
    QCOMPARE(t.time_s[49], 0.049);
    QCOMPARE(t.channels.size(), std::size_t{3});  // charge and energy are integrals, not read as channels
    QCOMPARE(channel(t, bs::PowerQuantity::Voltage).values[0], 5.012);
    QVERIFY(std::abs(channel(t, bs::PowerQuantity::Current).values[30] - (0.612 + 0.003 * std::sin(30.0))) < 1e-6);
    QVERIFY(b.warnings.size() == 1 && b.warnings[0].find("'charge' (5), 'energy' (6)") != std::string::npos);
    // The older export's '#'-prefixed header line.
    const auto hashed = bs::kPowerCsvFileFormat.parse_text(
        "#time,current,voltage,power\n0.000000,0.512,5.01,2.565\n0.001000,0.514,5.01,2.575\n", "js.csv");
    QCOMPARE(channel(hashed.power_traces.at(0), bs::PowerQuantity::Power).values[1], 2.575);
  }
  void otii_export_with_irregular_times() {
    const bs::PowerTrace t = import("otii-export.csv").power_traces.at(0);
    QCOMPARE(t.time_s.size(), std::size_t{8});
    QCOMPARE(t.time_s[4], 0.00175);
    QCOMPARE(channel(t, bs::PowerQuantity::Current).values[7], 0.0895);
    QCOMPARE(channel(t, bs::PowerQuantity::Voltage).values[0], 3.3);
  }
  void ina219_logger() {
    const auto b = import("ina219-logger.csv");
    const bs::PowerTrace& t = b.power_traces.at(0);
    QCOMPARE(t.channels.size(), std::size_t{3});    // bus V, mA, mW; the shunt drop is not the supply
    QVERIFY(std::abs(t.time_s[11] - 1.1) < 1e-12);  // millis, relative to the first row
    QCOMPARE(channel(t, bs::PowerQuantity::Current).values[1], 0.83);
    QCOMPARE(channel(t, bs::PowerQuantity::Voltage).values[1], 12.09);
    QCOMPARE(channel(t, bs::PowerQuantity::Power).values[0], 9.922);
    QVERIFY(b.warnings.at(0).find("'shunt_mV' (2)") != std::string::npos);
  }
  void decimal_comma_semicolon_bom_crlf() {
    const bs::PowerTrace t = import("spreadsheet-de.csv").power_traces.at(0);
    QCOMPARE(t.time_s.size(), std::size_t{8});
    QCOMPARE(t.time_s[3], 1.5);
    QCOMPARE(channel(t, bs::PowerQuantity::Current).values[2], 1.54);
    QCOMPARE(channel(t, bs::PowerQuantity::Voltage).values[7], 15.97);
    QCOMPARE(t.channels[0].name, std::string("Strom [mA]"));
  }
  void iso_timestamps_across_midnight() {
    const bs::PowerTrace t = import("iso-timestamps.csv").power_traces.at(0);
    QCOMPARE(t.platform, std::string("NUC"));
    QCOMPARE(QString::fromStdString(t.start_time), QStringLiteral("2026-12-31T23:59:58.000Z"));
    QCOMPARE(t.time_s.size(), std::size_t{16});
    QCOMPARE(t.time_s[15], 3.75);  // into the next year
    QCOMPARE(t.time_s[8], 2.0);
  }
  void tab_separated_ms_and_ma_and_supply_from_options() {
    auto b = import("tab-ms-ma.tsv");
    bs::PowerTrace t = b.power_traces.at(0);
    QCOMPARE(t.time_s[9], 0.9);
    QCOMPARE(channel(t, bs::PowerQuantity::Current).values[9], 0.599);
    QVERIFY(!t.supply_voltage_v);  // current only, no supply: kept empty, and said so
    QVERIFY(b.warnings.at(0).find("no supply voltage") != std::string::npos);
    bs::ParseOptions options;
    options.supply_voltage_v = 16.0;
    options.platform = "Jetson TX2";
    b = bs::import_power_log(kData + "tab-ms-ma.tsv", options);
    QCOMPARE(b.format, std::string("power-csv"));
    QCOMPARE(*b.power_traces.at(0).supply_voltage_v, 16.0);
    QCOMPARE(b.power_traces.at(0).platform, std::string("Jetson TX2"));
    QVERIFY(b.warnings.empty());
  }
  void header_aliases_and_units() {
    struct Case {
      const char* header;
      double time_scale, value_scale;
      bs::PowerQuantity quantity;
    };
    const Case cases[] = {
        {"time,current", 1, 1, bs::PowerQuantity::Current},
        {"t,I", 1, 1, bs::PowerQuantity::Current},
        {"Time [s],Current (mA)", 1, 1e-3, bs::PowerQuantity::Current},
        {"time_ms,current_mA", 1e-3, 1e-3, bs::PowerQuantity::Current},
        {"timestamp,A", 1, 1, bs::PowerQuantity::Current},
        {"time_us,current_uA", 1e-6, 1e-6, bs::PowerQuantity::Current},
        {"\"Time [ms]\", \"Power [mW]\"", 1e-3, 1e-3, bs::PowerQuantity::Power},
        {"Timestamp (s),Main power (W)", 1, 1, bs::PowerQuantity::Power},
        {"elapsed_s,main_current", 1, 1, bs::PowerQuantity::Current},  // a name part after '_' that is no unit
        {"millis,mW", 1e-3, 1e-3, bs::PowerQuantity::Power},
    };
    for (const Case& c : cases) {
      const auto b = bs::kPowerCsvFileFormat.parse_text(std::string(c.header) + "\n0,0\n2,5\n", "aliases.csv");
      const bs::PowerTrace& t = b.power_traces.at(0);
      QVERIFY2(std::abs(t.time_s[1] - 2 * c.time_scale) < 1e-15, c.header);
      QVERIFY2(has_channel(t, c.quantity), c.header);
      QVERIFY2(std::abs(channel(t, c.quantity).values[1] - 5 * c.value_scale) < 1e-15, c.header);
    }
  }
  void trailing_separator_and_comments_between_rows() {
    const auto b =
        bs::kPowerCsvFileFormat.parse_text("time_s,current_A,\n0,1,\n# marker: load starts\n1,2,\n", "x.csv");
    QCOMPARE(b.power_traces.at(0).time_s.size(), std::size_t{2});
    QCOMPARE(b.power_traces.at(0).channels.at(0).values[1], 2.0);
  }
  void streaming_equals_in_memory() {
    // A file larger than the reader's 1 MiB block: lines cut at block edges must parse like in memory.
    QTemporaryDir dir;
    const std::string path = dir.filePath("big.csv").toStdString();
    std::string text = "time_s,current_A,voltage_V\n";
    for (int k = 0; k < 120000; ++k)
      text += std::to_string(k * 0.001) + "," + std::to_string(2.0 + (k % 97) * 0.001) + ",16.0" +
              std::string(k % 7, ' ') + "\n";
    QFile f(QString::fromStdString(path));
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(text.data(), static_cast<qint64>(text.size()));
    f.close();
    const auto streamed = bs::kPowerCsvFileFormat.parse(path, {}, {}, bs::CancelToken{}).power_traces.at(0);
    const auto memory = bs::kPowerCsvFileFormat.parse_text(text, path).power_traces.at(0);
    QCOMPARE(streamed.time_s.size(), std::size_t{120000});
    QVERIFY(streamed.time_s == memory.time_s);
    QVERIFY(streamed.channels[0].values == memory.channels[0].values);
    QCOMPARE(streamed.channels[1].values[119999], 16.0);
  }
  void sniffing_picks_power_csv_only_for_power_logs() {
    const bs::FormatImporter imp(bs::kPowerCsvFileFormat);
    QCOMPARE(imp.sniff("time_s,current_A\n0,1\n", "x.txt"), 70);
    QCOMPARE(imp.sniff("# comment\n#time,current,voltage,power\n", "x"), 70);
    QCOMPARE(imp.sniff("name,iterations,real_time,cpu_time,time_unit\n", "x.csv"), 0);  // Google Benchmark CSV
    QCOMPARE(imp.sniff("# logged at 10 Hz, time in s\n", "x.csv"), 0);
    QCOMPARE(imp.sniff("{\"format\": \"benchscope-run\"}", "x.csv"), 0);
  }
};

QTEST_APPLESS_MAIN(TestPowerFormats)
#include "test_power_formats.moc"
