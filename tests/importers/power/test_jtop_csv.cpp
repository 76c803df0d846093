// SPDX-License-Identifier: GPL-3.0-or-later
// jetson-stats (jtop) CSV: the logger's quoting and time formats, the total, settings, and the rules for broken logs.
#include <QTest>

#include <cmath>

#include "common/importer.h"
#include "power/jtop_csv.h"
#include "power/power_csv.h"

#include "../../support/import_errors.h"

namespace {

// As examples/jtop_logger.py writes it (csv.DictWriter: "\r\n", the uptime quoted for its comma).
const std::string kHeader =
    "time,uptime,CPU1,CPU2,RAM,GPU,Temp cpu,Temp cv0,Power VDD_IN,Power VDD_CPU_GPU_CV,Power VDD_SOC,Power TOT,"
    "jetson_clocks,nvp model\r\n";

std::string row(const std::string& time, const std::string& uptime, int in, int cpu_gpu, int soc, int tot,
                const std::string& clocks = "OFF", const std::string& nvp = "MAXN") {
  return time + ",\"" + uptime + "\",5,OFF,0.25,26.7,44.6,-256," + std::to_string(in) + "," + std::to_string(cpu_gpu) +
         "," + std::to_string(soc) + "," + std::to_string(tot) + "," + clocks + "," + nvp + "\r\n";
}

const auto error_of = bs::test::import_errors_of(bs::kJtopCsvFileFormat, "j.csv");

}  // namespace

