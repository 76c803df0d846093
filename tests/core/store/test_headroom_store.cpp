// SPDX-License-Identifier: GPL-3.0-or-later
// Headroom measurements in the workspace (schema 9): every field comes back as stored, removing the import removes
// them, a result whose bookkeeping fails is refused before anything is stored, a damaged document is named and left
// out, renaming a platform moves them, and a version-8 workspace gains the table on opening.
#include <QTemporaryDir>
#include <QTest>

#include "headroom/headroom_json.h"
#include "headroom/latency_recorder.h"
#include "store/workspace.h"
#include "workspace_test_support.h"

using namespace bs::test;
using namespace bs::headroom;

namespace {

HeadroomMeasurement sample_measurement() {
  HeadroomMeasurement m;
  m.platform = "robot";
  m.kind = LatencyKind::ApplicationLoop;
  m.tool = "benchscope probe";
  m.command = "benchscope-cli headroom --rate 1000 --load pipeline";
  m.kernel = {"6.1.0-18-rt-amd64", "#1 SMP PREEMPT_RT", true, "PREEMPT_RT", "2,3", "2-3", "performance"};
  m.provenance.origin = bs::DataOrigin::Measured;
  m.provenance.host = "robot-1";
  for (const char* name : {"idle", "pipeline@30fps"}) {
    Phase p;
    p.name = name;
    p.load = std::string(name) == "idle" ? LoadKind::Idle : LoadKind::Pipeline;
    p.duration_s = 20;
    if (p.load == LoadKind::Pipeline) {
      p.target_rate = 30;
      p.achieved_rate = 29.7;
      p.rate_unit = "fps";
      p.mean_power_w = 9.8;
      p.power_sensor = "RAPL package-0";
      p.notes = {"a note"};
    }
    p.probe_cpu_s_per_s = 0.012;
    for (int k = 0; k < 2; ++k) {
      LatencyRecorder r(100'000, 1000, 1'000'000);
      for (int i = 0; i < 500; ++i) r.add((i % 37) * 1000 + k * 250, 300'000);
      r.add(2'500'000, 300'000);  // one overflow, one miss
      ThreadLatency t = r.result();
      t.index = k;
      t.cpu = k + 2;
      t.policy = "SCHED_FIFO";
      t.priority = 80;
      t.memory_locked = true;
      t.period_ns = 1'000'000;
      t.computation_ns = 300'000;
      p.threads.push_back(t);
    }
    m.phases.push_back(p);
  }
  return m;
}

bs::ImportBatch batch_of(const HeadroomMeasurement& m) {
  return batch_holding(&bs::ImportBatch::headroom, {m}, "headroom", "benchscope-headroom-v1");
}

}  // namespace

class TestHeadroomStore : public QObject {
  Q_OBJECT
 private slots:
  void round_trip_and_removal() {
    QTemporaryDir dir;
    bs::Workspace ws(dir.filePath("w.bsw").toStdString());
    const HeadroomMeasurement m = sample_measurement();
    const std::int64_t id = ws.add_import(batch_of(m), "h1");
    const auto stored = ws.headroom_measurements();
    QCOMPARE(stored.size(), std::size_t{1});
    QCOMPARE(stored[0].import_id, id);
    // The JSON form writes every field, so equal documents mean every field came back.
    QCOMPARE(to_json(stored[0].measurement).dump(), to_json(m).dump());
    const ThreadLatency& t = stored[0].measurement.phases[1].threads[1];
    QCOMPARE(t.histogram.overflows, std::uint64_t{1});
    QCOMPARE(*t.histogram.max_ns, 2'500'000LL);
    QCOMPARE(t.misses->count, std::uint64_t{1});
    QVERIFY(ws.damage().empty());
    ws.remove_import(id);
    QVERIFY(ws.headroom_measurements().empty());
  }

  void broken_bookkeeping_is_refused_whole() {
    QTemporaryDir dir;
    bs::Workspace ws(dir.filePath("w.bsw").toStdString());
    HeadroomMeasurement m = sample_measurement();
    m.phases[1].threads[0].histogram.cycles += 1;
    try {
      ws.add_import(batch_of(m), "h1");
      QFAIL("a measurement whose cycles do not add up was stored");
    } catch (const bs::WorkspaceError& e) {
      QVERIFY2(QString(e.what()).contains("phase 'pipeline@30fps' thread 0: cycles 502 != 500 in bins + 1 overflows"),
               e.what());
    }
    QVERIFY(ws.imports().empty());
    QVERIFY(ws.headroom_measurements().empty());
  }

  void tampered_document_is_named_and_left_out() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("w.bsw").toStdString();
    {
      bs::Workspace ws(path);
      ws.add_import(batch_of(sample_measurement()), "h1");
    }
    {
      RawDb raw(path, false);
      // Bins that no longer add up to the cycles (a hand edit of the first thread's cycles).
      QVERIFY(raw.exec("UPDATE headroom_measurements SET data = replace(data, '\"cycles\":501', '\"cycles\":9')"));
    }
    bs::Workspace ws(path);
    QVERIFY(ws.headroom_measurements().empty());
    QCOMPARE(ws.damage().size(), std::size_t{1});
    const QString reason = QString::fromStdString(describe(ws.damage()[0]));
    QVERIFY2(reason.startsWith("headroom measurement #1 (robot, benchscope probe): headroom_measurements.data: "),
             qPrintable(reason));
    QVERIFY2(reason.contains("headroom.phases[0].threads[0].histogram: cycles 9 != 500 in bins + 1 overflows"),
             qPrintable(reason));
    QVERIFY(ws.read_only());
  }

  void rename_platform_moves_it() {
    QTemporaryDir dir;
    bs::Workspace ws(dir.filePath("w.bsw").toStdString());
    ws.add_import(batch_of(sample_measurement()), "h1");
    ws.rename_platform("robot", "NUC");
    QCOMPARE(QString::fromStdString(ws.headroom_measurements().at(0).measurement.platform), QString("NUC"));
  }

  void version_8_workspace_gains_the_table() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("v8.bsw").toStdString();
    QVERIFY(old_workspace(path, "DROP TABLE headroom_measurements; PRAGMA user_version = 8;"));
    bs::Workspace ws(path);
    QCOMPARE(ws.schema_version(), bs::Workspace::kSchemaVersion);  // through 9 to the current version
    ws.add_import(batch_of(sample_measurement()), "h");
    QCOMPARE(ws.headroom_measurements().size(), std::size_t{1});
    QCOMPARE(ws.integrity_check(), std::string("ok"));
  }
};

QTEST_GUILESS_MAIN(TestHeadroomStore)
#include "test_headroom_store.moc"
