// SPDX-License-Identifier: GPL-3.0-or-later
// Bad power logs: each one an ImportError with the right category and file:line:column in its message. The files
// of tests/data/power/bad/ are checked from tests/data/bad/manifest.json by test_bad_corpus; here, texts, and the
// manifest entries marked "importer": "power-csv" against that importer itself.
#include <QTest>
#include <fstream>
#include <nlohmann/json.hpp>

#include "../../support/import_errors.h"
#include "power/power_csv.h"
#include "workspace/registry.h"

const auto parse_error = bs::test::import_errors_of(bs::kPowerCsvFileFormat, "log.csv");

class TestPowerBadInput : public QObject {
  Q_OBJECT
 private slots:
  void manifest_entries_of_the_power_csv_importer() {
    // tests/data/bad/manifest.json entries marked "importer": "power-csv": rejected by that importer (not merely
    // by sniffing), with the manifest's text in the reason and a line number.
    std::ifstream in(BENCHSCOPE_TEST_DATA_DIR "/bad/manifest.json");
    const auto manifest = nlohmann::json::parse(in);
    int checked = 0;
    for (const auto& entry : manifest.at("files")) {
      if (entry.value("importer", "") != "power-csv") continue;
      const std::string path = std::string(BENCHSCOPE_TEST_DATA_DIR "/") + entry.at("file").get<std::string>();
      const bs::ImportError e = bs::test::import_error_of([&] { return bs::import_file(path, bs::CancelToken{}); });
      const std::string what = e.what();
      QVERIFY2(std::string(bs::to_string(e.category())) == entry.at("category").get<std::string>(), what.c_str());
      for (const std::string& text : entry.at("contains").is_string()
                                         ? std::vector<std::string>{entry.at("contains").get<std::string>()}
                                         : entry.at("contains").get<std::vector<std::string>>())
        QVERIFY2(what.find(text) != std::string::npos, what.c_str());
      QVERIFY2(e.location().line > 0, what.c_str());
      try {
        bs::kPowerCsvFileFormat.parse(path, {}, {}, bs::CancelToken{});
        QFAIL(qPrintable(QString::fromStdString(path) + " was accepted by the power CSV importer"));
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
    limits.max_power_rows = 3;  // the meter CSV's own row limit (100M-row logs are allowed by default)
    try {
      bs::kPowerCsvFileFormat.parse_text("time_s,current_A\n0,1\n1,1\n2,1\n3,1\n", "log.csv", {}, limits);
      QFAIL("accepted more rows than the limit");
    } catch (const bs::ImportError& e) {
      QCOMPARE(e.category(), bs::ImportErrorCategory::TooLarge);
      QCOMPARE(e.location().line, std::size_t{5});
    }
    const std::string long_line = "time_s,current_A\n0," + std::string(std::size_t{1} << 21, '1') + "\n";
    try {
      bs::kPowerCsvFileFormat.parse_text(long_line, "log.csv");
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
    QVERIFY_THROWS_EXCEPTION(bs::Cancelled, bs::kPowerCsvFileFormat.parse_text(text, "log.csv", {}, {}, token));
  }
};

QTEST_APPLESS_MAIN(TestPowerBadInput)
#include "test_power_bad_input.moc"
