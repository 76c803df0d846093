// SPDX-License-Identifier: GPL-3.0-or-later
// User battery presets live in the workspace: saved, read back after reopening, replacing a built-in of the same
// name, removed; bad values refused on save and bad stored JSON skipped with a message. Workspace settings keep
// apart from the schema's own meta keys.
#include <QTemporaryDir>
#include <QTest>

#include "store/battery_preset_store.h"
#include "store/workspace.h"

class TestBatteryPresets : public QObject {
  Q_OBJECT
 private slots:
  void save_reopen_read_back() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const std::string path = dir.filePath("w.bsw").toStdString();
    bs::BatterySetup robot = bs::builtin_battery_setups().front();
    robot.pack.name = "robot 6S";
    robot.pack.description = "our humanoid's pack";
    robot.pack.cells_series = 6;
    robot.pack.capacity_ah = 5.2;
    robot.pack.internal_resistance_ohm = 0.025;
    robot.depth_of_discharge = 0.8;
    robot.extra_load_w = 225;
    robot.model = bs::BatteryModel::Lipo;
    robot.mission = "idle:60:12,walk:30:140";
    {
      bs::Workspace ws(path);
      QVERIFY(bs::workspace_battery_setups(ws).empty());
      bs::save_battery_setup(ws, robot);
      bs::BatterySetup paper = bs::builtin_battery_setups().front();
      paper.pack.capacity_ah = 5.0;  // an edited built-in
      bs::save_battery_setup(ws, paper);
    }
    bs::Workspace ws(path);
    QCOMPARE(ws.schema_version(), bs::Workspace::kSchemaVersion);
    const auto stored = bs::workspace_battery_setups(ws);
    QCOMPARE(stored.size(), std::size_t{2});
    const auto back = bs::find_battery_setup(&ws, "robot 6S");
    QVERIFY(back);
    QVERIFY(back->from_workspace);
    QCOMPARE(back->pack.description, robot.pack.description);
    QCOMPARE(back->pack.cells_series, 6);
    QCOMPARE(back->pack.capacity_ah, 5.2);
    QCOMPARE(back->pack.internal_resistance_ohm, 0.025);
    QCOMPARE(back->pack.cutoff_cell_v, robot.pack.cutoff_cell_v);
    QCOMPARE(back->depth_of_discharge, 0.8);
    QCOMPARE(back->extra_load_w, 225.0);
    QVERIFY(back->model == bs::BatteryModel::Lipo);
    QCOMPARE(back->mission, robot.mission);
    // The edited built-in replaces the built-in in the combined list, which keeps its order.
    const auto all = bs::all_battery_setups(&ws);
    QCOMPARE(all.size(), bs::battery_presets().size() + 1);
    QCOMPARE(all.front().pack.name, std::string("paper-4s-3850"));
    QCOMPARE(all.front().pack.capacity_ah, 5.0);
    QVERIFY(all.front().from_workspace);
    QCOMPARE(bs::find_battery_setup(nullptr, "paper-4s-3850")->pack.capacity_ah, 3.85);
    bs::remove_battery_setup(ws, "paper-4s-3850");
    QCOMPARE(bs::find_battery_setup(&ws, "paper-4s-3850")->pack.capacity_ah, 3.85);
  }

  void invalid_values_refused() {
    QTemporaryDir dir;
    bs::Workspace ws(dir.filePath("w.bsw").toStdString());
    bs::BatterySetup s = bs::builtin_battery_setups().front();
    s.pack.name = "bad";
    s.depth_of_discharge = 0;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, bs::save_battery_setup(ws, s));
    s.depth_of_discharge = 1;
    s.mission = "walk:abc:10";
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, bs::save_battery_setup(ws, s));
    s.mission.clear();
    s.pack.name.clear();
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, bs::save_battery_setup(ws, s));
    QVERIFY(bs::workspace_battery_setups(ws).empty());
    // A damaged stored entry is skipped and reported, the others still load.
    ws.set_setting("battery-preset/broken", "{\"capacity_ah\": \"lots\"}");
    s.pack.name = "fine";
    bs::save_battery_setup(ws, s);
    std::vector<std::string> errors;
    const auto got = bs::workspace_battery_setups(ws, &errors);
    QCOMPARE(got.size(), std::size_t{1});
    QCOMPARE(got[0].pack.name, std::string("fine"));
    QCOMPARE(errors.size(), std::size_t{1});
    QVERIFY(errors[0].find("capacity_ah") != std::string::npos);
  }

  void settings_are_kept_apart_from_meta() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("w.bsw").toStdString();
    {
      bs::Workspace ws(path);
      ws.set_setting("schema_version", "999");  // stored as a setting, not over the schema's key
      ws.set_setting("a%_b", "1");
      ws.set_setting("a", "2");
      QCOMPARE(ws.settings("a%").size(), std::size_t{1});
      QCOMPARE(ws.settings("a").size(), std::size_t{2});
    }
    bs::Workspace ws(path);  // still opens: the real schema version is untouched
    QCOMPARE(ws.schema_version(), bs::Workspace::kSchemaVersion);
    QCOMPARE(ws.settings().size(), std::size_t{3});
    ws.remove_setting("a");
    QCOMPARE(ws.settings("a").size(), std::size_t{1});
  }
};

QTEST_MAIN(TestBatteryPresets)
#include "test_battery_presets.moc"
