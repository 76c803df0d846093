// SPDX-License-Identifier: GPL-3.0-or-later
#include <QFile>
#include <QTest>

#include "power/power_csv.h"

#include "../../support/find_item.h"
#include "../../support/import_errors.h"
#include "../../support/importer_parse.h"
#include "../../support/text_lines.h"

using bs::test::any_line_contains;

namespace {

bs::PowerTrace parse(const std::string& text) {
  auto batch = bs::kPowerCsvFileFormat.parse_text(text, "log.csv");
  return std::move(batch.power_traces.at(0));
}

const bs::PowerChannel* channel(const bs::PowerTrace& t, bs::PowerQuantity q) {
  return bs::test::find_item(t.channels, &bs::PowerChannel::quantity, q);
}

const bs::PowerChannel* named(const bs::PowerTrace& t, const std::string& name) {
  return bs::test::find_item(t.channels, &bs::PowerChannel::name, name);
}

const auto error_of = bs::test::import_errors_of(bs::kPowerCsvFileFormat, "log.csv");

}  // namespace

class TestPowerCsv : public QObject {
  Q_OBJECT
 private slots:
  void paper_sample_log() {
    const auto batch = bs::test::parse_with(bs::kPowerCsvFileFormat,
                                            BENCHSCOPE_SOURCE_DIR "/sample_data/paper-2018/power/nuc-current.csv");
    const bs::PowerTrace& t = batch.power_traces.at(0);
    QCOMPARE(t.platform, std::string("NUC"));
    QCOMPARE(*t.supply_voltage_v, 16.0);
    QCOMPARE(t.time_s.size(), std::size_t{1200});
    QCOMPARE(t.provenance.origin, bs::DataOrigin::Reconstructed);
    QVERIFY(channel(t, bs::PowerQuantity::Current));
  }
  void formats_and_units() {
    // Semicolons with decimal commas (European spreadsheet export), BOM, mA.
    auto t = parse("\xEF\xBB\xBFZeit [s];Strom [mA]\n0,0;1500,5\n0,5;1600\n");
    QCOMPARE(t.time_s[1], 0.5);
    QCOMPARE(channel(t, bs::PowerQuantity::Current)->values[0], 1.5005);
    // INA219 logger: millis, shunt drop ignored, bus voltage, mA, mW.
    t = parse("millis,shunt_mV,bus_V,current_mA,power_mW\n1000,1.2,12.1,820,9922\n1100,1.3,12.0,830,9960\n");
    QCOMPARE(t.time_s[1], 0.1 + 0.0 * t.time_s[0]);  // relative to the first sample, ms -> s
    QCOMPARE(channel(t, bs::PowerQuantity::Voltage)->values[0], 12.1);
    QCOMPARE(channel(t, bs::PowerQuantity::Current)->values[1], 0.83);
    QCOMPARE(channel(t, bs::PowerQuantity::Power)->values[0], 9.922);
    QCOMPARE(t.channels.size(), std::size_t{3});
    // Joulescope export: the header is a '#' line.
    t = parse("#time,current,voltage,power\n0.000000,0.512,5.01,2.565\n0.001000,0.514,5.01,2.575\n");
    QCOMPARE(t.time_s[1], 0.001);
    QCOMPARE(channel(t, bs::PowerQuantity::Power)->values[1], 2.575);
    // Otii export.
    t = parse("Timestamp (s),Main current (A),Main voltage (V)\n0,0.25,5.0\n0.1,0.26,5.0\n");
    QCOMPARE(channel(t, bs::PowerQuantity::Current)->values[1], 0.26);
    // Tab separated, CRLF.
    t = parse("t\tI\r\n0\t1.0\r\n1\t2.0\r\n");
    QCOMPARE(t.time_s.size(), std::size_t{2});
  }
  void bad_input_names_line_and_column() {
    std::string big = "time_s,current_A\n";
    for (int i = 0; i < 1232; ++i) big += std::to_string(i) + ",1.0\n";
    big += "1232,abc\n";
    auto e = error_of(big);
    QCOMPARE(e.location().line, std::size_t{1234});
    QCOMPARE(e.location().column, std::size_t{6});
    QVERIFY(std::string(e.what()).starts_with("log.csv:1234:6: current_A: 'abc' is not a number"));
    e = error_of("time_s,current_A\n");
    QCOMPARE(e.category(), bs::ImportErrorCategory::Empty);
    e = error_of("time_s,current_A\n0,1\n2,1\n1,1\n");
    QCOMPARE(e.location().line, std::size_t{4});
    QVERIFY(std::string(e.what()).find("backwards") != std::string::npos);
    e = error_of("time_s,current_A\n-1,1\n");
    QVERIFY(std::string(e.what()).find("negative time") != std::string::npos);
    e = error_of("time_s,current_A\n0,1\n1;2\n");  // mixed separators
    QCOMPARE(e.category(), bs::ImportErrorCategory::Syntax);
    QCOMPARE(e.location().line, std::size_t{3});
    e = error_of("time_s,temperature\n0,20\n");
    QCOMPARE(e.category(), bs::ImportErrorCategory::MissingField);
    e = error_of("time_s,current_A\n0,\n");
    QVERIFY(std::string(e.what()).find("empty cell") != std::string::npos);
  }
  void rfc4180_quoting() {
    // Separators and doubled quotes inside quoted cells; quoted numbers; an ignored quoted column.
    auto t = parse("time_s,\"current, A\",note\n0,\"1.5\",\"a \"\"quoted\"\", text; here\"\n1, \"2.5\" ,plain\n");
    QCOMPARE(t.time_s.size(), std::size_t{2});
    QCOMPARE(t.channels.size(), std::size_t{1});
    QCOMPARE(t.channels[0].name, std::string("current, A"));
    QCOMPARE(t.channels[0].values, (std::vector<double>{1.5, 2.5}));
    // Quoted header and cells with ';' and decimal commas (a spreadsheet's "quote all" export).
    t = parse("\"Zeit [s]\";\"Strom [mA]\"\n\"0,5\";\"1500,5\"\n\"1,0\";\"1600\"\n");
    QCOMPARE(t.time_s[1], 0.5);
    QCOMPARE(t.channels[0].values[0], 1.5005);
    // An unclosed quote and text after a closing quote are errors that name the place.
    auto e = error_of("time_s,current_A\n0,1\n1,\"2\n");
    QCOMPARE(e.category(), bs::ImportErrorCategory::Syntax);
    QVERIFY(std::string(e.what()).starts_with("log.csv:3:3: current_A: quoted cell not closed"));
    e = error_of("time_s,current_A\n0,\"1\"x\n");
    QVERIFY(std::string(e.what()).find("text after the closing quote") != std::string::npos);
  }
  void wall_clock_time_columns() {
    // ISO 8601 with an offset: time_s from the first row, start_time kept as written.
    auto t = parse("timestamp,power_W\n2026-11-22T10:00:01.250+01:00,5\n2026-11-22T10:00:02.000+01:00,6\n");
    QCOMPARE(QString::fromStdString(t.start_time), QStringLiteral("2026-11-22T10:00:01.250+01:00"));
    QCOMPARE(t.time_s[1], 0.75);
    // nvidia-smi's year/month/day with slashes.
    t = parse("timestamp,power_W\n2025/05/05 20:58:44.813,5\n2025/05/05 20:58:45.013,6\n");
    QCOMPARE(QString::fromStdString(t.start_time), QStringLiteral("2025-05-05T20:58:44.813"));
    QVERIFY(std::abs(t.time_s[1] - 0.2) < 1e-6);
    // Month first with dashes (tegrastats' order), across midnight.
    t = parse("date,current_A\n12-31-2026 23:59:59.500,1\n01-01-2027 00:00:00.250,1\n");
    QCOMPARE(QString::fromStdString(t.start_time), QStringLiteral("2026-12-31T23:59:59.500"));
    QVERIFY(std::abs(t.time_s[1] - 0.75) < 1e-6);
    // Otii's wall clock: "(UTC)" is a zone, not a unit; the start time gets its "Z".
    auto b = bs::kPowerCsvFileFormat.parse_text(
        "Wall-clock time (UTC),Main current (A),Main voltage (V)\n"
        "2026-11-22 10:00:01.000,0.1,3.3\n2026-11-22 10:00:01.500,0.2,3.3\n",
        "otii.csv");
    QCOMPARE(QString::fromStdString(b.power_traces[0].start_time), QStringLiteral("2026-11-22 10:00:01.000Z"));
    QCOMPARE(b.power_traces[0].time_s[1], 0.5);
    QCOMPARE(b.power_traces[0].provenance.measurement, bs::MeasurementKind::ExternalMeter);
    QCOMPARE(b.power_traces[0].provenance.sensor, std::string("Otii"));
    // Relative seconds beside a wall clock: time from the seconds, start time from the wall clock.
    t = parse(
        "Timestamp (s),Wall-clock time (UTC),Main current "
        "(A)\n0.5,2026-11-22T10:00:01.5,0.1\n1.0,2026-11-22T10:00:02,0.2\n");
    QCOMPARE(t.time_s[1], 0.5);
    QCOMPARE(QString::fromStdString(t.start_time), QStringLiteral("2026-11-22T10:00:01.5Z"));
    // Unix time in seconds, milliseconds, and nanoseconds beyond a double's 53 bits (read exactly as integers:
    // 1763805601250000001 - 1763805601250000000 = 1 ns survives).
    t = parse("epoch,power_W\n1763805601.25,5\n1763805601.75,5\n");
    QCOMPARE(QString::fromStdString(t.start_time), QStringLiteral("2025-11-22T10:00:01.250Z"));
    QCOMPARE(t.time_s[1], 0.5);
    t = parse("time_ms,power_W\n1763805601250,5\n1763805601750,5\n");
    QCOMPARE(QString::fromStdString(t.start_time), QStringLiteral("2025-11-22T10:00:01.250Z"));
    t = parse(
        "Timestamp (ns),Power Draw (W)\n1763805601250000000,12.84\n1763805601250000001,12.9\n1763805601350000000,13\n");
    QCOMPARE(QString::fromStdString(t.start_time), QStringLiteral("2025-11-22T10:00:01.250Z"));
    QCOMPARE(t.time_s[1], 1e-9);
    QVERIFY(std::abs(t.time_s[2] - 0.1) < 1e-12);
    // A small relative time is not a Unix time.
    QVERIFY(parse("time_s,power_W\n12.5,1\n13,1\n").start_time.empty());
  }
  void repeated_and_decreasing_times() {
    // Equal times: kept, and a warning says where (a sample of zero width adds nothing to the energy).
    const auto b = bs::kPowerCsvFileFormat.parse_text("time_s,power_W\n0,1\n1,1\n1,2\n1,3\n2,1\n", "log.csv");
    QCOMPARE(b.power_traces[0].time_s.size(), std::size_t{5});
    QVERIFY(any_line_contains(b.warnings, "log.csv:4: 2 rows repeat the previous row's time"));
    // Decreasing date-times: an error naming the line.
    const auto e = error_of("timestamp,power_W\n2026-11-22T10:00:01,1\n2026-11-22T10:00:03,1\n2026-11-22T10:00:02,1\n");
    QCOMPARE(e.category(), bs::ImportErrorCategory::InvalidValue);
    QCOMPARE(e.location().line, std::size_t{4});
    QVERIFY(std::string(e.what()).find("time goes backwards (1.000000 s after 2.000000 s") != std::string::npos);
    // A time of day without a date is neither a number nor a date-time.
    QVERIFY(std::string(error_of("time,power_W\n12:00:01,1\n").what()).find("neither a number nor a date-time") !=
            std::string::npos);
  }
  void everyday_headers() {
    // "sec,mw" (a minimal logger): mW -> W.
    auto t = parse("sec,mw\n0,1500\n1,1700\n");
    QCOMPARE(t.channels[0].quantity, bs::PowerQuantity::Power);
    QCOMPARE(t.channels[0].values[1], 1.7);
    // A total beside per-node columns: each is a channel, the total is named.
    auto b = bs::kPowerCsvFileFormat.parse_text("time_s,node1_watts,node2_watts,total_watts\n0,10,20,30\n1,11,21,32\n",
                                                "nodes.csv");
    t = b.power_traces[0];
    QCOMPARE(t.channels.size(), std::size_t{3});
    QCOMPARE(t.total_channel, std::string("total_watts"));
    QVERIFY(any_line_contains(b.warnings, "statistics use 'total_watts' (named as the total)"));
    // Several power columns and no total: none named, and a warning says which one the statistics use.
    b = bs::kPowerCsvFileFormat.parse_text("time_s,GPU0 Power (W),GPU1 Power (W)\n0,100,120\n1,110,130\n", "gpus.csv");
    QVERIFY(b.power_traces[0].total_channel.empty());
    QVERIFY(any_line_contains(b.warnings,
                              "2 power columns ('GPU0 Power (W)', 'GPU1 Power (W)') and none named total/sum/package: "
                              "statistics use 'GPU0 Power (W)' (the first)"));
    // jtop-style "Power TOT" as a whole word; "summary" is not a sum.
    QCOMPARE(parse("time_s,Power CPU,Power TOT\n0,1,5\n").total_channel, std::string("Power TOT"));
    // nvidia-smi-like columns: the power limit is a setting, not a sample; an empty cell is a missing sample.
    b = bs::kPowerCsvFileFormat.parse_text(
        "timestamp,power.draw [W],power.limit [W],current_A\n0,50,250,\n1,,250,4\n2,52,,4.1\n", "smi.csv");
    t = b.power_traces[0];
    QCOMPARE(t.channels.size(), std::size_t{2});
    QVERIFY(named(t, "power.draw [W]"));
    QVERIFY(std::isnan(named(t, "power.draw [W]")->values[1]));
    QVERIFY(std::isnan(named(t, "current_A")->values[0]));
    QCOMPARE(named(t, "current_A")->values[2], 4.1);
    QVERIFY(any_line_contains(b.warnings,
                              "smi.csv:3: 'power.draw [W]': 1 of 3 cells empty or N/A, kept as missing samples"));
    QVERIFY(any_line_contains(b.warnings, "'power.limit [W]' (3)"));
    // N/A as nvidia-smi writes it is missing too; a column that is empty throughout is dropped.
    b = bs::kPowerCsvFileFormat.parse_text("time_s,CPU Power (W),GPU Power (W)\n0,,[N/A]\n1,,200\n", "perf.csv");
    QCOMPARE(b.power_traces[0].channels.size(), std::size_t{1});
    QCOMPARE(b.power_traces[0].channels[0].name, std::string("GPU Power (W)"));
    QVERIFY(any_line_contains(b.warnings, "columns with no value in any row, not kept: 'CPU Power (W)'"));
  }
  void provenance_of_meters() {
    // Joulescope's '#' header: an external meter, named.
    auto t = parse("#time,current,voltage,power\n0,0.5,5,2.5\n");
    QCOMPARE(t.provenance.measurement, bs::MeasurementKind::ExternalMeter);
    QCOMPARE(t.provenance.sensor, std::string("Joulescope"));
    // A comment naming the meter.
    t = parse("# meter: Keysight N6705C\ntime_s,current_A,voltage_V\n0,1,12\n");
    QCOMPARE(t.provenance.measurement, bs::MeasurementKind::ExternalMeter);
    QCOMPARE(t.provenance.sensor, std::string("Keysight N6705C"));
    t = parse("# measurement: on-board sensor\n# sensor: INA3221 VDD_IN\ntime_s,power_mW\n0,1\n");
    QCOMPARE(t.provenance.measurement, bs::MeasurementKind::OnBoardSensor);
    QCOMPARE(t.provenance.sensor, std::string("INA3221 VDD_IN"));
    // No hint: unknown, and no sensor invented.
    t = parse("time_s,current_A\n0,1\n");
    QCOMPARE(t.provenance.measurement, bs::MeasurementKind::Unknown);
    QVERIFY(t.provenance.sensor.empty());
  }
  void sniffing() {
    const bs::FormatImporter imp(bs::kPowerCsvFileFormat);
    QVERIFY(imp.sniff("time_s,current_A\n0,1\n", "x.txt") > 0);
    QVERIFY(imp.sniff("# a comment\n#time,current,voltage,power\n", "x") > 0);
    QCOMPARE(imp.sniff("name,value\na,1\n", "x.csv"), 0);
    QCOMPARE(imp.sniff("{\"format\": \"benchscope-run\"}", "x.csv"), 0);
  }