class TestJtopCsv : public QObject {
  Q_OBJECT
 private slots:
  void reads_times_total_rails_and_settings() {
    const std::string text = kHeader +
                             row("2024-03-01 10:00:00.250000", "1 day, 2:03:04.500000", 5000, 1500, 1200, 5000) +
                             row("2024-03-01 10:00:01.250000", "1 day, 2:03:05.500000", 7000, 3000, 1300, 7000) +
                             row("2024-03-01 10:00:02", "1 day, 2:03:06.250000", 6500, 2500, 1250, 6500);
    const auto b = bs::kJtopCsvFileFormat.parse_text(text, "j.csv");
    const bs::PowerTrace& t = b.power_traces.at(0);
    QCOMPARE(t.total_channel, std::string("Power TOT"));
    QCOMPARE(t.channels.front().name, std::string("Power TOT"));  // the total first
    QCOMPARE(t.channels.size(), std::size_t{4});  // TOT, VDD_IN, VDD_CPU_GPU_CV, VDD_SOC: temperatures are not power
    QCOMPARE(t.channels[0].values[1], 7.0);
    QCOMPARE(t.channels[2].values[1], 3.0);
    QCOMPARE(t.time_s[1], 1.0);
    QCOMPARE(t.time_s[2], 1.75);  // "10:00:02" without microseconds (str(datetime) drops them when zero)
    QCOMPARE(t.start_time, std::string("2024-03-01T10:00:00.250"));
    const std::vector<std::pair<std::string, std::string>> settings{{"jetson_clocks", "OFF"}, {"nvp model", "MAXN"}};
    QCOMPARE(t.provenance.settings, settings);
    QVERIFY(b.warnings.empty());
  }
  void uptime_when_there_is_no_time_column() {
    const std::string text =
        "uptime,Power TOT,nvp model\n\"3 days, 0:07:35.540000\",3852,15W\n"
        "\"3 days, 0:07:36.040000\",3900,15W\n23:59:59,1,15W\n";
    // The third row's uptime (23:59:59, a fresh boot?) is before the first: time goes backwards.
    const auto e = error_of(text);
    QCOMPARE(e.location().line, std::size_t{4});
    QCOMPARE(e.location().field, std::string("uptime"));
    const auto b = bs::kJtopCsvFileFormat.parse_text(
        "uptime,Power TOT,nvp model\n\"3 days, 0:07:35.540000\",3852,15W\n"
        "\"3 days, 0:07:36.040000\",3900,15W\n",
        "j.csv");
    QVERIFY(std::abs(b.power_traces.at(0).time_s[1] - 0.5) < 1e-9);
    QVERIFY(b.power_traces.at(0).start_time.empty());
  }
  void settings_that_change_are_kept_and_warned() {
    const std::string text = kHeader + row("2024-03-01 10:00:00", "0:01:00", 5000, 1, 1, 5000, "OFF", "15W") +
                             row("2024-03-01 10:00:01", "0:01:01", 9000, 1, 1, 9000, "ON", "MAXN");
    const auto b = bs::kJtopCsvFileFormat.parse_text(text, "j.csv");
    const auto& s = b.power_traces.at(0).provenance.settings;
    QCOMPARE(s.at(0).second, std::string("OFF then ON"));
    QCOMPARE(s.at(1).second, std::string("15W then MAXN"));
    QCOMPARE(b.warnings.size(), std::size_t{2});
    QVERIFY(b.warnings[0].find("j.csv:3: jetson_clocks changed from 'OFF' to 'ON'") != std::string::npos);
  }
  void empty_power_cell_is_a_missing_sample() {
    std::string text = kHeader + row("2024-03-01 10:00:00", "0:01:00", 5000, 1, 1, 5000);
    text += "2024-03-01 10:00:01,\"0:01:01\",5,OFF,0.25,26.7,44.6,-256,5000,,1,5000,OFF,MAXN\r\n";
    const auto b = bs::kJtopCsvFileFormat.parse_text(text, "j.csv");
    QVERIFY(std::isnan(b.power_traces.at(0).channels[2].values[1]));
    QCOMPARE(b.power_traces.at(0).channels[0].values[1], 5.0);
    QCOMPARE(b.warnings.size(), std::size_t{1});
    QVERIFY(b.warnings[0].find("j.csv:3: 'Power VDD_CPU_GPU_CV' is empty") != std::string::npos);
  }
  void broken_logs() {
    // A huge value: a clear error at its line and column, never a mean of 1e17 W.
    auto e = error_of(
        kHeader + row("2024-03-01 10:00:00", "0:01:00", 5000, 1, 1, 5000) +
        "2024-03-01 10:00:01,\"0:01:01\",5,OFF,0.25,26.7,44.6,-256,5000,1,1,99999999999999999999,OFF,MAXN\r\n");
    QCOMPARE(e.category(), bs::ImportErrorCategory::InvalidValue);
    QCOMPARE(e.location().line, std::size_t{3});
    QCOMPARE(e.location().field, std::string("Power TOT"));
    QVERIFY(std::string(e.what()).find("between -2 W and 1 kW") != std::string::npos);
    // Text in a power cell.
    e = error_of(kHeader + "2024-03-01 10:00:00,\"0:01:00\",5,OFF,0.25,26.7,44.6,-256,5000,1,1,OFF,OFF,MAXN\r\n" +
                 row("2024-03-01 10:00:01", "0:01:01", 1, 1, 1, 1));
    QCOMPARE(e.location().line, std::size_t{2});
    QCOMPARE(e.location().field, std::string("Power TOT"));
    // A row with a cell too many in the middle; a cut-off last row is skipped.
    e = error_of(kHeader + row("2024-03-01 10:00:00", "0:01:00", 1, 1, 1, 1) +
                 "2024-03-01 10:00:01,\"0:01:01\",5,OFF,0.25,26.7,44.6,-256,1,1,1,1,OFF,MAXN,extra\r\n" +
                 row("2024-03-01 10:00:02", "0:01:02", 1, 1, 1, 1));
    QCOMPARE(e.category(), bs::ImportErrorCategory::Syntax);
    QCOMPARE(e.location().line, std::size_t{3});
    const auto cut = bs::kJtopCsvFileFormat.parse_text(
        kHeader + row("2024-03-01 10:00:00", "0:01:00", 1, 1, 1, 1) + "2024-03-01 10:00:01,\"0:0", "j.csv");
    QCOMPARE(cut.power_traces.at(0).time_s.size(), std::size_t{1});
    QVERIFY(cut.warnings.at(0).find("j.csv:3: cut-off last row") != std::string::npos);
    // No total, no time, a bad date, time backwards, a header without rows.
    e = error_of("time,uptime,Power VDD_IN,nvp model\n2024-03-01 10:00:00,0:01:00,1,MAXN\n");
    QCOMPARE(e.category(), bs::ImportErrorCategory::MissingField);
    QCOMPARE(e.location().field, std::string("Power TOT"));
    e = error_of("CPU1,Power TOT\n1,1\n");
    QCOMPARE(e.location().field, std::string("time"));
    e = error_of("time,Power TOT,nvp model\n03/01/2024 10:00,1,MAXN\n2024-03-01 10:00:00,1,MAXN\n");
    QCOMPARE(e.location().line, std::size_t{2});
    QCOMPARE(e.location().field, std::string("time"));
    e = error_of(
        "time,Power TOT,nvp model\n2024-03-01 10:00:05,1,MAXN\n2024-03-01 10:00:04,1,MAXN\n2024-03-01 "
        "10:00:06,1,MAXN\n");
    QVERIFY(std::string(e.what()).find("backwards") != std::string::npos);
    e = error_of(kHeader);
    QCOMPARE(e.category(), bs::ImportErrorCategory::MissingField);
  }
  void sniffing_beats_power_csv_on_jtop_files() {
    const std::string head = kHeader + row("2024-03-01 10:00:00", "0:01:00", 1, 1, 1, 1);
    const int jtop = bs::FormatImporter(bs::kJtopCsvFileFormat).sniff(head, "log.csv");
    QCOMPARE(jtop, 95);
    QVERIFY(jtop > bs::FormatImporter(bs::kPowerCsvFileFormat).sniff(head, "log.csv"));
    QCOMPARE(bs::FormatImporter(bs::kJtopCsvFileFormat).sniff("time_s,power_W\n0,1\n", "x.csv"), 0);
    QCOMPARE(bs::FormatImporter(bs::kJtopCsvFileFormat).sniff("RAM 1/2MB VDD_IN 1/1\n", "x.log"), 0);
  }
};

QTEST_APPLESS_MAIN(TestJtopCsv)
#include "test_jtop_csv.moc"
