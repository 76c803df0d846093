// SPDX-License-Identifier: GPL-3.0-or-later
// One way home for a power recording made on its own (#52): `benchscope-cli record-power --workspace` stores the
// trace as one import built by recording_home, whose hash is of the recording itself (its CSV), so the same
// recording stored again is refused and another one, even of the same second and sensor, is not.
#include <sstream>

#include <QTest>

#include "../../support/home_checks.h"
#include "power/recording_home.h"
#include "sensors/recording_csv.h"

using namespace bs;

class TestRecordingHome : public QObject {
  Q_OBJECT
 private slots:
  void the_same_recording_is_one_import() {
    const PowerTrace trace = test::recorded_beside("record-power sleep 1");
    test::same_measurement_is_one_import(recording_home(trace, "benchscope-cli record-power"),
                                         recording_home(trace, "benchscope-cli record-power"));
  }

  void the_hash_is_of_the_recording() {
    const PowerTrace trace = test::recorded_beside("record-power sleep 1");
    const HomeBatch home = recording_home(trace, "benchscope-cli record-power");
    std::ostringstream csv;
    sensors::write_recording_csv(csv, trace);
    QCOMPARE(home.content_hash, content_hash(csv.str()));
    // Another recording of the same start, label and sensor (what the old recipe hashed) is another import.
    PowerTrace other = trace;
    other.channels[0].values[1] = 14.0;
    QVERIFY(recording_home(other, "benchscope-cli record-power").content_hash != home.content_hash);
  }

  void the_batch_holds_the_trace_alone() {
    const HomeBatch home = recording_home(test::recorded_beside("record-power sleep 1"), "benchscope-cli record-power");
    QCOMPARE(home.batch.format, std::string("benchscope-power-recording"));
    QCOMPARE(home.batch.source_path, std::string("benchscope-cli record-power (robot-nuc, 2026-12-06T10:00:00Z)"));
    QVERIFY(home.batch.runs.empty() && home.batch.result_sets.empty());
    test::trace_goes_home_with_it(home,
                                  [](const Workspace& ws) { return test::import_ids(ws.power_trace_summaries()); });
  }
};

QTEST_APPLESS_MAIN(TestRecordingHome)
#include "test_recording_home.moc"
