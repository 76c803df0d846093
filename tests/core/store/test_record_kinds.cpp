// SPDX-License-Identifier: GPL-3.0-or-later
// The record-kind descriptors (store/record_kinds.h, #52): every vector of an import batch has one, and the code
// that loops over them (storing, checking on opening, undoing a removal, counting, a robot job's import) handles
// every kind. One import holding one record of each kind goes through all of it.
#include <QTemporaryDir>
#include <QTest>
#include <set>

#include "../../support/headroom_samples.h"
#include "../../support/sample_records.h"
#include "remote/job_import.h"
#include "store/import_snapshot.h"
#include "store/record_kinds.h"
#include "workspace_test_support.h"

using namespace bs;
using namespace bs::test;

// A member added to ImportBatch without a descriptor would be stored by nothing: this fails first, naming the place.
static_assert(sizeof(ImportBatch) == 2 * sizeof(std::string) + (kRecordKindCount + 1) * sizeof(std::vector<int>),
              "ImportBatch changed: give a new record kind its descriptor in store/record_kinds.h");

namespace {

ImportBatch one_of_each_kind() {
  ImportBatch b = batch_of({make_run("NUC GPU", "OpenCL", 4, 3, 2)}, "every-kind");
  b.format = "benchscope-test";
  ResultSet set;
  set.platform = "NUC";
  set.device = "NUC CPU";
  set.backend = "cpu";
  set.source_format = "clpeak-text";
  set.measurements = {{"float", "flops", "GFLOPS", {12.5}, {}}};
  b.result_sets.push_back(set);
  PowerTrace trace;
  trace.platform = "NUC";
  trace.label = "load";
  trace.time_s = {0, 1, 2};
  trace.channels = {{"power", PowerQuantity::Power, {10, 11, 12}}};
  b.power_traces.push_back(trace);
  b.frames.push_back(copied_frame("cap", 2, 2));
  PipelineRun pipe;
  pipe.platform = "NUC";
  pipe.device = "NUC CPU";
  pipe.backend = "cpu";
  pipe.stages = {{"preprocess", 3, 0.01, 0.001, 0.009, 0.012, 0.01, 0.011}};
  b.pipeline_runs.push_back(pipe);
  b.dnn_runs.push_back(sample_inference_run("NUC"));
  b.headroom.push_back(loop_measurement("NUC", {{"idle", loop_thread(200, 40)}}));
  b.sustain_runs.push_back(sample_sustained_run("NUC"));
  return b;
}

// How many records of each kind the workspace holds, as each kind's own reader returns them.
RecordCounts stored_counts(const Workspace& ws) {
  RecordCounts c;
  for_each_record_kind([&](const auto& kind) { c.n[static_cast<std::size_t>(kind.id)] = (ws.*kind.read)().size(); });
  return c;
}

}  // namespace

class TestRecordKinds : public QObject {
  Q_OBJECT
 private slots:
  void every_kind_has_one_descriptor_in_order() {
    std::set<std::size_t> ids;
    std::size_t order = 0;
    for_each_record_kind([&](const auto& kind) {
      QCOMPARE(static_cast<std::size_t>(kind.id), order++);
      ids.insert(static_cast<std::size_t>(kind.id));
      QVERIFY(std::string(kind.words.one) != kind.words.many);
      QVERIFY(*kind.words.section != '\0');
    });
    QCOMPARE(ids.size(), kRecordKindCount);
    // Each kind alone makes a batch not empty: empty() asks every descriptor.
    const ImportBatch all = one_of_each_kind();
    for_each_record_kind([&](const auto& kind) {
      ImportBatch only;
      (only.*kind.in_batch) = all.*kind.in_batch;
      QVERIFY2(!only.empty(), kind.words.one);
    });
    QVERIFY(ImportBatch{}.empty());
  }

  void counts_read_in_the_kinds_words() {
    RecordCounts c;
    c.add(one_of_each_kind());
    QCOMPARE(c.total(), kRecordKindCount);
    QCOMPARE(c.summary(), std::string("1 run, 1 result set, 1 power log, 1 frame, 1 pipeline run, 1 inference run, "
                                      "1 headroom measurement, 1 sustained run"));
    c.add(batch_of({make_run("NUC GPU", "OpenCL", 8, 3, 2)}));
    QCOMPARE(c[RecordKindId::Run], std::size_t{2});
    QCOMPARE(RecordCounts{}.summary(), std::string("nothing"));
  }

  // Stored in one import, read back, snapshotted, removed and restored: every kind survives each step.
  void one_of_each_kind_is_stored_and_restored() {
    QTemporaryDir dir;
    Workspace ws(dir.filePath("w.bsw").toStdString());
    const std::int64_t id = ws.add_import(one_of_each_kind(), "hash-all");
    RecordCounts one;
    one.add(one_of_each_kind());
    QCOMPARE(stored_counts(ws).n, one.n);
    const ImportSnapshot snap = snapshot_import(ws, id);
    RecordCounts in_snapshot;
    in_snapshot.add(snap.batch);
    QCOMPARE(in_snapshot.n, one.n);
    ws.remove_import(id);
    QCOMPARE(stored_counts(ws).total(), std::size_t{0});
    restore_import(ws, snap);
    QCOMPARE(stored_counts(ws).n, one.n);
    // A workspace reopened reads every kind without damage (the opening scan lists every kind).
    const Workspace again(ws.path(), Workspace::OpenMode::ReadOnly);
    QVERIFY(again.damage().empty());
    QCOMPARE(stored_counts(again).n, one.n);
  }

  // A robot's job: every kind comes home stamped and under the confirmed platform, except frames, which stay on the
  // robot with a warning naming them.
  void a_robot_job_brings_every_kind_but_frames() {
    QTemporaryDir dir;
    const std::string result = dir.filePath("result.bsw").toStdString();
    {
      Workspace robot(result);
      robot.add_import(one_of_each_kind(), "hash-robot");
    }
    remote::RemoteOrigin origin;
    origin.destination = "jetson";
    origin.hostname = "tx2";
    origin.job_id = "j1";
    const std::vector<ImportBatch> batches = remote::job_batches(result, origin, "Jetson TX2");
    QCOMPARE(batches.size(), std::size_t{1});
    RecordCounts came;
    came.add(batches[0]);
    for_each_record_kind([&](const auto& kind) {
      const bool stays = from_robot_v<decltype(kind)> == FromRobot::StaysOnRobot;
      QCOMPARE(came[kind.id], std::size_t{stays ? 0u : 1u});
      if constexpr (from_robot_v<decltype(kind)> == FromRobot::Stamped)
        for (const auto& item : batches[0].*kind.in_batch) {
          QCOMPARE(item.platform, std::string("Jetson TX2"));
          bool stamped = false;
          for (const auto& [key, value] : item.provenance.settings)
            stamped = stamped || (key == "remote job" && value == "j1");
          QVERIFY2(stamped, kind.words.one);
        }
    });
    QCOMPARE(batches[0].warnings.size(), std::size_t{1});
    QVERIFY2(batches[0].warnings[0].find("frame 'cap' left out: frames stay on the robot") != std::string::npos,
             batches[0].warnings[0].c_str());
  }
};

QTEST_MAIN(TestRecordKinds)
#include "test_record_kinds.moc"
