// SPDX-License-Identifier: GPL-3.0-or-later
// The Headroom tab's view on synthetic measurements whose histograms are known by construction: one step line per
// phase and thread, each curve's maximum (and overflows) in the legend, the deadline line with the cycles beyond
// it counted per curve, the table's cells from core, the flags banner (non-real-time in red), and the choice of
// measurement kept across a reload.
#include <qcustomplot.h>
#include <QCheckBox>
#include <QComboBox>
#include <QLabel>
#include <QSpinBox>
#include <QTableWidget>
#include <QTest>

#include "headroom/headroom_view.h"
#include "headroom/latency_recorder.h"

using namespace bs::headroom;

namespace {

// Two phases x two threads, 1 kHz: 1000 cycles at 10 us (idle) or 20 us (load), plus 5 cycles at 150 us and, on
// the load's thread 1, one at 12.345 ms beyond the 10 ms limit.
bs::StoredHeadroom sample(std::int64_t id, bool realtime) {
  HeadroomMeasurement m;
  m.platform = "robot";
  m.tool = "benchscope probe";
  m.provenance.date = "2026-11-28T10:00:00Z";
  m.kernel.preempt_rt = true;
  m.kernel.governor = "performance";
  for (const std::string name : {"idle", "pipeline@30fps"}) {
    Phase p;
    p.name = name;
    for (int k = 0; k < 2; ++k) {
      LatencyRecorder r(10'000'000, 1000, 1'000'000);
      for (int i = 0; i < 1000; ++i) r.add(name == "idle" ? 10'000 : 20'000);
      for (int i = 0; i < 5; ++i) r.add(150'000);
      if (name != "idle" && k == 1) r.add(12'345'000);
      ThreadLatency t = r.result();
      t.index = k;
      t.policy = realtime ? "SCHED_FIFO" : "SCHED_OTHER";
      if (realtime) t.priority = 80;
      t.memory_locked = realtime;
      t.period_ns = 1'000'000;
      t.deadline_ns = 1'000'000;
      p.threads.push_back(t);
    }
    m.phases.push_back(p);
  }
  return {id, id + 10, m};
}

QString deadline_text(const QCustomPlot* plot) {
  for (int i = 0; i < plot->itemCount(); ++i)
    if (auto* t = qobject_cast<QCPItemText*>(plot->item(i))) return t->text();
  return {};
}

}  // namespace

class TestHeadroomView : public QObject {
  Q_OBJECT
 private slots:
  void draws_the_histogram_the_community_draws() {
    bs::ui::HeadroomView view;
    view.resize(1280, 800);
    QVERIFY(view.chooser()->count() == 0);
    view.set_measurements({sample(1, true)});
    const QCustomPlot* plot = view.plot();
    QCOMPARE(plot->graphCount(), 4);
    QCOMPARE(plot->yAxis->scaleType(), QCPAxis::stLogarithmic);
    QCOMPARE(plot->graph(0)->name(), QString("idle · T0, max 150 µs"));
    QCOMPARE(plot->graph(3)->name(), QString("pipeline@30fps · T1, max 12345 µs (1 beyond 10000 µs)"));
    QCOMPARE(plot->graph(0)->lineStyle(), QCPGraph::lsStepLeft);
    QVERIFY(plot->graph(0)->pen().style() != plot->graph(1)->pen().style());  // threads apart in greyscale
    QVERIFY(plot->graph(0)->pen().color() != plot->graph(2)->pen().color());  // phases by colour
    // The deadline starts at the period, 1000 us: only the 12.345 ms cycle lies beyond it.
    QCOMPARE(view.deadline()->value(), 1000);
    QString text = deadline_text(plot);
    QVERIFY2(text.startsWith("deadline 1000 µs"), qPrintable(text));
    QVERIFY2(text.contains("pipeline@30fps · T1: 1 beyond (0.0994 %)"), qPrintable(text));  // 1 of 1006
    QVERIFY2(text.contains("idle · T0: 0 beyond (0 %)"), qPrintable(text));
    // Moved to 100 us: the five 150 us cycles of every curve are beyond it too.
    view.deadline()->setValue(100);
    text = deadline_text(plot);
    QVERIFY2(text.contains("idle · T0: 5 beyond (0.498 %)"), qPrintable(text));  // 5 of 1005
    QVERIFY2(text.contains("pipeline@30fps · T1: 6 beyond (0.596 %)"), qPrintable(text));
    view.show_deadline()->setChecked(false);
    QVERIFY(deadline_text(plot).isEmpty());

    const QTableWidget* t = view.table();
    QCOMPARE(t->rowCount(), 4);
    const auto cell = [t](int row, const QString& column) {
      for (int c = 0; c < t->columnCount(); ++c)
        if (t->horizontalHeaderItem(c)->text() == column) return t->item(row, c)->text();
      return QString("<no column %1>").arg(column);
    };
    QCOMPARE(cell(0, "Phase"), QString("idle"));
    QCOMPARE(cell(0, "p50"), QString("10 us"));
    QCOMPARE(cell(0, "p99.9"), QString("150 us"));  // rank 1004 of 1005
    QCOMPARE(cell(3, "Max"), QString("12345 us"));
    QCOMPARE(cell(3, "Misses"), QString("0.10 % (1)"));
    QCOMPARE(cell(3, "Longest miss run"), QString("1"));
    QCOMPARE(cell(3, "n"), QString("1006"));
    QCOMPARE(cell(3, "Policy"), QString("SCHED_FIFO 80"));
    QVERIFY(!view.flags_label()->text().contains("non-real-time"));
  }

  void says_non_real_time_and_keeps_the_choice() {
    bs::ui::HeadroomView view;
    view.set_measurements({sample(1, true), sample(2, false)});
    QCOMPARE(view.chooser()->currentIndex(), 1);  // the newest comes to the front
    QVERIFY(view.chooser()->currentText().contains("non-real-time"));
    QVERIFY(view.flags_label()->isVisibleTo(&view));
    QVERIFY(view.flags_label()->text().contains("color:#b00000"));
    QVERIFY(view.flags_label()->text().contains("non-real-time (SCHED_OTHER)"));
    QVERIFY(view.select(1));
    view.set_measurements({sample(1, true), sample(2, false)});  // a reload
    QCOMPARE(view.chooser()->currentIndex(), 0);
    view.set_measurements({});
    QCOMPARE(view.chooser()->count(), 0);
    QVERIFY(!view.plot()->isVisibleTo(&view));
  }
};

QTEST_MAIN(TestHeadroomView)
#include "test_headroom_view.moc"
