// SPDX-License-Identifier: GPL-3.0-or-later
// The Lens tab's "Calibrate from checkerboard…" dialog, driven on synthetic views of a known lens: the table shows
// every image's RMS or why it was rejected, Apply puts the lens into the tab as one undo step, Save… writes it,
// Cancel stops a run. scripts/screenshots runs it with BENCHSCOPE_SCREENSHOT_DIR set to collect
// docs/screenshots/checkerboard-dialog.png.
#include <QProgressBar>
#include <QPushButton>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QToolBar>
#include <cmath>

#include "../../support/checkerboard_lens.h"
#include "image_files/image_files.h"
#include "vision/checkerboard_dialog.h"
#include "vision/frames/synthetic_checkerboard.h"
#include "vision/lens_tab.h"
#include "vision/reprojection_tuner.h"

using namespace bs;

namespace {

// The lens on a 640x512 sensor.
vision::Lens truth_lens() { return bs::test::checkerboard_truth_lens(640, 512, 322.4, 254.1); }

// Writes nine views of a 10x7 board (30 mm squares) and a blank frame; returns their paths.
QStringList write_views(const QTemporaryDir& dir) {
  vision::CheckerboardRender how;
  how.board = vision::parse_board("10x7", 30);
  how.supersample = 2;
  how.noise_sigma = 1;
  QStringList paths;
  int n = 0;
  for (const char* p :
       {"0,0,0,250,0,0", "15,20,0,260,0,0", "-10,-25,15,240,40,30", "0,0,45,220,220,0", "0,0,-45,220,-220,0",
        "0,-40,0,230,0,200", "0,40,0,230,0,-200", "20,-30,35,230,150,130", "-20,30,-35,230,-150,-130"}) {
    const QString path = dir.filePath(QString("board-%1.png").arg(++n, 2, 10, QChar('0')));
    how.seed = static_cast<unsigned>(n);
    bs::image_files::write(path.toStdString(), vision::render_checkerboard(truth_lens(), vision::parse_pose(p), how));
    paths << path;
  }
  const QString blank = dir.filePath("lens-cap-on.png");
  bs::image_files::write(blank.toStdString(), cv::Mat(512, 640, CV_8UC1, cv::Scalar(20)));
  paths.insert(3, blank);
  return paths;
}

}  // namespace

class TestCheckerboardDialog : public QObject {
  Q_OBJECT
 private slots:
  void calibrates_applies_and_saves() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QStringList paths = write_views(dir);
    ui::LensTab tab;
    tab.tuner()->set_fisheye(cv::Mat(512, 640, CV_8UC3, cv::Scalar(0, 0, 0)));
    // The tab's toolbar offers the dialog.
    bool offered = false;
    for (QAction* a : tab.tuner()->tool_bar()->actions())
      offered |= a->text().startsWith("Calibrate from checkerboard");
    QVERIFY(offered);
    const vision::Lens before = tab.tuner()->params().lens;
    ui::CheckerboardDialog* d = tab.open_checkerboard_dialog();
    d->set_images(paths);
    d->set_board(10, 7, 30);
    d->set_model(vision::CalibrationModel::KannalaBrandt);
    d->set_fov(190);
    QCOMPARE(d->table()->rowCount(), 10);
    QVERIFY(!d->apply_button()->isEnabled());
    QSignalSpy done(d, &ui::CheckerboardDialog::calibration_finished);
    d->start();
    QVERIFY(d->running());
    QVERIFY(done.wait(300000));
    QCOMPARE(done.first().first().toBool(), true);
    QVERIFY2(d->result(), qPrintable(d->error()));
    const auto& r = *d->result();
    QCOMPARE(r.used(), 9);
    QCOMPARE(d->progress_bar()->value(), 1000);
    // Row 3 is the blank frame: rejected, with the reason in the table.
    QCOMPARE(d->table()->item(3, 0)->text(), QString("lens-cap-on.png"));
    QVERIFY(d->table()->item(3, 4)->text().startsWith("rejected: no checkerboard of 10x7 squares"));
    QCOMPARE(d->table()->item(3, 2)->text(), QString("–"));
    for (int row : {0, 1, 2, 4, 5, 6, 7, 8, 9}) {
      QCOMPARE(d->table()->item(row, 4)->text(), QString("used"));
      QCOMPARE(d->table()->item(row, 1)->text(), QString("54"));
      const double rms = d->table()->item(row, 2)->text().toDouble();
      QVERIFY(rms > 0 && rms < 0.3);
    }
    QVERIFY(d->summary_text().contains(QString("RMS %1 px").arg(r.rms_px, 0, 'f', 3)));
    const vision::Lens truth = truth_lens();
    QVERIFY(std::abs(r.lens.r_pp / truth.r_pp - 1) < 0.005);
    QVERIFY(std::hypot(r.lens.cx - truth.cx, r.lens.cy - truth.cy) < 1.0);
    QVERIFY(r.rms_px < 0.3);
    d->resize(980, 620);
    if (const QByteArray shots = qgetenv("BENCHSCOPE_SCREENSHOT_DIR"); !shots.isEmpty())
      d->grab().save(QString::fromUtf8(shots) + "/checkerboard-dialog.png", "PNG", 0);

    // Apply: the tab's lens becomes the calibrated one, as one undo step.
    QVERIFY(d->apply_button()->isEnabled());
    d->apply_button()->click();
    const vision::Lens applied = tab.tuner()->params().lens;
    QCOMPARE(applied.r_pp, r.lens.r_pp);
    QCOMPARE(applied.cx, r.lens.cx);
    QCOMPARE(applied.calibration.method, vision::LensCalibration::Method::Checkerboard);
    QCOMPARE(applied.calibration.images_used, 9);
    QCOMPARE(applied.calibration.images_rejected, 1);
    tab.tuner()->undo_action()->trigger();
    QCOMPARE(tab.tuner()->params().lens.r_pp, before.r_pp);
    QCOMPARE(tab.tuner()->params().lens.calibration.method, before.calibration.method);

    // Save…: a lens file that loads back to the calibrated lens.
    const QString saved = dir.filePath("calibrated.json");
    d->save(saved);
    const auto loaded = vision::load_tuner_json(saved.toStdString());
    QCOMPARE(loaded.lens.r_pp, r.lens.r_pp);
    QCOMPARE(loaded.lens.k, r.lens.k);
    QCOMPARE(*loaded.lens.calibration.rms_px, r.rms_px);
  }

  void cancel_stops_a_run() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QStringList paths;
    // Many copies of a blank frame: the run is cancelled while it looks for corners.
    const QString blank = dir.filePath("blank.png");
    bs::image_files::write(blank.toStdString(), cv::Mat(512, 640, CV_8UC1, cv::Scalar(128)));
    for (int i = 0; i < 200; ++i) {
      const QString p = dir.filePath(QString("blank-%1.png").arg(i));
      QFile::copy(blank, p);
      paths << p;
    }
    ui::CheckerboardDialog d(vision::TunerParams{});
    d.set_images(paths);
    QSignalSpy done(&d, &ui::CheckerboardDialog::calibration_finished);
    d.start();
    d.cancel();
    QVERIFY(done.wait(60000));
    QCOMPARE(done.first().first().toBool(), false);
    QVERIFY(!d.result());
    QCOMPARE(d.error(), QString("Cancelled."));
    QVERIFY(!d.apply_button()->isEnabled());
  }
};

QTEST_MAIN(TestCheckerboardDialog)
#include "test_checkerboard_dialog.moc"
