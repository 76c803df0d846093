// SPDX-License-Identifier: GPL-3.0-or-later
#include <QTest>

#include "power_csv.h"

#include "../support/import_errors.h"

namespace {

bs::PowerTrace parse(const std::string& text) {
  auto batch = bs::parse_power_csv(text, "log.csv");
  return std::move(batch.power_traces.at(0));
}

const bs::PowerChannel* channel(const bs::PowerTrace& t, bs::PowerQuantity q) {
  for (const auto& c : t.channels)
    if (c.quantity == q) return &c;
  return nullptr;
}

bs::ImportError error_of(const std::string& text) {
  return bs::test::import_error_of([&] { return bs::parse_power_csv(text, "log.csv"); });
}

}  // namespace

class TestPowerCsv : public QObject {
  Q_OBJECT
 private slots:
  void paper_sample_log() {
    const bs::CancelToken cancel;
    const auto batch = bs::PowerCsvImporter().parse(BENCHSCOPE_SOURCE_DIR "/sample_data/paper-2018/power/nuc-current.csv", {}, cancel);
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
  void sniffing() {
    const bs::PowerCsvImporter imp;
    QVERIFY(imp.sniff("time_s,current_A\n0,1\n", "x.txt") > 0);
    QVERIFY(imp.sniff("# a comment\n#time,current,voltage,power\n", "x") > 0);
    QCOMPARE(imp.sniff("name,value\na,1\n", "x.csv"), 0);
    QCOMPARE(imp.sniff("{\"format\": \"benchscope-run\"}", "x.csv"), 0);
  }
};

QTEST_APPLESS_MAIN(TestPowerCsv)
#include "test_power_csv.moc"
