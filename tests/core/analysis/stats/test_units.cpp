// SPDX-License-Identifier: GPL-3.0-or-later
#include <QTest>
#include <cmath>

#include "analysis/stats/units.h"

class TestUnits : public QObject {
  Q_OBJECT
 private slots:
  void si_prefixes() {
    QCOMPARE(bs::format_si(5.25e12, "FLOPS"), std::string("5.25 TFLOPS"));
    QCOMPARE(bs::format_si(15.54e9, "FLOPS"), std::string("15.54 GFLOPS"));
    QCOMPARE(bs::format_si(440e9, "FLOPS"), std::string("440.00 GFLOPS"));
    QCOMPARE(bs::format_si(0.0, "FLOPS"), std::string("0.00 FLOPS"));
    QCOMPARE(bs::format_si(-2.5e3, "W", 1), std::string("-2.5 kW"));
    QCOMPARE(bs::format_si(4.73e-6, "s"), std::string("4.73 \xC2\xB5s"));
    QCOMPARE(bs::format_si(6.21e-3, "s"), std::string("6.21 ms"));
    QCOMPARE(bs::format_si(std::nan(""), "W"), std::string("NaN W"));
    QCOMPARE(bs::si_exponent(999.0), 0);
    QCOMPARE(bs::si_exponent(1000.0), 3);
  }
  void mean_sd() {
    QCOMPARE(bs::format_mean_sd(6.21, 0.99, 200, "ms"), std::string("6.21 \xC2\xB1 0.99 ms (n = 200)"));
  }
};

QTEST_APPLESS_MAIN(TestUnits)
#include "test_units.moc"