  void a_last_line_cut_inside_its_number_is_left_out() {
    // Issue #43.7: cut after "162.4,3." the last row parses (3 A) although the logger was writing 3.0611. A last
    // line without its line ending may be cut wherever: it is left out, and the warning names file, line and text.
    // (These current-only logs also get the warning that their power stays unknown: only the cut line's is looked at.)
    const auto cut_warnings = [](const bs::ImportBatch& b) {
      std::vector<std::string> out;
      for (const std::string& w : b.warnings)
        if (w.find("no line ending") != std::string::npos) out.push_back(w);
      return out;
    };
    const std::string head = "time_s,current_A\n0.0,2.9000\n0.2,3.0100\n";
    const bs::ImportBatch b = bs::kPowerCsvFileFormat.parse_text(head + "0.4,3.", "meter.csv");
    const bs::PowerTrace& t = b.power_traces.at(0);
    QCOMPARE(t.time_s.size(), std::size_t{2});
    QCOMPARE(t.channels.at(0).values.back(), 3.01);
    const auto cut = cut_warnings(b);
    QCOMPARE(cut.size(), std::size_t{1});
    QVERIFY2(cut[0].rfind("meter.csv:4: ", 0) == 0 && cut[0].find("\"0.4,3.\"") != std::string::npos, cut[0].c_str());
    // Ended properly, the same row is a row.
    const bs::ImportBatch ended = bs::kPowerCsvFileFormat.parse_text(head + "0.4,3.\n", "meter.csv");
    QCOMPARE(ended.power_traces.at(0).time_s.size(), std::size_t{3});
    QVERIFY(cut_warnings(ended).empty());
    // The only data row without its line ending is read, and the warning says to check it.
    const bs::ImportBatch one = bs::kPowerCsvFileFormat.parse_text("time_s,current_A\n0.0,2.9", "one.csv");
    QCOMPARE(one.power_traces.at(0).time_s.size(), std::size_t{1});
    const auto only = cut_warnings(one);
    QCOMPARE(only.size(), std::size_t{1});
    QVERIFY2(only[0].find("check its last value") != std::string::npos, only[0].c_str());
    // A comment last, without a line ending, carries no number: nothing to say about it.
    QVERIFY(cut_warnings(bs::kPowerCsvFileFormat.parse_text(head + "# end", "meter.csv")).empty());
  }

