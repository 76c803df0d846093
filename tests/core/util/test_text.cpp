// SPDX-License-Identifier: GPL-3.0-or-later
// The shared text helpers (util/text.h): ASCII white space off both ends, ASCII lower case, UTF-8 left intact
// whatever the C library's locale says; comma-separated terms; numbers through a printf format, of any length, and with
// fixed decimals; parts joined; endings in any case; and the enumeration word tables' completeness check.
#include <clocale>

#include <QTest>

#include "util/enum_words.h"
#include "util/text.h"

class TestText : public QObject {
  Q_OBJECT
 private slots:
  void trims_ascii_white_space() {
    QCOMPARE(std::string(bs::trim(" \t\r\n\f\vNUC power\t \r")), std::string("NUC power"));
    QCOMPARE(std::string(bs::trim("")), std::string());
    QCOMPARE(std::string(bs::trim(" \t ")), std::string());
    QCOMPARE(std::string(bs::trim("a")), std::string("a"));
    // A no-break space (U+00A0, C2 A0 in UTF-8) is text, not ASCII white space.
    QCOMPARE(std::string(bs::trim("\xc2\xa0x\xc2\xa0")), std::string("\xc2\xa0x\xc2\xa0"));
  }

  void lowers_ascii_only() {
    QCOMPARE(bs::lower("Jetson TX2 GR3D_FREQ"), std::string("jetson tx2 gr3d_freq"));
    // "Ä" (C3 84) stays two bytes as they are, in any locale.
    std::setlocale(LC_ALL, "C.UTF-8");
    QCOMPARE(bs::lower("\xc3\x84RM"), std::string("\xc3\x84rm"));
    std::setlocale(LC_ALL, "C");
  }

  void splits_comma_terms() {
    using Terms = std::vector<std::string>;
    QCOMPARE(bs::comma_terms("1kHz, p99.9 <= 200us,,load=idle"), (Terms{"1kHz", "p99.9<=200us", "load=idle"}));
    QCOMPARE(bs::comma_terms("pipeline@30fps"), (Terms{"pipeline@30fps"}));  // no comma: one term
    QCOMPARE(bs::comma_terms(" , ,"), Terms{});
    QCOMPARE(bs::comma_terms(""), Terms{});
    QCOMPARE(bs::comma_terms("a,b "), (Terms{"a", "b"}));  // the last term needs no comma after it
  }

  void formats_numbers_of_any_length() {
    QCOMPARE(bs::format_number("%.2f W", 9.4849), std::string("9.48 W"));
    QCOMPARE(bs::format_number("%+.1f %%", 2.25), std::string("+2.2 %"));
    // 1e300 in fixed notation is 301 digits before the point: more than any fixed buffer of the old copies held.
    QCOMPARE(bs::format_number("%.0f", 1e300).size(), std::size_t{301});
    QCOMPARE(bs::fixed(1.005, 2), bs::format_number("%.2f", 1.005));
    QCOMPARE(bs::fixed(2.5, 0), std::string("2"));  // round half to even, as printf
    QCOMPARE(bs::fixed(-0.125, 2), std::string("-0.12"));
    QCOMPARE(bs::fixed(3, 3), std::string("3.000"));
  }

  void joins_parts() {
    QCOMPARE(bs::join({"a", "b", "c"}, ", "), std::string("a, b, c"));
    QCOMPARE(bs::join({"benchscope-cli", "sustain", "--load", "flops"}, " "),
             std::string("benchscope-cli sustain --load flops"));
    QCOMPARE(bs::join({}, "; "), std::string());
    QCOMPARE(bs::join({"", "x"}, "; "), std::string("; x"));  // empty parts count: the caller drops them
  }

  void endings_in_any_case() {
    QVERIFY(bs::ends_with_ci("/data/Capture.PNG", ".png"));
    QVERIFY(!bs::ends_with_ci("png", ".png"));
    QVERIFY(bs::ends_with_any_ci("run.TIFF", ".tif .tiff"));
    QVERIFY(bs::ends_with_any_ci("a/mlperf_log_summary.txt", "mlperf_log_summary.txt"));
    QVERIFY(!bs::ends_with_any_ci("results.json", ".txt .log"));
    QVERIFY(!bs::ends_with_any_ci("results.json", ""));
    QVERIFY(!bs::ends_with_any_ci("", ".json"));
  }

  void word_tables_name_every_value() {
    enum class Colour { Red, Green, Blue };
    constexpr bs::EnumWord<Colour> kAll[] = {{Colour::Red, "red"}, {Colour::Green, "green"}, {Colour::Blue, "blue"}};
    constexpr bs::EnumWord<Colour> kAliases[] = {
        {Colour::Blue, "blue"}, {Colour::Red, "red"}, {Colour::Green, "green"}, {Colour::Red, "rouge"}};
    constexpr bs::EnumWord<Colour> kNoGreen[] = {{Colour::Red, "red"}, {Colour::Blue, "blue"}};
    static_assert(bs::names_every_value(kAll, Colour::Blue));
    QVERIFY(bs::names_every_value(kAliases, Colour::Blue));   // any order, a value named twice
    QVERIFY(!bs::names_every_value(kNoGreen, Colour::Blue));  // a value added without its line
    QCOMPARE(std::string(bs::word_of(kNoGreen, Colour::Green, "?")), std::string("?"));
  }
};

QTEST_APPLESS_MAIN(TestText)
#include "test_text.moc"
