// SPDX-License-Identifier: GPL-3.0-or-later
// Scenario (issue #43.8): a lab calibrates the paper camera's lens from photos of a printed checkerboard in the Lens
// tab. Its optics show a lit disc of 174 degrees, the lens file says 195, and the board was held no further than
// about 55 degrees off the axis. On main the fitted 195-degree circle lay far outside the rim the images show and
// nothing said so, and the lens was used out to the view's edge (75 degrees) with only a vague word of extrapolation.
// The person: opens the paper workspace, the Lens tab, "Calibrate from checkerboard…", adds the photos through the
// file dialog, picks the equidistant model, Calibrate, reads the summary, Apply, Close; then "Save lens for this
// frame" and "Detect circle" on the paper's capture. Each place must say where the lens is not to be trusted,
// with both numbers.
#include <QComboBox>
#include <QLabel>
#include <QTest>
#include <QToolButton>
#include <cmath>

#include "image_files/image_files.h"
#include "vision/checkerboard_dialog.h"
#include "vision/frames/synthetic_checkerboard.h"
#include "vision/lens/lens.h"
#include "vision/lens_tab.h"
#include "vision/reprojection_tuner.h"

#include "../../../support/scenario_window.h"

using bs::test::ModalAnswerer;

namespace {

// The photos: a 10x7 board of 30 mm squares through the paper's optics as they are (the disc ends at 174 degrees),
// straight ahead and swung out to about 45-55 degrees in every direction, as a lab holds it.
QStringList write_photos(const QString& folder) {
  bs::vision::Lens optics = bs::vision::Lens::paper();
  optics.fov_deg = 174;
  bs::vision::CheckerboardRender how;
  how.board = bs::vision::parse_board("10x7", 30);
  how.supersample = 2;
  QStringList names;
  int n = 0;
  for (const char* pose : {"0,0,0,300,0,0", "0,0,45,300,300,0", "0,0,-45,300,-300,0", "0,-45,0,300,0,300",
                           "0,45,0,300,0,-300", "20,-30,35,300,200,170", "-20,30,-35,300,-200,-170"}) {
    const QString name = QStringLiteral("board-%1.png").arg(++n);
    how.seed = static_cast<unsigned>(n);
    bs::image_files::write((folder + '/' + name).toStdString(),
                           bs::vision::render_checkerboard(optics, bs::vision::parse_pose(pose), how));
    names << name;
  }
  return names;
}

// The visible tool button under `parent` whose action's text starts with `text`, as a person finds it (the tab's
// tool bar shows its actions as buttons that wrap onto a second row).
QToolButton* tool_button(QWidget* parent, const QString& text) {
  for (QToolButton* b : parent->findChildren<QToolButton*>())
    if (b->isVisible() && b->defaultAction() && bs::test::plain(b->defaultAction()->text()).startsWith(text)) return b;
  return nullptr;
}

bs::ui::CheckerboardDialog* open_dialog() {
  for (QWidget* w : QApplication::topLevelWidgets())
    if (auto* d = qobject_cast<bs::ui::CheckerboardDialog*>(w); d && d->isVisible()) return d;
  return nullptr;
}

}  // namespace

