// SPDX-License-Identifier: GPL-3.0-or-later
// One way home for a headroom measurement made in-process (#52): the Headroom tab and `benchscope-cli headroom
// --workspace` build their batch with headroom_import, so the same measurement gets the same content hash whoever
// stored it (they hashed different JSON before), and a workspace refuses it the second time.
#include <QTemporaryDir>
#include <QTest>

#include "../../support/home_checks.h"
#include "headroom/headroom_import.h"
#include "headroom/headroom_json.h"
#include "store/workspace.h"

using namespace bs;
using namespace bs::headroom;

namespace {

HeadroomMeasurement measurement(const std::string& platform) {
  HeadroomMeasurement m;
  m.platform = platform;
  m.kind = LatencyKind::ApplicationLoop;
  m.tool = "benchscope probe";
  m.command = "benchscope-cli headroom --rate 1000";
  m.provenance.origin = DataOrigin::Measured;
  m.provenance.date = "2026-12-06";
  Phase p;
  p.name = "idle";
  p.load = LoadKind::Idle;
  p.duration_s = 10;
  m.phases = {p};
  return m;
}

}  // namespace

class TestHeadroomImport : public QObject {
  Q_OBJECT
 private slots:
  void both_front_ends_hash_alike() {
    const HeadroomMeasurement m = measurement("robot");
    const auto tab = headroom_import(m, std::nullopt, "Headroom tab");
    const auto cli = headroom_import(m, std::nullopt, "benchscope-cli headroom");
    QCOMPARE(tab.content_hash, cli.content_hash);
    QCOMPARE(tab.content_hash, content_hash(to_json(m).dump()));  // the record, not its derived summary
    QVERIFY(tab.content_hash != headroom_import(measurement("desk"), std::nullopt, "Headroom tab").content_hash);
    QCOMPARE(tab.batch.format, std::string(kHeadroomFormat));
    QCOMPARE(tab.batch.source_path, std::string("Headroom tab (robot, 2026-12-06)"));
    QCOMPARE(tab.batch.headroom.size(), std::size_t{1});
    QVERIFY(tab.batch.power_traces.empty());
  }

  void the_power_trace_goes_home_with_it() {
    const HomeBatch home =
        headroom_import(measurement("robot"), test::recorded_beside("RAPL package-0"), "Headroom tab");
    QCOMPARE(home.batch.power_traces.size(), std::size_t{1});
    QCOMPARE(home.batch.power_traces[0].label, std::string("RAPL package-0"));
    test::trace_goes_home_with_it(home,
                                  [](const Workspace& ws) { return test::import_ids(ws.headroom_measurements()); });
  }

  void a_workspace_refuses_the_same_measurement_twice() {
    QTemporaryDir dir;
    Workspace ws(dir.filePath("h.bsw").toStdString());
    const HeadroomMeasurement m = measurement("robot");
    bring_home(ws, headroom_import(m, std::nullopt, "Headroom tab"));
    QVERIFY_THROWS_EXCEPTION(WorkspaceError,
                             bring_home(ws, headroom_import(m, std::nullopt, "benchscope-cli headroom")));
    QCOMPARE(ws.headroom_measurements().size(), std::size_t{1});
    test::same_measurement_is_one_import(headroom_import(m, std::nullopt, "Headroom tab"),
                                         headroom_import(m, std::nullopt, "benchscope-cli headroom"));
  }
};

QTEST_APPLESS_MAIN(TestHeadroomImport)
#include "test_headroom_import.moc"
