// SPDX-License-Identifier: GPL-3.0-or-later
// Sustained runs in the workspace (schema 11, issue #53): stored with their import in one transaction, read back
// unchanged, removed with the import, moved by a platform rename, a damaged document named and left out, and a
// version-10 workspace gains the table when opened.
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <limits>

#include "../../support/sustained_flops.h"
#include "store/workspace.h"
#include "sustain/sustain_json.h"
#include "workspace_test_support.h"

using namespace bs::test;
using namespace bs;

namespace {

SustainRun sample_run() {
  auto r = bs::test::sustained_flops_run("robot", "flops for 3 s");
  r.t_s = {1.0, 2.0, 3.0};
  r.rate = {10.5, std::numeric_limits<double>::quiet_NaN(), 9.5};
  r.clocks = {{"cpu0", 3e9, {3e9, 2e9, 1.8e9}}};
  r.temperatures = {{"thermal_zone0 x86_pkg_temp", 95.0, {60, 70, 97}}};
  r.not_exposed = {"no devfreq device under /sys/class/devfreq: no GPU clock"};
  r.provenance.origin = DataOrigin::Measured;
  r.provenance.host = "robot-1";
  return r;
}

ImportBatch batch_of(const SustainRun& r) {
  return batch_holding(&ImportBatch::sustain_runs, {r}, "benchscope-cli sustain", "benchscope-sustain-v1");
}

}  // namespace

class TestSustainStore : public QObject {
  Q_OBJECT
 private slots:
  void round_trip_and_removal() {
    QTemporaryDir dir;
    Workspace ws(dir.filePath("w.bsw").toStdString());
    const SustainRun r = sample_run();
    const std::int64_t id = ws.add_import(batch_of(r), "s1");
    const auto stored = ws.sustain_runs();
    QCOMPARE(stored.size(), std::size_t{1});
    QCOMPARE(stored[0].import_id, id);
    // The JSON form writes every field, so equal documents mean every field came back (NaN as null).
    QCOMPARE(sustain::record_to_json(stored[0].run).dump(), sustain::record_to_json(r).dump());
    QVERIFY(std::isnan(stored[0].run.rate[1]));
    QVERIFY(ws.damage().empty());
    // The same run again is a duplicate import (same content hash).
    QVERIFY_THROWS_EXCEPTION(WorkspaceError, ws.add_import(batch_of(r), "s1"));
    ws.remove_import(id);
    QVERIFY(ws.sustain_runs().empty());
  }

  void tampered_document_is_named_and_left_out() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("w.bsw").toStdString();
    {
      Workspace ws(path);
      ws.add_import(batch_of(sample_run()), "s1");
    }
    {
      RawDb raw(path, false);
      // Times that no longer increase (a hand edit).
      QVERIFY(
          raw.exec("UPDATE sustain_runs SET data = replace(data, '\"t_s\":[1.0,2.0,3.0]', '\"t_s\":[1.0,2.0,1.5]')"));
    }
    Workspace ws(path);
    QVERIFY(ws.sustain_runs().empty());
    QCOMPARE(ws.damage().size(), std::size_t{1});
    const QString reason = QString::fromStdString(describe(ws.damage()[0]));
    QVERIFY2(reason.startsWith("sustained run #1 (robot, flops for 3 s): sustain_runs.data: "), qPrintable(reason));
    QVERIFY2(reason.contains("sustain.t_s[2]: does not increase"), qPrintable(reason));
    QVERIFY(ws.read_only());
  }

  void rename_platform_moves_it() {
    QTemporaryDir dir;
    Workspace ws(dir.filePath("w.bsw").toStdString());
    ws.add_import(batch_of(sample_run()), "s1");
    ws.rename_platform("robot", "NUC");
    QCOMPARE(QString::fromStdString(ws.sustain_runs().at(0).run.platform), QString("NUC"));
  }

  void version_10_workspace_gains_the_table() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("v10.bsw").toStdString();
    QVERIFY(old_workspace(path, "DROP TABLE sustain_runs; PRAGMA user_version = 10;"));
    Workspace ws(path);
    QCOMPARE(ws.schema_version(), Workspace::kSchemaVersion);
    ws.add_import(batch_of(sample_run()), "s");
    QCOMPARE(ws.sustain_runs().size(), std::size_t{1});
    QCOMPARE(ws.integrity_check(), std::string("ok"));
  }
};

QTEST_GUILESS_MAIN(TestSustainStore)
#include "test_sustain_store.moc"
