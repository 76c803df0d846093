// SPDX-License-Identifier: GPL-3.0-or-later
// Bad power logs: each one an ImportError with the right category and file:line:column in its message.
#include <QTest>
#include <fstream>
#include <nlohmann/json.hpp>

#include "importer.h"
#include "power_csv.h"

namespace {

const std::string kBad = BENCHSCOPE_TEST_DATA_DIR "/power/bad/";

bs::ImportError import_error(const std::string& path) {
  try {
    bs::import_file(path, bs::CancelToken{});
  } catch (const bs::ImportError& e) {
    return e;
  }
  return bs::ImportError(bs::ImportErrorCategory::Io, {}, "no error");
}

bs::ImportError parse_error(const std::string& text) {
  try {
    bs::parse_power_csv(text, "log.csv");
  } catch (const bs::ImportError& e) {
    return e;
  }
  return bs::ImportError(bs::ImportErrorCategory::Io, {}, "no error");
}

}  // namespace

class TestPowerBadInput : public QObject {
  Q_OBJECT
 private slots:
  void corpus_data() {
    QTest::addColumn<QString>("file");
    QTest::addColumn<int>("category");
    QTest::addColumn<QString>("where");  // the "file:line:column" prefix (or the file alone for whole-file problems)
    QTest::addColumn<QString>("reason");
    using C = bs::ImportErrorCategory;
    QTest::newRow("empty") << "empty.csv" << int(C::Empty) << "empty.csv: " << "empty";
    QTest::newRow("header only") << "header-only.csv" << int(C::Empty) << "header-only.csv:1: " << "no data rows";
    QTest::newRow("mixed separators") << "mixed-separators.csv" << int(C::Syntax) << "mixed-separators.csv:3:1: "
                                      << "mixed separators";
    QTest::newRow("negative time") << "negative-time.csv" << int(C::InvalidValue) << "negative-time.csv:3:1: "
                                   << "negative time";
    QTest::newRow("missing time") << "missing-time.csv" << int(C::InvalidValue) << "missing-time.csv:3:1: "
                                  << "missing time";
    QTest::newRow("time backwards") << "time-backwards.csv" << int(C::InvalidValue) << "time-backwards.csv:5: "
                                    << "time goes backwards";
    QTest::newRow("utf-16") << "utf16.csv" << int(C::Encoding) << "utf16.csv: " << "UTF-16";
    QTest::newRow("binary") << "binary.bin" << int(C::Binary) << "binary.bin: " << "binary";
    QTest::newRow("unknown unit") << "unknown-unit.csv" << int(C::Unsupported) << "unknown-unit.csv:1:8: "
                                  << "unit 'furlongs'";
  }
  void corpus() {
    QFETCH(QString, file);
    QFETCH(int, category);
    QFETCH(QString, where);
    QFETCH(QString, reason);
    const bs::ImportError e = import_error(kBad + file.toStdString());
    const QString what = QString::fromStdString(e.what());
    QVERIFY2(int(e.category()) == category, qPrintable(what));
    QVERIFY2(what.startsWith(QString::fromStdString(kBad) + where), qPrintable(what));
    QVERIFY2(what.contains(reason), qPrintable(what));
  }
  void manifest_entries_of_the_power_csv_importer() {
    // tests/data/bad/manifest.json entries marked "importer": "power-csv": rejected by that importer (not merely
    // by sniffing), with the manifest's text in the reason and a line number.
    std::ifstream in(BENCHSCOPE_TEST_DATA_DIR "/bad/manifest.json");
    const auto manifest = nlohmann::json::parse(in);
    int checked = 0;
    for (const auto& entry : manifest.at("files")) {
      if (entry.value("importer", "") != "power-csv") continue;
      const std::string path = std::string(BENCHSCOPE_TEST_DATA_DIR "/") + entry.at("file").get<std::string>();
      const bs::ImportError e = import_error(path);
      const std::string what = e.what();
      QVERIFY2(std::string(bs::to_string(e.category())) == entry.at("category").get<std::string>(), what.c_str());
      QVERIFY2(what.find(entry.at("contains").get<std::string>()) != std::string::npos, what.c_str());
      QVERIFY2(e.location().line > 0, what.c_str());
      try {
        bs::read_power_csv(path);
        QFAIL(qPrintable(QString::fromStdString(path) + " was accepted by read_power_csv"));
      } catch (const bs::ImportError&) {
      }
      ++checked;
    }
    QVERIFY(checked >= 5);
  }
  void non_numeric_cell_at_line_1234() {
    std::string text = "# platform: NUC\n# supply_voltage_V: 16\ntime_s,current_A,voltage_V\n";
    for (int line = 4; line < 1234; ++line) text += std::to_string(line * 0.1) + ",2.5,16.0\n";
    text += "123.4,2.5,16.O\n";  // a letter O typed for a zero
    const bs::ImportError e = parse_error(text);
    QCOMPARE(e.category(), bs::ImportErrorCategory::InvalidValue);
    QCOMPARE(e.location().line, std::size_t{1234});
    QCOMPARE(e.location().column, std::size_t{11});
    QCOMPARE(std::string(e.what()), std::string("log.csv:1234:11: voltage_V: '16.O' is not a number"));
  }
  void rows_that_do_not_fit_the_header() {
    auto e = parse_error("time_s,current_A,voltage_V\n0,1,16\n1,1\n");
    QCOMPARE(e.category(), bs::ImportErrorCategory::Syntax);
    QVERIFY(std::string(e.what()).starts_with("log.csv:3:4: voltage_V: row has 2 cells, the header 3"));
    e = parse_error("time_s,current_A\n0,1\n1,1,7\n");
    QVERIFY(std::string(e.what()).starts_with("log.csv:3:5: row has more cells"));
    e = parse_error("time_s;current_A\n0;1\n1,5,2\n");  // a comma row in a semicolon file
    QCOMPARE(e.category(), bs::ImportErrorCategory::Syntax);
    QVERIFY(std::string(e.what()).find("mixed separators") != std::string::npos);
  }
  void headers_without_what_is_needed() {
    auto e = parse_error("current_A,voltage_V\n1,16\n");
    QCOMPARE(e.category(), bs::ImportErrorCategory::MissingField);
    QVERIFY(std::string(e.what()).starts_with("log.csv:1:1: header: no time column"));
    e = parse_error("time_s,temperature_C\n0,40\n");
    QVERIFY(std::string(e.what()).find("no current or power column") != std::string::npos);
    e = parse_error("# only a comment\n");
    QCOMPARE(e.category(), bs::ImportErrorCategory::Empty);
    e = parse_error("time_s,current_A\n0,inf\n");
    QVERIFY(std::string(e.what()).find("'inf' is not a number") != std::string::npos);
    e = parse_error("# supply_voltage_V: -3\ntime_s,current_A\n0,1\n");
    QCOMPARE(e.category(), bs::ImportErrorCategory::InvalidValue);
  }
  void documented_limits() {
    bs::ImportLimits limits;
    limits.max_samples = 3;
    try {
      bs::parse_power_csv("time_s,current_A\n0,1\n1,1\n2,1\n3,1\n", "log.csv", bs::CancelToken{}, {}, limits);
      QFAIL("accepted more rows than the limit");
    } catch (const bs::ImportError& e) {
      QCOMPARE(e.category(), bs::ImportErrorCategory::TooLarge);
      QCOMPARE(e.location().line, std::size_t{5});
    }
    const std::string long_line = "time_s,current_A\n0," + std::string(std::size_t{1} << 21, '1') + "\n";
    try {
      bs::parse_power_csv(long_line, "log.csv");
      QFAIL("accepted a 2 MiB line");
    } catch (const bs::ImportError& e) {
      QCOMPARE(e.category(), bs::ImportErrorCategory::TooLarge);
      QCOMPARE(e.location().line, std::size_t{2});
    }
  }
  void cancel() {
    bs::CancelToken token;
    token.cancel();
    std::string text = "time_s,current_A\n";
    for (int k = 0; k < 5000; ++k) text += std::to_string(k) + ",1\n";
    QVERIFY_THROWS_EXCEPTION(bs::Cancelled, bs::parse_power_csv(text, "log.csv", token));
  }
};

QTEST_APPLESS_MAIN(TestPowerBadInput)
#include "test_power_bad_input.moc"
