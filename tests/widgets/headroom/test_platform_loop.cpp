// SPDX-License-Identifier: GPL-3.0-or-later
// The Platforms tab's control-loop requirement on the paper's sample data: with no headroom measurement every
// platform is unknown and none is recommended; a measurement that passes makes its platform the choice again, one
// that fails is said with its margin; a mistyped requirement is shown in red and ignored. The requirement is part of
// the decision the workspace keeps (issue #43.2, store/decision_store.h): set by a person it is emitted, a mistyped
// one is not, and a stored one comes back.
#include <QCheckBox>
#include <QLabel>
#include <QLineEdit>
#include <QSignalSpy>
#include <QTest>

#include "../../support/headroom_samples.h"
#include "../../support/paper_sample.h"
#include "platform/platform_view.h"

using namespace bs::headroom;

namespace {

// p99.9 of its 1001 cycles is the first of the two late ones.
HeadroomMeasurement loop_on(const std::string& platform, int late_us) {
  return bs::test::loop_measurement(platform, {{"pipeline@30fps", bs::test::loop_thread(999, 15, {late_us, late_us})}});
}

}  // namespace

class TestPlatformLoop : public QObject {
  Q_OBJECT
 private slots:
  void loop_requirement_decides() {
    auto [runs, traces, pipelines] = bs::test::load_paper_sample();
    bs::ui::PlatformView view;
    view.set_data(runs, traces);
    QCOMPARE(view.recommendation(), QString("NUC"));
    view.set_loop_requirement("1kHz,p99.9<=200us,load=pipeline@30fps");
    QCOMPARE(view.recommendation(), QString());  // nobody measured: unknown everywhere, nothing passes
    QVERIFY(view.summary_text().contains("NUC <b>unknown</b> (no headroom measurement)"));
    // p99.9 of 1001 cycles is the first late one: 150 us passes on the Jetson, 450 us fails on the NUC.
    view.set_headroom({loop_on("Jetson TX2", 150), loop_on("NUC", 450)});
    QCOMPARE(view.recommendation(), QString("Jetson TX2"));
    const QString summary = view.summary_text();
    QVERIFY2(summary.contains("Jetson TX2 <b>passes</b>"), qPrintable(summary));
    QVERIFY2(summary.contains("NUC <b>FAILS</b> (p99.9 (pipeline@30fps) 250 us over the limit of 200 us (2.25x))"),
             qPrintable(summary));
    view.loop_edit()->setText("1kHz,p99.9<=200");
    emit view.loop_edit()->editingFinished();
    QVERIFY(view.summary_text().contains("Control loop ignored"));
    QCOMPARE(view.recommendation(), QString("NUC"));  // ignored: the other constraints (none) decide
    view.loop_check()->setChecked(false);
    QVERIFY(!view.summary_text().contains("Control loop"));
  }

  void loop_requirement_is_part_of_the_kept_decision() {
    bs::ui::PlatformView view;
    QSignalSpy edited(&view, &bs::ui::PlatformView::decision_edited);
    QVERIFY(view.decision().loop.empty());
    // A person ticks "Control loop:" (the example requirement in the field): one decision edited, with the loop.
    view.loop_check()->click();
    QCOMPARE(edited.size(), 1);
    const auto ticked = edited.at(0).at(0).value<bs::StoredDecision>();
    QCOMPARE(ticked.loop, view.loop_edit()->text().toStdString());
    QVERIFY(ticked.constrained());
    // Mistyped: ignored by the verdicts, so not part of the decision either.
    view.loop_edit()->setText("1kHz,p99.9<=200");
    emit view.loop_edit()->editingFinished();
    QCOMPARE(edited.size(), 2);
    QVERIFY(edited.at(1).at(0).value<bs::StoredDecision>().loop.empty());
    // The workspace's stored requirement comes back ticked, without a decision edited.
    bs::StoredDecision stored = view.decision();  // the battery and load as the view has them, the loop stored
    stored.loop = "500Hz,p99<=1ms";
    view.apply_decision(stored);
    QCOMPARE(edited.size(), 2);
    QVERIFY(view.loop_check()->isChecked());
    QCOMPARE(view.loop_edit()->text(), QString("500Hz,p99<=1ms"));
    QVERIFY(view.loop_requirement());
    QCOMPARE(view.decision(), stored);
    view.apply_decision(std::nullopt);  // nothing stored: no requirement
    QVERIFY(!view.loop_check()->isChecked());
    QVERIFY(!view.loop_requirement());
  }
};

QTEST_MAIN(TestPlatformLoop)
#include "test_platform_loop.moc"
