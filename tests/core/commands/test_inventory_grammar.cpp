// SPDX-License-Identifier: GPL-3.0-or-later
// `benchscope-cli devices` and `sensors` (#52: every command `remote` accepts has a grammar): settings -> words ->
// settings is the identity with no option and with every option set, and bad words are refused naming the option.
#include <QTest>

#include "commands/inventory_grammar.h"

#include "../../support/grammar_under_test.h"

using bs::commands::DevicesSettings;
using bs::commands::SensorsSettings;

const bs::test::Grammar<DevicesSettings> devices{{"devices"}, bs::commands::devices_from_words};
const bs::test::Grammar<SensorsSettings> sensors{{"sensors"}, bs::commands::sensors_from_words};

class TestInventoryGrammar : public QObject {
  Q_OBJECT
 private slots:
  void devices_words_come_back() {
    QVERIFY(devices.round_trip(DevicesSettings{}) == DevicesSettings{});
    DevicesSettings all;
    all.json = all.table = all.measure_ceilings = true;
    all.isa = "avx2";
    all.workspace = "lab.bsw";
    all.proc_root = "/tmp/board/proc";
    all.sysfs_root = "/tmp/board";
    QVERIFY(devices.round_trip(all) == all);
  }

  void sensors_words_come_back() {
    QVERIFY(sensors.round_trip(SensorsSettings{}) == SensorsSettings{});
    SensorsSettings all;
    all.json = true;
    all.sysfs_root = "/tmp/fixture";
    QVERIFY(sensors.round_trip(all) == all);
  }

  void bad_words_are_refused_by_name() {
    QCOMPARE(devices.refusal({"--speed"}), QStringLiteral("unknown option '--speed'"));
    QCOMPARE(devices.refusal({"gpu"}), QStringLiteral("devices takes no positional argument ('gpu')"));
    QVERIFY(devices.refusal({"--isa"}).contains("--isa"));  // a value is missing
    QCOMPARE(sensors.refusal({"--sysfs"}), QStringLiteral("unknown option '--sysfs'"));
    QCOMPARE(sensors.refusal({"here"}), QStringLiteral("sensors takes no positional argument ('here')"));
  }
};

QTEST_APPLESS_MAIN(TestInventoryGrammar)
#include "test_inventory_grammar.moc"
