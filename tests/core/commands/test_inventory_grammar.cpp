// SPDX-License-Identifier: GPL-3.0-or-later
// `benchscope-cli devices` and `sensors` (#52: every command `remote` accepts has a grammar): settings -> words ->
// settings is the identity with no option and with every option set, and bad words are refused naming the option.
#include <QTest>

#include "commands/inventory_grammar.h"

#include "../../support/refusal.h"

using bs::commands::DevicesSettings;
using bs::commands::SensorsSettings;

namespace {

template <class Settings, class From>
Settings round_trip(const Settings& s, From from_words, const char* name) {
  const std::vector<std::string> words = bs::commands::to_words(s);
  if (words.front() != name) throw std::logic_error("the words do not start with the command");
  return from_words({words.begin() + 1, words.end()});
}

}  // namespace

class TestInventoryGrammar : public QObject {
  Q_OBJECT
 private slots:
  void devices_words_come_back() {
    QVERIFY(round_trip(DevicesSettings{}, bs::commands::devices_from_words, "devices") == DevicesSettings{});
    DevicesSettings all;
    all.json = all.table = all.measure_ceilings = true;
    all.isa = "avx2";
    all.workspace = "lab.bsw";
    all.proc_root = "/tmp/board/proc";
    all.sysfs_root = "/tmp/board";
    QVERIFY(round_trip(all, bs::commands::devices_from_words, "devices") == all);
  }

  void sensors_words_come_back() {
    QVERIFY(round_trip(SensorsSettings{}, bs::commands::sensors_from_words, "sensors") == SensorsSettings{});
    SensorsSettings all;
    all.json = true;
    all.sysfs_root = "/tmp/fixture";
    QVERIFY(round_trip(all, bs::commands::sensors_from_words, "sensors") == all);
  }

  void bad_words_are_refused_by_name() {
    const auto devices = [](std::vector<std::string> w) {
      return bs::test::refusal([&] { bs::commands::devices_from_words(w); });
    };
    const auto sensors = [](std::vector<std::string> w) {
      return bs::test::refusal([&] { bs::commands::sensors_from_words(w); });
    };
    QCOMPARE(devices({"--speed"}), QStringLiteral("unknown option '--speed'"));
    QCOMPARE(devices({"gpu"}), QStringLiteral("devices takes no positional argument ('gpu')"));
    QVERIFY(devices({"--isa"}).contains("--isa"));  // a value is missing
    QCOMPARE(sensors({"--sysfs"}), QStringLiteral("unknown option '--sysfs'"));
    QCOMPARE(sensors({"here"}), QStringLiteral("sensors takes no positional argument ('here')"));
  }
};

QTEST_APPLESS_MAIN(TestInventoryGrammar)
#include "test_inventory_grammar.moc"
