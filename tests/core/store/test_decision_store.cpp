// SPDX-License-Identifier: GPL-3.0-or-later
// Schema 10 (issue #43.2, #43.4): the Platforms tab's decision (its control-loop requirement of #45 too) and each
// platform's chosen power log, kept in the workspace; the migration of a version-9 file (with #45's headroom table)
// and of a version-8 file (through 9); the order in which the comparisons then get the logs.
#include <QTemporaryDir>
#include <QTest>

#include "../../support/headroom_samples.h"
#include "store/battery_preset_store.h"
#include "store/decision_inputs.h"
#include "store/decision_store.h"
#include "store/workspace.h"
#include "workspace_test_support.h"

using bs::test::old_workspace;
using bs::test::RawDb;

namespace {

bs::PowerTrace log_of(const std::string& platform, const std::string& label, double amps) {
  bs::PowerTrace t;
  t.platform = platform;
  t.label = label;
  t.supply_voltage_v = 16;
  t.time_s = {0, 1, 2};
  t.channels.push_back({"I", bs::PowerQuantity::Current, {amps, amps, amps}});
  return t;
}

// NUC (2.5 A), Jetson TX2 (0.6 A), NUC again (1.9 A): the NUC's second log comes last.
void fill(bs::Workspace& ws) {
  bs::ImportBatch b;
  b.source_path = "logs";
  b.format = "power-csv";
  b.power_traces = {log_of("NUC", "nuc-a.csv", 2.5), log_of("Jetson TX2", "jetson.csv", 0.6),
                    log_of("NUC", "nuc-b.csv", 1.9)};
  ws.add_import(b, "hash-logs");
}

// A workspace's one headroom measurement (#45, schema 9): a robot's loop at 1 kHz beside the pipeline.
bs::ImportBatch headroom_batch() {
  return bs::test::batch_holding(
      &bs::ImportBatch::headroom,
      {bs::test::loop_measurement("robot", {{"pipeline@30fps", bs::test::loop_thread(1000, 50)}})}, "headroom",
      "benchscope-headroom-v1");
}

}  // namespace

