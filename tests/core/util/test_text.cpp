// SPDX-License-Identifier: GPL-3.0-or-later
// The shared text helpers (util/text.h): ASCII white space off both ends, ASCII lower case, UTF-8 left intact
// whatever the C library's locale says.
#include <clocale>

#include <QTest>

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
};

QTEST_APPLESS_MAIN(TestText)
#include "test_text.moc"
