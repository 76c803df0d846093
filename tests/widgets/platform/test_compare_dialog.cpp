// SPDX-License-Identifier: GPL-3.0-or-later
// The compare dialog: a 10 % slower B with 8 repetitions shows one regression row (red); a higher threshold
// clears it; unchanged rows only when asked.
#include <QCheckBox>
#include <QTableWidget>
#include <QTest>

#include "../../support/run_on.h"
#include "platform/compare_dialog.h"

namespace {

bs::FlopsRun run(double scale) {
  auto r = bs::test::run_on<bs::FlopsRun>("robot", "GPU", "OpenCL");
  r.dims = 4;
  r.iterations = 40000;
  for (int w : {1024, 2048}) {
    bs::WorkerSample s{w, {}};
    for (int k = 0; k < 8; ++k)
      s.seconds.push_back(1e-3 * w / 1024 * (w == 2048 ? 0.8 : 1.0) * scale * (1 + 0.001 * k));
    r.samples.push_back(s);
  }
  return r;
}

}  // namespace

class TestCompareDialog : public QObject {
  Q_OBJECT
 private slots:
  void regression_row() {
    bs::ui::CompareDialog d({run(1.0)}, {}, {run(1.1)}, {}, "a.bsw", "b.bsw");
    QCOMPARE(d.regressions(), 1);
    QCOMPARE(d.table()->rowCount(), 1);
    // scripts/screenshots sets this to collect the dialog for the docs.
    if (const QByteArray dir = qgetenv("BENCHSCOPE_SCREENSHOT_DIR"); !dir.isEmpty())
      d.grab().save(QString::fromUtf8(dir) + "/compare-dialog.png", "PNG", 0);
    QCOMPARE(d.table()->item(0, 6)->text(), QString("regression"));
    QVERIFY(d.table()->item(0, 1)->text().endsWith("W=2048"));
    QVERIFY(d.table()->item(0, 0)->background().color().red() > d.table()->item(0, 0)->background().color().green());
    d.set_threshold_percent(20);
    QCOMPARE(d.regressions(), 0);
    QCOMPARE(d.table()->rowCount(), 0);  // unchanged rows hidden by default
    for (QCheckBox* c : d.findChildren<QCheckBox*>())
      if (c->text().contains("unchanged")) c->setChecked(true);
    QCOMPARE(d.table()->rowCount(), 1);
    QVERIFY(d.windowTitle().contains("a.bsw") && d.windowTitle().contains("b.bsw"));
  }
};

QTEST_MAIN(TestCompareDialog)
#include "test_compare_dialog.moc"
