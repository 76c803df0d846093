// SPDX-License-Identifier: GPL-3.0-or-later
// The word reader every command and grammar shares: options with and without "=", "--" ending the options,
// negative numbers as values, and the refusals naming the option. Numbers written by grammars read back exactly.
#include <QTest>

#include <cmath>
#include <limits>

#include "commands/words.h"

#include "../../support/refusal.h"

using bs::commands::read_words;
using bs::commands::UsageError;

namespace {

QString refusal(const std::vector<std::string>& words) {
  return bs::test::refusal([&] { read_words(words, {"--json"}, {"--out", "--rate"}); });
}

}  // namespace

class TestWords : public QObject {
  Q_OBJECT
 private slots:
  void options_flags_and_positionals() {
    const auto w =
        read_words({"a", "--out=x=y", "--json", "--rate", "-3", "--", "--json", "-"}, {"--json"}, {"--out", "--rate"});
    QCOMPARE(w.positional, (std::vector<std::string>{"a", "--json", "-"}));
    QCOMPARE(*w.value("--out"), std::string("x=y"));
    QCOMPARE(w.number("--rate", 0), -3.0);
    QVERIFY(w.has("--json"));
    QCOMPARE(w.number("--absent", 7), 7.0);
  }

  void refusals_name_the_option() {
    QCOMPARE(refusal({"--bogus"}), QStringLiteral("unknown option '--bogus'"));
    QCOMPARE(refusal({"--json=1"}), QStringLiteral("--json takes no value"));
    QCOMPARE(refusal({"--out"}), QStringLiteral("--out needs a value"));
    const auto w = read_words({"--rate", "1e999"}, {}, {"--rate"});
    QVERIFY_THROWS_EXCEPTION(UsageError, w.number("--rate", 0));
    QVERIFY_THROWS_EXCEPTION(
        UsageError, bs::commands::whole_number(read_words({"--rate", "2.5"}, {}, {"--rate"}), "--rate", 1, 1, 10));
  }

  void numbers_are_short_and_read_back_exactly() {
    QCOMPARE(bs::commands::number_word(1000), std::string("1000"));
    QCOMPARE(bs::commands::number_word(0.5), std::string("0.5"));
    QCOMPARE(bs::commands::number_word(12.345), std::string("12.345"));
    for (const double v :
         {0.1, 1.0 / 3, 123456.789e-7, std::nextafter(1.0, 2.0), 4e9, -2.5, std::numeric_limits<double>::min()}) {
      const auto w = read_words({"--rate", bs::commands::number_word(v)}, {}, {"--rate"});
      QCOMPARE(w.number("--rate", 0), v);
    }
  }
};

QTEST_APPLESS_MAIN(TestWords)
#include "test_words.moc"