class TestScenarioLensLimits : public QObject {
  Q_OBJECT
 private slots:
  void a_lens_beyond_its_evidence_says_so_with_both_numbers() {
    QTemporaryDir dir;
    const QString photos = dir.filePath("photos");
    QVERIFY(QDir().mkpath(photos));
    const QStringList names = write_photos(photos);
    bs::ui::MainWindow w;
    BS_STEP(bs::test::open_paper_window(w, dir));
    QVERIFY(bs::test::open_tab(w, "Lens"));
    bs::ui::ReprojectionTuner* tuner = w.lens_tab()->tuner();
    // The paper's capture is the frame the tab tunes (1280x1024, the lens its sidecar records).
    QVERIFY(bs::test::wait_until([&] { return tuner->fisheye().cols == 1280; }, 500));

    QToolButton* calibrate = tool_button(tuner, "Calibrate from checkerboard");
    QVERIFY2(calibrate, "no \"Calibrate from checkerboard…\" in the Lens tab's tool bar");
    bs::test::click(calibrate);
    QVERIFY(bs::test::wait_until([] { return open_dialog() != nullptr; }, 100));
    bs::ui::CheckerboardDialog* dialog = open_dialog();
    ModalAnswerer person;
    person.expect("Checkerboard photos (file dialog)", ModalAnswerer::titled("Checkerboard photos"),
                  [&](QWidget* d) { bs::test::choose_files(d, photos, names); });
    QAbstractButton* add = bs::test::widget_with_text<QPushButton>(dialog, "Add images…");
    QVERIFY(add);
    bs::test::click(add);
    QVERIFY2(bs::test::wait_until([&] { return person.done(); }, 500), qPrintable(person.report()));
    QCOMPARE(dialog->images().size(), names.size());
    // The lens file's model: equidistant (k = 0), chosen from the box with the keyboard.
    auto* model = dialog->findChild<QComboBox*>();
    QVERIFY(model);
    model->setFocus();
    bs::test::key(model, Qt::Key_End);
    QVERIFY(model->currentText().startsWith("Equidistant"));
    bs::test::click(bs::test::widget_with_text<QPushButton>(dialog, "Calibrate"));
    QVERIFY(bs::test::wait_until([&] { return !dialog->running() && (dialog->result() || !dialog->error().isEmpty()); },
                                 6000));
    QVERIFY2(dialog->result(), qPrintable(dialog->error()));
    const auto& result = *dialog->result();

    // 1. The dialog: the fitted 195-degree circle against the photos' own rim, both radii, in what the person reads.
    const QString summary = dialog->summary_text();
    QVERIFY2(summary.contains("disagrees with the image's detected rim"), qPrintable(summary));
    QVERIFY2(result.rim && result.rim->disagrees, "the photos' rim agrees with the fit: the scenario lost its point");
    for (const double radius : {result.rim->fitted_radius_px, result.rim->rim_radius_px})
      QVERIFY2(summary.contains(QString::number(radius, 'f', 1)), qPrintable(summary));
    bs::test::screenshot(dialog, "lens-limits-dialog");

    // 2. Applied: the view reaches further off the axis than the corners did, and the tab says so in sight.
    bs::test::click(dialog->apply_button());
    QCOMPARE(tuner->params().lens.calibration.method, bs::vision::LensCalibration::Method::Checkerboard);
    bs::test::click(bs::test::widget_with_text<QPushButton>(dialog, "Close"));
    QVERIFY(bs::test::wait_until([] { return open_dialog() == nullptr; }, 100));
    const QString note = tuner->extrapolation_note();
    const double covered = *tuner->params().lens.calibration.covered_deg;
    QVERIFY2(note.contains(QStringLiteral("covered %1 degrees").arg(std::round(covered))), qPrintable(note));
    QVERIFY2(note.contains("reaches 75 degrees"), qPrintable(note));
    auto* shown = tuner->findChild<QLabel*>(QStringLiteral("extrapolationNote"));
    QVERIFY(shown && shown->isVisible());
    bs::test::screenshot(&w, "lens-limits-applied");

    // 3. Kept for the frame, then Detect circle on the paper's capture: its rim against the calibrated lens's circle.
    QToolButton* save = tool_button(tuner, "Save lens for this frame");
    QVERIFY(save && save->isEnabled());
    bs::test::click(save);
    bs::test::click(tool_button(tuner, "Detect circle"));
    QVERIFY(bs::test::wait_until([&] { return !tuner->circle_warning().isEmpty(); }, 500));
    const QString warning = tuner->circle_warning();
    QVERIFY2(warning.contains("The calibrated lens"), qPrintable(warning));
    QVERIFY2(warning.contains(" px"), qPrintable(warning));
    QVERIFY2(tuner->status_text().contains("The calibrated lens"), qPrintable(tuner->status_text()));
    bs::test::screenshot(&w, "lens-limits-tab");
  }
};

BENCHSCOPE_SCENARIO_MAIN(TestScenarioLensLimits)
#include "test_scenario_lens_limits.moc"