class TestDecisionStore : public QObject {
  Q_OBJECT
 private slots:
  void decision_survives_reopen_and_can_be_cleared() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("d.bsw").toStdString();
    {
      bs::Workspace ws(path);
      QVERIFY(!bs::stored_decision(ws));
      bs::StoredDecision d;
      d.power_budget_w = 10;
      d.min_runtime_min = 40;
      d.battery = "paper-4s-3850";
      d.extra_load_w = 12.5;
      d.mission = "idle:60:12,walk:30:140";
      d.candidates = "orin,pi5";
      bs::set_stored_decision(ws, d);
    }
    bs::Workspace ws(path);
    const auto back = bs::stored_decision(ws);
    QVERIFY(back);
    QCOMPARE(*back->power_budget_w, 10.0);
    QVERIFY(!back->min_fps);
    QCOMPARE(*back->min_runtime_min, 40.0);
    QCOMPARE(back->battery, std::string("paper-4s-3850"));
    QCOMPARE(back->extra_load_w, 12.5);
    QCOMPARE(back->mission, std::string("idle:60:12,walk:30:140"));
    QCOMPARE(back->candidates, std::string("orin,pi5"));
    QCOMPARE(*back->constraints().min_runtime_h, 40.0 / 60);
    QCOMPARE(bs::describe_constraints(back->constraints()),
             std::string("a power budget of 10 W, at least 40 min on the battery"));
    // Refused: a budget of 0 W, a negative load. The stored decision stays as it was.
    bs::StoredDecision bad = *back;
    bad.power_budget_w = 0;
    QVERIFY_THROWS_EXCEPTION(bs::WorkspaceError, bs::set_stored_decision(ws, bad));
    bad = *back;
    bad.extra_load_w = -1;
    QVERIFY_THROWS_EXCEPTION(bs::WorkspaceError, bs::set_stored_decision(ws, bad));
    QVERIFY(bs::stored_decision(ws) == back);
    bs::set_stored_decision(ws, std::nullopt);
    QVERIFY(!bs::stored_decision(ws));
  }

  void a_hand_edited_value_out_of_range_is_refused_with_its_column() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("d.bsw").toStdString();
    {
      bs::Workspace ws(path);
      bs::StoredDecision d;
      d.power_budget_w = 10;
      bs::set_stored_decision(ws, d);
    }
    // Past the CHECKs (a file written by hand): the reader must neither take the value nor drop it silently.
    const auto refused = [&path](const std::string& sql, const QString& expected) {
      {
        RawDb raw(path, false);
        if (!raw.exec("PRAGMA ignore_check_constraints = 1; " + sql)) return QStringLiteral("cannot edit the file");
      }
      bs::Workspace ws(path);
      try {
        bs::stored_decision(ws);
      } catch (const bs::WorkspaceError& e) {
        if (e.kind() != bs::WorkspaceError::Kind::Corrupt) return QStringLiteral("not Corrupt: ") + e.what();
        return QString(e.what()).contains(expected) ? QString() : QStringLiteral("message: ") + e.what();
      }
      return QStringLiteral("read without complaint");
    };
    QCOMPARE(refused("UPDATE decision SET power_budget_w = -5;", "decision.power_budget_w: -5 is not a number > 0"),
             QString());
    QCOMPARE(refused("UPDATE decision SET power_budget_w = 10, min_fps = 'fast';",
                     "decision.min_fps: 'fast' is not a number"),
             QString());
    QCOMPARE(refused("UPDATE decision SET min_fps = NULL, extra_load_w = -1;", "decision.extra_load_w: -1"), QString());
    QCOMPARE(refused("UPDATE decision SET extra_load_w = 0, loop = 'p99<=1us';", "decision.loop: 'p99<=1us'"),
             QString());
    {
      RawDb raw(path, false);
      QVERIFY(raw.exec("UPDATE decision SET loop = '';"));
    }
    bs::Workspace ws(path);
    QCOMPARE(*bs::stored_decision(ws)->power_budget_w, 10.0);  // whole again: read as stored
  }

  void chosen_log_goes_first_and_leaves_with_its_log() {
    QTemporaryDir dir;
    bs::Workspace ws(dir.filePath("c.bsw").toStdString());
    fill(ws);
    const auto traces = ws.power_trace_summaries();
    QCOMPARE(traces.size(), std::size_t{3});
    const std::int64_t nuc_b = traces[2].id, jetson = traces[1].id;
    QVERIFY(bs::chosen_logs(ws).empty());
    bs::set_chosen_log(ws, "NUC", nuc_b);
    QCOMPARE(bs::chosen_logs(ws).at("NUC"), nuc_b);
    // Another platform's log, an unknown log, a blank platform: refused.
    QVERIFY_THROWS_EXCEPTION(bs::WorkspaceError, bs::set_chosen_log(ws, "NUC", jetson));
    QVERIFY_THROWS_EXCEPTION(bs::WorkspaceError, bs::set_chosen_log(ws, "NUC", 9999));
    QVERIFY_THROWS_EXCEPTION(bs::WorkspaceError, bs::set_chosen_log(ws, " ", nuc_b));
    // The comparisons get the NUC's chosen log before its other one; the rest keep their order.
    std::vector<bs::StoredPowerTrace> ordered = ws.power_trace_summaries();
    bs::order_chosen_logs_first(ws, ordered);
    QCOMPARE(ordered[0].trace.label, std::string("nuc-b.csv"));
    QCOMPARE(ordered[1].trace.label, std::string("nuc-a.csv"));
    QCOMPARE(ordered[2].trace.label, std::string("jetson.csv"));
    // The log moved to another platform chooses nothing; removed, its choice goes with it.
    bs::set_chosen_log(ws, "NUC", std::nullopt);
    QVERIFY(bs::chosen_logs(ws).empty());
    bs::set_chosen_log(ws, "NUC", nuc_b);
    ws.remove_import(traces[2].import_id);
    QVERIFY(bs::chosen_logs(ws).empty());
  }

  void order_is_stable_without_choices() {
    const std::vector<std::string> platforms{"A", "B", "A", "C", "B"};
    const std::vector<std::int64_t> ids{1, 2, 3, 4, 5};
    QCOMPARE(bs::chosen_logs_first(platforms, ids, {}), (std::vector<std::size_t>{0, 1, 2, 3, 4}));
    QCOMPARE(bs::chosen_logs_first(platforms, ids, {{"B", 5}, {"A", 1}}), (std::vector<std::size_t>{0, 4, 1, 2, 3}));
  }

  void control_loop_requirement_is_kept_and_checked() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("d.bsw").toStdString();
    const std::string loop = "1kHz,p99.9<=200us,max-consecutive-misses<=1,load=pipeline@30fps";
    {
      bs::Workspace ws(path);
      bs::StoredDecision d;
      d.loop = loop;
      QVERIFY(d.constrained());  // a requirement alone is a constraint, as in the Platforms tab
      bs::set_stored_decision(ws, d);
    }
    bs::Workspace ws(path);
    const auto back = bs::stored_decision(ws);
    QVERIFY(back);
    QCOMPARE(back->loop, loop);
    QVERIFY(back->constrained());
    const QString words = QString::fromStdString(bs::describe_constraints(*back));
    QVERIFY2(words.startsWith("control loop 1 kHz"), qPrintable(words));
    bs::StoredDecision with_budget = *back;
    with_budget.power_budget_w = 10;
    QVERIFY2(QString::fromStdString(bs::describe_constraints(with_budget))
                 .startsWith("a power budget of 10 W, control loop"),
             qPrintable(QString::fromStdString(bs::describe_constraints(with_budget))));
    // A requirement that does not parse is refused with what is wrong with it; the stored one stays.
    bs::StoredDecision bad = *back;
    bad.loop = "p99<=1us";
    try {
      bs::set_stored_decision(ws, bad);
      QFAIL("a control-loop requirement without a rate was stored");
    } catch (const bs::WorkspaceError& e) {
      QVERIFY2(QString(e.what()).contains("control-loop requirement"), e.what());
    }
    QCOMPARE(bs::stored_decision(ws)->loop, loop);
  }

  // #53: the sustained requirement is kept beside the decision's row (a workspace setting, no schema change), read
  // back with the rest, checked on the way in and out, and removed with the decision.
  void sustained_requirement_is_kept_and_checked() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("d.bsw").toStdString();
    {
      bs::Workspace ws(path);
      bs::StoredDecision d;
      d.sustained = "stability>=97%,minutes>=20";
      QVERIFY(d.constrained());  // a requirement alone is a constraint
      bs::set_stored_decision(ws, d);
    }
    {
      bs::Workspace ws(path);
      const auto back = bs::stored_decision(ws);
      QVERIFY(back);
      QCOMPARE(back->sustained, std::string("stability>=97%,minutes>=20"));
      QVERIFY(back->loop.empty() && !back->power_budget_w);
      QCOMPARE(QString::fromStdString(bs::describe_constraints(*back)),
               QString("sustained stability >= 97 %, at least 20 min"));
      const bs::DecisionInputs in = bs::decision_inputs(&ws);
      QVERIFY(in.sustained);
      QCOMPARE(*in.sustained->min_minutes, 20.0);
      // Refused with what is wrong; the stored one stays.
      bs::StoredDecision bad = *back;
      bad.sustained = "stability>=fast";
      try {
        bs::set_stored_decision(ws, bad);
        QFAIL("a sustained requirement that does not parse was stored");
      } catch (const bs::WorkspaceError& e) {
        QVERIFY2(QString(e.what()).contains("the sustained requirement: sustained requirement term 'stability>=fast'"),
                 e.what());
      }
      QCOMPARE(bs::stored_decision(ws)->sustained, std::string("stability>=97%,minutes>=20"));
      // A decision without it clears it; removing the decision removes it too.
      bs::StoredDecision plain;
      plain.min_fps = 5;
      bs::set_stored_decision(ws, plain);
      QVERIFY(bs::stored_decision(ws)->sustained.empty());
      bs::set_stored_decision(ws, *back);
      bs::set_stored_decision(ws, std::nullopt);
      QVERIFY(ws.settings("decision/").empty());
      bs::set_stored_decision(ws, *back);
      // A hand-edited setting that does not parse is refused when read, naming it.
      ws.set_setting("decision/sustained", "minutes>=x");
      try {
        bs::stored_decision(ws);
        QFAIL("a damaged sustained requirement was read");
      } catch (const bs::WorkspaceError& e) {
        QCOMPARE(e.kind(), bs::WorkspaceError::Kind::Corrupt);
        QVERIFY2(QString(e.what()).contains("decision/sustained: 'minutes>=x'"), e.what());
      }
    }
  }

  // Schema 9 is #45's headroom table: a version-9 file keeps its measurements and gains the decision's tables.
  // Issue #50.2: the inputs the GUI's Platforms tab and the CLI both read (store/decision_inputs.h). The Battery
  // tab's 5000 mAh edit (no decision stored) is the pack in effect; a decision naming a preset takes that preset but
  // keeps its own parallel load and mission; a named preset that is gone falls back to the Battery tab's.
  void decision_inputs_follow_the_gui_rule() {
    QTemporaryDir dir;
    bs::Workspace ws(dir.filePath("w.bsw").toStdString());
    bs::DecisionInputs none = bs::decision_inputs(&ws);
    QCOMPARE(QString::fromStdString(none.battery.pack.name), QString("paper-4s-3850"));
    QVERIFY(!none.stored && !none.battery_from_tab);

    bs::BatterySetup tab = bs::builtin_battery_setups().front();
    tab.pack.capacity_ah = 5.0;
    tab.depth_of_discharge = 0.8;
    tab.extra_load_w = 12;
    tab.mission = "walk:30:140";
    ws.set_setting("battery-tab/current", bs::battery_setup_to_json(tab));
    const bs::DecisionInputs from_tab = bs::decision_inputs(&ws);
    QVERIFY(from_tab.battery_from_tab);
    QCOMPARE(from_tab.options.battery_capacity_ah, 5.0);
    QCOMPARE(from_tab.options.usable_fraction, 0.8);
    QCOMPARE(from_tab.options.extra_load_w, 12.0);
    QCOMPARE(QString::fromStdString(from_tab.options.mission), QString("walk:30:140"));

    bs::StoredDecision d;
    d.power_budget_w = 10;
    d.battery = "paper-4s-3850";
    d.extra_load_w = 3;
    bs::set_stored_decision(ws, d);
    const bs::DecisionInputs named = bs::decision_inputs(&ws);
    QVERIFY(!named.battery_from_tab);
    QCOMPARE(named.options.battery_capacity_ah, 3.85);
    QCOMPARE(named.options.usable_fraction, 1.0);
    QCOMPARE(named.options.extra_load_w, 3.0);  // the decision's own
    QVERIFY(named.options.mission.empty());
    QCOMPARE(*named.constraints.power_budget_w, 10.0);

    d.battery = "a pack deleted since";
    bs::set_stored_decision(ws, d);
    const bs::DecisionInputs gone = bs::decision_inputs(&ws);
    QVERIFY(gone.battery_missing && gone.battery_from_tab);
    QCOMPARE(gone.options.battery_capacity_ah, 5.0);
  }

  void a_version_9_file_gains_the_tables() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("v9.bsw").toStdString();
    {
      bs::Workspace ws(path);
      ws.add_import(headroom_batch(), "h");
    }
    {
      RawDb old(path, false);
      QVERIFY(old.exec("DROP TABLE chosen_logs; DROP TABLE decision; PRAGMA user_version = 9;"));
    }
    bs::Workspace ws(path);
    QVERIFY(ws.schema_version() >= 10);  // through 10 to the current version
    QCOMPARE(ws.schema_version(), bs::Workspace::kSchemaVersion);
    QCOMPARE(ws.headroom_measurements().size(), std::size_t{1});
    QVERIFY(!bs::stored_decision(ws));
    bs::StoredDecision d;
    d.min_fps = 5;
    d.loop = "500Hz,p99<=1ms";
    bs::set_stored_decision(ws, d);
    QCOMPARE(*bs::stored_decision(ws)->min_fps, 5.0);
    QCOMPARE(bs::stored_decision(ws)->loop, std::string("500Hz,p99<=1ms"));
    QCOMPARE(ws.integrity_check(), std::string("ok"));
  }

  // An older file migrates through 9 (headroom) to 10 (the decision) in one opening.
  void a_version_8_file_gains_both_versions_tables() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("v8.bsw").toStdString();
    QVERIFY(old_workspace(
        path,
        "DROP TABLE chosen_logs; DROP TABLE decision; DROP TABLE headroom_measurements; PRAGMA user_version = 8;"));
    bs::Workspace ws(path);
    QCOMPARE(ws.schema_version(), bs::Workspace::kSchemaVersion);
    QCOMPARE(RawDb(path).scalar("PRAGMA user_version"), std::to_string(bs::Workspace::kSchemaVersion));
    ws.add_import(headroom_batch(), "h");
    QCOMPARE(ws.headroom_measurements().size(), std::size_t{1});
    QVERIFY(!bs::stored_decision(ws));
    bs::StoredDecision d;
    d.power_budget_w = 10;
    bs::set_stored_decision(ws, d);
    QCOMPARE(*bs::stored_decision(ws)->power_budget_w, 10.0);
    QCOMPARE(ws.integrity_check(), std::string("ok"));
  }
};

QTEST_APPLESS_MAIN(TestDecisionStore)
#include "test_decision_store.moc"
