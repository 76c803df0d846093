// SPDX-License-Identifier: GPL-3.0-or-later
// The Lens tab's "Propose lines" and "Delete line" (issue #20 part 3: "or accepts long edges BenchScope
// proposes"): on a synthetic room capture with known truth, the button adds proposed lines as picked lines, one
// undo step; a selected line is deleted and undeleted; the fit over the proposals lands on the truth. scripts/
// screenshots runs it with BENCHSCOPE_SCREENSHOT_DIR set to collect docs/screenshots/lens-line-proposals.png.
#include <QAction>
#include <QCheckBox>
#include <QListWidget>
#include <QPushButton>
#include <QTest>
#include <cmath>

#include "../../support/room_lens.h"
#include "tuner_preview.h"
#include "vision/frames/synthetic_room.h"
#include "vision/lens/line_fit.h"
#include "vision/lens_tab.h"
#include "vision/preview_pane.h"
#include "vision/reprojection_tuner.h"

using namespace bs;
using bs::test::wait_for_preview;
using bs::ui::ReprojectionTuner;

namespace {

constexpr double kPi = 3.14159265358979323846;

}  // namespace

class TestLineProposals : public QObject {
  Q_OBJECT
 private slots:
  void propose_delete_undo_and_fit() {
    const vision::Lens truth = bs::test::room_truth_lens();
    const vision::RoomOptions room{.vignetting = 0.3, .noise = 0.005, .seed = 5};
    ui::LensTab tab;
    tab.resize(1500, 1120);  // tall enough for the whole line panel in the screenshot
    tab.show();
    ReprojectionTuner& t = *tab.tuner();
    t.set_fisheye(vision::render_room_fisheye(truth, room), "synthetic room, Kannala-Brandt 195°");
    // What Detect circle gives on this frame, a little off: equidistant with the right rim, the centre 6.4 px off.
    vision::TunerParams start = t.params();
    start.lens = truth;
    start.lens.type = vision::LensType::Equidistant;
    start.lens.k = {};
    start.lens.r_pp = (195 * kPi / 360) / 600;
    start.lens.cx += 5;
    start.lens.cy -= 4;
    start.view = vision::View{1280, 1024, 150, 0, 0, 0};
    t.set_params(start);
    QVERIFY(t.picked_lines().empty());
    QVERIFY(!t.propose_button()->toolTip().isEmpty());
    QCOMPARE(t.propose_button()->shortcut(), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_P));
    QVERIFY(!t.delete_line_button()->isEnabled());  // nothing selected

    // Propose: lines appear, in the list too, as one undo step that leaves the lens alone.
    QTest::mouseClick(t.propose_button(), Qt::LeftButton);
    const std::size_t proposed = t.picked_lines().size();
    qInfo("proposed %zu lines; %s", proposed, qPrintable(t.lines_summary_text()));
    QVERIFY(proposed >= 40);
    QCOMPARE(t.lines_list()->count(), static_cast<int>(proposed));
    QVERIFY(t.lines_list()->item(0)->text().contains("RMS"));
    QVERIFY(t.params() == start);
    for (const auto& l : t.picked_lines()) QVERIFY(l.size() >= 3);
    // Pressing it again adds nothing: every proposal is picked already.
    QCOMPARE(t.propose_lines(), 0);
    QCOMPARE(t.picked_lines().size(), proposed);

    // Select one in the list, delete it (one step), bring it back.
    t.lines_list()->setCurrentRow(3);
    QCOMPARE(t.selected_line(), 3);
    QVERIFY(t.delete_line_button()->isEnabled());
    const vision::PickedLine third = t.picked_lines()[3];
    QTest::mouseClick(t.delete_line_button(), Qt::LeftButton);
    QCOMPARE(t.picked_lines().size(), proposed - 1);
    QVERIFY(t.picked_lines()[3] != third);
    QCOMPARE(t.lines_list()->count(), static_cast<int>(proposed - 1));
    t.undo_action()->trigger();
    QCOMPARE(t.picked_lines().size(), proposed);
    QVERIFY(t.picked_lines()[3] == third);
    // A click near a line on the fisheye preview selects it.
    const cv::Point2d on = third[third.size() / 2];
    emit t.fisheye_pane()->clicked(QPointF(on.x + 1, on.y));
    QCOMPARE(t.selected_line(), 3);

    wait_for_preview(t);
    if (const QByteArray shots = qgetenv("BENCHSCOPE_SCREENSHOT_DIR"); !shots.isEmpty())
      QVERIFY(t.grab().save(QString::fromUtf8(shots) + "/lens-line-proposals.png", "PNG", 0));
    QVERIFY(t.grab().save(QString(BENCHSCOPE_BINARY_DIR) + "/lens-line-proposals.png"));

    // The fit over the proposals (outlier lines rejected): on the truth within a pixel; one undo step back.
    QVERIFY(t.reject_lines_box()->isChecked());
    const auto fit = t.fit_lens_to_lines();
    const double centre_err = std::hypot(fit.lens.cx - truth.cx, fit.lens.cy - truth.cy);
    const double r_pp_err = std::abs(fit.lens.r_pp / truth.r_pp - 1);
    qInfo("fit: %zu lines left out; RMS %.3f -> %.3f px; centre error %.3f px, r_pp error %.3f %%",
          fit.rejected_lines.size(), fit.before.rms_px, fit.after.rms_px, centre_err, 100 * r_pp_err);
    QVERIFY(t.line_fit_text().contains("left out"));
    QVERIFY(centre_err < 1.0);
    QVERIFY(r_pp_err < 0.005);
    t.undo_action()->trigger();
    QVERIFY(t.params() == start);
    QCOMPARE(t.picked_lines().size(), proposed);  // the lens went back, the lines stay

    // Undo the proposals: no lines, the lens untouched; redo brings them back.
    t.undo_action()->trigger();  // the undelete of line 4 was an undo; the step before is the proposal
    QVERIFY(t.picked_lines().empty());
    QCOMPARE(t.lines_list()->count(), 0);
    QCOMPARE(t.selected_line(), -1);
    QVERIFY(t.params() == start);
    t.redo_action()->trigger();
    QCOMPARE(t.picked_lines().size(), proposed);
  }
  void clicks_and_clear_are_undo_steps_too() {
    ReprojectionTuner t;
    t.set_fisheye(vision::render_room_fisheye(bs::test::room_truth_lens()));
    t.add_source_point({100, 100});
    t.add_source_point({200, 110});
    t.add_source_point({300, 130});
    t.new_line();
    t.add_source_point({400, 400});
    QCOMPARE(t.picked_lines().size(), std::size_t{2});
    t.undo_action()->trigger();
    QCOMPARE(t.picked_lines().size(), std::size_t{1});
    QCOMPARE(t.picked_lines()[0].size(), std::size_t{3});
    t.clear_line_points();
    QVERIFY(t.picked_lines().empty());
    t.undo_action()->trigger();
    QCOMPARE(t.picked_lines().size(), std::size_t{1});
    // Reset takes the lens back, not the lines.
    t.reset_action()->trigger();
    QCOMPARE(t.picked_lines().size(), std::size_t{1});
  }
};

QTEST_MAIN(TestLineProposals)
#include "test_line_proposals.moc"
