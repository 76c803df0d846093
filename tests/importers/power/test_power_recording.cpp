// SPDX-License-Identifier: GPL-3.0-or-later
// BenchScope's own power recordings read back: provenance (on-board sensor, sensor, host, start), total channel,
// phases; what a recorder wrote is what the importer returns.
#include <QTest>

#include <sstream>

#include "analysis/power/phase_energy.h"
#include "power/power_import.h"
#include "power/power_recording.h"
#include "sensors/recording_csv.h"
#include "workspace/registry.h"

using namespace bs;

class TestPowerRecording : public QObject {
  Q_OBJECT
 private slots:
  void fixture_file() {
    const std::string path = BENCHSCOPE_TEST_DATA_DIR "/power/recording/nano-fixture.csv";
    const ImportBatch batch = import_file(path, CancelToken{});
    QCOMPARE(batch.format, std::string("benchscope-power-recording"));
    const PowerTrace& t = batch.power_traces.at(0);
    QCOMPARE(t.channels.size(), std::size_t{3});
    QCOMPARE(t.channels[0].name, std::string("POM_5V_IN"));
    QCOMPARE(t.total_channel, std::string("POM_5V_IN"));
    QCOMPARE(t.platform, std::string("jetson-nano"));
    QCOMPARE(t.start_time, std::string("2026-11-23T18:30:00.125Z"));
    QCOMPARE(t.provenance.measurement, MeasurementKind::OnBoardSensor);
    QCOMPARE(t.provenance.sensor, std::string("ina3221 POM_5V_IN (ina3221:6-0040:POM_5V_IN)"));
    QCOMPARE(t.provenance.host, std::string("jetson-nano"));
    QCOMPARE(t.provenance.settings.size(), std::size_t{4});
    QCOMPARE(t.provenance.settings[2].second, std::string("100 ms"));
    QCOMPARE(t.phases.size(), std::size_t{2});
    QCOMPARE(t.phases[1].name, std::string("point W=64 D=4"));
    QCOMPARE(t.phases[1].start_s, 0.15);
    const auto e = phase_energies(t);
    // warm-up 0..0.15 s: 3.96 W for 0.1 s = 0.396 J, then 0.1..0.15 from 3.96 to 4.56 W (halfway to 5.16):
    // (3.96 + 4.56) / 2 x 0.05 = 0.213 J; 0.609 J in all.
    QVERIFY(std::abs(e[0].energy_j - 0.609) < 1e-12);
    // point 0.15..0.35: 0.15..0.2 (4.56 + 5.16) / 2 x 0.05 = 0.243; 0.2..0.3 5.16 x 0.1 = 0.516;
    // 0.3..0.35 (5.16 + 4.56) / 2 x 0.05 = 0.243: 1.002 J over 0.2 s = 5.01 W.
    QVERIFY(std::abs(e[1].energy_j - 1.002) < 1e-12);
    QVERIFY(std::abs(e[1].mean_power_w - 5.01) < 1e-12);
    // `benchscope-cli power FILE` reads it through the power-log entry point too.
    QCOMPARE(import_power_log(path, {}).power_traces.at(0).provenance.measurement, MeasurementKind::OnBoardSensor);
  }

  void round_trip_of_what_the_recorder_writes() {
    PowerTrace t;
    t.platform = "robot-nuc";
    t.label = "run flops";
    t.start_time = "2026-11-23T10:00:00Z";
    t.time_s = {0, 0.1, 0.2};
    t.channels = {{"package-0", PowerQuantity::Power, {12.5, 13.0, NAN}},
                  {"package-0 core", PowerQuantity::Power, {8.25, 9.0, 9.5}}};
    t.total_channel = "package-0";
    t.phases = {{"point W=64 D=4", 0.05, 0.15}};
    t.provenance.measurement = MeasurementKind::OnBoardSensor;
    t.provenance.sensor = "rapl package-0 (rapl:package-0)";
    t.provenance.host = "robot-nuc";
    t.provenance.settings = {{"sensor kind", "rapl"}};
    std::ostringstream csv;
    sensors::write_recording_csv(csv, t);
    const ImportBatch b = kPowerRecordingFileFormat.parse_text(csv.str(), "mem.csv");
    const PowerTrace& r = b.power_traces.at(0);
    QCOMPARE(r.time_s.size(), std::size_t{2});  // the row with a failed read is left out, and said so
    QCOMPARE(b.warnings.size(), std::size_t{1});
    QCOMPARE(r.channels[1].name, std::string("package-0 core"));
    QCOMPARE(r.channels[1].values[1], 9.0);
    QCOMPARE(r.total_channel, std::string("package-0"));
    QCOMPARE(r.phases.at(0).end_s, 0.15);
    QCOMPARE(r.provenance.sensor, t.provenance.sensor);
    QCOMPARE(r.start_time, t.start_time);
  }

  void errors_name_the_line() {
    const std::string head = std::string(sensors::kRecordingMagic) + "\n# measurement: on-board sensor\n";
    try {
      kPowerRecordingFileFormat.parse_text(head + "# phase: x = 1 .. oops\ntime_s,a power (W)\n0,1\n", "p.csv");
      QFAIL("accepted a bad phase");
    } catch (const ImportError& e) {
      QCOMPARE(e.location().line, std::size_t{3});
    }
    QVERIFY_THROWS_EXCEPTION(ImportError, kPowerRecordingFileFormat.parse_text(
                                              std::string(sensors::kRecordingMagic) +
                                                  "\n# measurement: external meter\ntime_s,a power (W)\n0,1\n",
                                              "m.csv"));
  }
};

QTEST_GUILESS_MAIN(TestPowerRecording)
#include "test_power_recording.moc"