  void cut_off_last_line_imports_the_complete_rows() {
    // Issue #32.8: a logger killed while writing leaves a last line without its line ending, cut mid-row. The
    // complete rows are imported and a warning names the line left out; the same bad row WITH a line ending (or
    // no complete row before it) is still an error.
    QFile f(BENCHSCOPE_SOURCE_DIR "/tests/data/power/otii-export.csv");
    QVERIFY(f.open(QIODevice::ReadOnly));
    const std::string whole = f.readAll().toStdString();
    const std::size_t cut_at = whole.find("0.005000,0.089") + std::string("0.005000,0.089").size();
    const std::string cut = whole.substr(0, cut_at);  // "...\n0.005000,0.089": the voltage cell never written
    const bs::ImportBatch b = bs::kPowerCsvFileFormat.parse_text(cut, "otii-cut.csv");
    const bs::PowerTrace& t = b.power_traces.at(0);
    QCOMPARE(t.time_s.size(), std::size_t{7});  // rows 2..8 of the file
    for (const bs::PowerChannel& c : t.channels) QCOMPARE(c.values.size(), std::size_t{7});
    QCOMPARE(t.time_s.back(), 0.004);
    bool named = false;
    for (const std::string& w : b.warnings)
      named = named || (w.find("otii-cut.csv:9:") == 0 && w.find("cut off") != std::string::npos &&
                        w.find("7 complete rows") != std::string::npos);
    QVERIFY(named);
    // With its line ending the short row is a real error, not a cut.
    QVERIFY_THROWS_EXCEPTION(bs::ImportError, bs::kPowerCsvFileFormat.parse_text(cut + "\n", "otii-short.csv"));
    // Nothing complete before the cut: an error.
    const std::string header_only = whole.substr(0, whole.find('\n') + 1) + "0.000000,0.08";
    QVERIFY_THROWS_EXCEPTION(bs::ImportError, bs::kPowerCsvFileFormat.parse_text(header_only, "otii-empty.csv"));
  }
};

QTEST_APPLESS_MAIN(TestPowerCsv)
#include "test_power_csv.moc"
