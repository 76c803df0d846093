// SPDX-License-Identifier: GPL-3.0-or-later
#include <QAction>
#include <QDoubleSpinBox>
#include <QSignalSpy>
#include <QSlider>
#include <QTemporaryDir>
#include <QTest>

#include "tuner_preview.h"
#include "vision/frames/synthetic.h"
#include "vision/preview_pane.h"
#include "vision/reprojection_tuner.h"

using namespace bs;
using bs::test::wait_for_preview;
using bs::ui::ReprojectionTuner;

namespace {

// A small synthetic fisheye (160 degrees, so the test chart fills the image circle) keeps the test fast.
cv::Mat small_fisheye(vision::Lens* lens_out = nullptr) {
  vision::Lens lens;
  lens.width = 320;
  lens.height = 256;
  lens.fov_deg = 160;
  lens.r_pp = (80 * 3.14159265358979 / 180) / 110;  // image circle radius 110 px
  lens.cx = 165;
  lens.cy = 126;
  if (lens_out) *lens_out = lens;
  return vision::render_fisheye(lens);
}

}  // namespace

class TestReprojectionTuner : public QObject {
  Q_OBJECT
 private slots:
  void slider_drag_is_one_undo_step_through_the_actions() {
    ReprojectionTuner t;
    t.resize(1100, 700);
    t.show();
    t.set_fisheye(small_fisheye());
    vision::TunerParams start = t.params();
    start.view = vision::View{320, 256, 120, 0, 0, 0};
    t.set_params(start);
    wait_for_preview(t, 20000);
    QCOMPARE(t.output_pane()->image().size(), QSize(320, 256));
    QSignalSpy changed(&t, &ReprojectionTuner::lens_changed);
    QVERIFY(!t.undo_action()->isEnabled());
    // A drag: the slider is held down while its value moves through 25 positions.
    t.yaw_slider()->setSliderDown(true);
    for (int v = 10; v <= 250; v += 10) t.yaw_slider()->setValue(v);
    t.yaw_slider()->setSliderDown(false);
    QCOMPARE(t.params().view.yaw_deg, 25.0);
    QCOMPARE(changed.count(), 25);
    QCOMPARE(changed.last().at(1).value<vision::View>().yaw_deg, 25.0);
    wait_for_preview(t, 20000);  // newest request wins: the shown preview is the last one
    QVERIFY(t.undo_action()->isEnabled());
    t.undo_action()->trigger();
    QCOMPARE(t.params().view.yaw_deg, 0.0);
    QCOMPARE(t.yaw_slider()->value(), 0);  // controls follow the state
    QVERIFY(!t.undo_action()->isEnabled());
    t.redo_action()->trigger();
    QCOMPARE(t.params().view.yaw_deg, 25.0);
    // Issue #23.10: Ctrl+Z with the cursor in a number field undoes the lens change, not the field's typing;
    // Ctrl+Shift+Z redoes it.
    t.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&t));
    t.r_pp_spin()->setFocus();
    QTRY_VERIFY(t.r_pp_spin()->hasFocus());
    QTest::keyClick(t.r_pp_spin(), Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(t.params().view.yaw_deg, 0.0);
    QCOMPARE(t.yaw_slider()->value(), 0);
    QTest::keyClick(t.r_pp_spin(), Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    QCOMPARE(t.params().view.yaw_deg, 25.0);
    QVERIFY(t.yaw_slider()->minimumWidth() >= 360);  // about one pixel per degree
    // A separate edit of another field is its own step; Reset returns to the start, undoably.
    t.r_pp_spin()->setValue(t.r_pp_spin()->value() * 1.1);
    QVERIFY(std::abs(t.params().lens.r_pp - start.lens.r_pp * 1.1) < 1e-7);
    t.reset_action()->trigger();
    QVERIFY(t.params() == start);
    t.undo_action()->trigger();
    QVERIFY(std::abs(t.params().lens.r_pp - start.lens.r_pp * 1.1) < 1e-7);
    t.undo_action()->trigger();
    QCOMPARE(t.params().lens.r_pp, start.lens.r_pp);
    QCOMPARE(t.params().view.yaw_deg, 25.0);
  }
  void masks_lines_and_auto_calibration() {
    ReprojectionTuner t;
    t.show();
    vision::Lens truth;
    t.set_fisheye(small_fisheye(&truth));
    vision::TunerParams p = t.params();
    p.lens.fov_deg = 160;
    p.view = vision::View{320, 256, 120, 0, 0, 0};
    t.set_params(p);
    // Auto-calibration finds the circle and sets principal point and r_pp as one undo step.
    const auto circle = t.auto_calibrate();
    QVERIFY(circle.has_value());
    QVERIFY(std::abs(t.params().lens.cx - truth.cx) < 2 && std::abs(t.params().lens.cy - truth.cy) < 2);
    QVERIFY(std::abs(t.params().lens.r_pp - truth.r_pp) / truth.r_pp < 0.02);
    t.undo_action()->trigger();
    QCOMPARE(t.params().lens.cx, -1.0);
    t.redo_action()->trigger();
    // A mask polygon clicked on the fisheye: blanks the view where it covers the source.
    t.set_mask_editing(true);
    for (const QPointF q : {QPointF(100, 60), QPointF(230, 60), QPointF(230, 200), QPointF(100, 200)})
      t.add_mask_point(q);
    t.set_mask_editing(false);
    QCOMPARE(t.params().masks.size(), std::size_t{1});
    QCOMPARE(t.params().masks[0].size(), std::size_t{4});
    wait_for_preview(t, 20000);
    const QImage masked = t.output_pane()->image();
    QCOMPARE(masked.pixelColor(160, 128), QColor(64, 64, 64));  // the centre is under the mask
    t.undo_action()->trigger();
    QVERIFY(t.params().masks.empty());
    wait_for_preview(t, 20000);
    QVERIFY(t.output_pane()->image().pixelColor(160, 128) != QColor(64, 64, 64));
    // Line tool: the residual text reports RMS and max in pixels.
    t.add_line_point({10, 10});
    t.add_line_point({20, 20});
    QVERIFY(t.line_residual_text().contains("1 more"));
    t.add_line_point({30, 31});  // off by 1 px: TLS distances 0.116, 0.230, 0.114 px (worked by hand)
    QVERIFY2(t.line_residual_text().contains("RMS 0.16 px, max 0.23 px (n = 3)"), qPrintable(t.line_residual_text()));
    // Save and load: the loaded file is an undoable change.
    QTemporaryDir dir;
    t.save_json(dir.filePath("lens.json"));
    vision::TunerParams saved = t.params();
    t.yaw_slider()->setValue(300);
    t.load_json(dir.filePath("lens.json"));
    QVERIFY(t.params() == saved);
    t.export_lut(dir.filePath("view.bslut"));
    QCOMPARE(vision::read_lut(dir.filePath("view.bslut").toStdString()).cols, 320);
  }
};

QTEST_MAIN(TestReprojectionTuner)
#include "test_reprojection_tuner.moc"
