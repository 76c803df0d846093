// SPDX-License-Identifier: GPL-3.0-or-later
// Worker counts on the FLOPS axes read compactly: 1k, 256k, 1.02M.
#include <QTest>

#include "common/count_tickers.h"

class TestCountTickers : public QObject {
  Q_OBJECT
 private slots:
  void worker_ticks_are_compact() {
    QCOMPARE(bs::ui::compact_count(0), QString("0"));
    QCOMPARE(bs::ui::compact_count(1), QString("1"));
    QCOMPARE(bs::ui::compact_count(750), QString("750"));
    QCOMPARE(bs::ui::compact_count(1000), QString("1k"));
    QCOMPARE(bs::ui::compact_count(256000), QString("256k"));
    QCOMPARE(bs::ui::compact_count(1e6), QString("1M"));
    QCOMPARE(bs::ui::compact_count(1024000), QString("1.02M"));
    QCOMPARE(bs::ui::compact_count(999999.6), QString("1M"));
    QCOMPARE(bs::ui::compact_count(0.5), QString("0.5"));
  }
};

QTEST_MAIN(TestCountTickers)
#include "test_count_tickers.moc"
