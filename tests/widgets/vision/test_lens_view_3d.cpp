// SPDX-License-Identifier: GPL-3.0-or-later
// Needs an X display (VTK is GLX only here): registered DISPLAY, runs under xvfb-run.
#include <QApplication>
#include <QDir>
#include <QFile>
#include <QTest>

#include "vision/lens_tab.h"
#include "vision/lens_view_3d.h"
#include "vision/preview_pane.h"
#include "vision/reprojection_tuner.h"

using namespace bs;

namespace {

// Share of the centre 60x60 pixels that differ from the background colour (0.13, 0.14, 0.17).
double non_background_share(const QImage& img) {
  const QColor bg = QColor::fromRgbF(0.13f, 0.14f, 0.17f);
  int differ = 0, n = 0;
  for (int y = img.height() / 2 - 30; y < img.height() / 2 + 30; ++y)
    for (int x = img.width() / 2 - 30; x < img.width() / 2 + 30; ++x, ++n) {
      const QColor c = img.pixelColor(x, y);
      if (std::abs(c.red() - bg.red()) + std::abs(c.green() - bg.green()) + std::abs(c.blue() - bg.blue()) > 30)
        ++differ;
    }
  return static_cast<double>(differ) / n;
}

// Distinct colours among the centre pixels: a textured patch shows the chart's many colours, a flat one few.
int distinct_colours(const QImage& img) {
  QSet<QRgb> set;
  for (int y = img.height() / 2 - 40; y < img.height() / 2 + 40; ++y)
    for (int x = img.width() / 2 - 40; x < img.width() / 2 + 40; ++x) set.insert(img.pixel(x, y) & 0xF0F0F0);
  return static_cast<int>(set.size());
}

}  // namespace

class TestLensView3D : public QObject {
  Q_OBJECT
 private slots:
  void textured_sphere_is_visible_and_follows_the_lens() {
    ui::LensTab tab;
    tab.resize(1600, 900);
    tab.set_fisheye({}, {});  // the synthetic paper-lens frame
    tab.show();
    QVERIFY(QTest::qWaitForWindowExposed(&tab));
    ui::LensView3D* view = tab.view_3d();
    QVERIFY(view != nullptr);
    QVERIFY(view->textured_triangles() > 1000);
    QTRY_VERIFY_WITH_TIMEOUT(tab.tuner()->shown_generation() == tab.tuner()->requested_generation() &&
                                 !tab.tuner()->output_pane()->image().isNull(),
                             30000);
    QImage shot = view->grabFramebuffer();
    QVERIFY(!shot.isNull());
    QVERIFY2(non_background_share(shot) > 0.9, qPrintable(QString::number(non_background_share(shot))));
    QVERIFY2(distinct_colours(shot) > 20, qPrintable(QString::number(distinct_colours(shot))));
    // A narrower lens covers a smaller patch.
    const int before = view->textured_triangles();
    vision::Lens narrow = tab.tuner()->params().lens;
    narrow.fov_deg = 120;
    view->set_lens(narrow, tab.tuner()->params().view);
    // Same ring count, but the 120 degree patch fits the sensor while the paper circle is cut at top and bottom.
    QVERIFY(view->textured_triangles() > before);
    // The same frame rendered twice gives the same pixels (no uninitialised GL state).
    view->set_lens(tab.tuner()->params().lens, tab.tuner()->params().view);
    const QImage a = view->grabFramebuffer(), b = view->grabFramebuffer();
    QCOMPARE(a, b);
    // Mouse drag rotates the camera: the picture changes; the same drag back and forth is not needed to check it.
    const QPoint from(view->width() / 2, view->height() / 2), to = from + QPoint(80, 30);
    QTest::mousePress(view, Qt::LeftButton, {}, from);
    for (int k = 1; k <= 8; ++k) {
      QMouseEvent move(QEvent::MouseMove, from + (to - from) * k / 8, view->mapToGlobal(from + (to - from) * k / 8),
                       Qt::NoButton, Qt::LeftButton, Qt::NoModifier);
      QApplication::sendEvent(view, &move);
    }
    QTest::mouseRelease(view, Qt::LeftButton, {}, to);
    QVERIFY(view->grabFramebuffer() != a);
    view->reset_camera();
    QCOMPARE(view->grabFramebuffer(), a);
    if (const QByteArray dir = qgetenv("BENCHSCOPE_SCREENSHOT_DIR"); !dir.isEmpty()) {
      // A tuned state worth looking at: the robot's nose masked at the bottom of the frame, the view turned
      // left and down, three points clicked along a chart line.
      ui::ReprojectionTuner* t = tab.tuner();
      t->set_mask_editing(true);
      for (const QPointF q : {QPointF(470, 1023), QPointF(560, 930), QPointF(720, 930), QPointF(810, 1023)})
        t->add_mask_point(q);
      t->set_mask_editing(false);
      vision::TunerParams p = t->params();
      p.view.yaw_deg = 20;
      p.view.pitch_deg = -10;
      p.view.fov_deg = 120;
      t->set_params(p);
      QTRY_VERIFY_WITH_TIMEOUT(t->shown_generation() == t->requested_generation(), 30000);
      QDir().mkpath(dir);
      view->grab().save(dir + "/lens-view-3d.png", "PNG", 0);
      t->grab().save(dir + "/reprojection-tuner.png", "PNG", 0);
    }
  }
  void first_show_renders_the_synthetic_frame_in_the_background() {
    ui::LensTab tab;
    tab.resize(1200, 700);
    tab.show();  // no set_fisheye: the tab renders the paper-lens frame off the GUI thread
    QVERIFY(QTest::qWaitForWindowExposed(&tab));
    QTRY_VERIFY_WITH_TIMEOUT(!tab.tuner()->fisheye().empty(), 60000);
    QCOMPARE(tab.tuner()->fisheye().cols, 1280);
    QTRY_VERIFY_WITH_TIMEOUT(!tab.tuner()->output_pane()->image().isNull(), 30000);
    QVERIFY(tab.view_3d() != nullptr);
  }
  void no_qt5_in_the_process() {
    QFile maps("/proc/self/maps");
    QVERIFY(maps.open(QIODevice::ReadOnly));
    const QByteArray text = maps.readAll();
    QVERIFY2(!text.contains("libQt5"), "a Qt 5 library is loaded next to Qt 6");
    QVERIFY(text.contains("libvtkRenderingOpenGL2"));
  }
};

namespace {
int lens_view_3d_main(int argc, char** argv) {
  ui::set_vtk_default_surface_format();  // before QApplication, as app/gui/main.cpp does
  QApplication app(argc, argv);
  TestLensView3D test;
  return QTest::qExec(&test, argc, argv);
}
}  // namespace
BENCHSCOPE_TEST_CUSTOM_MAIN(lens_view_3d_main)
#include "test_lens_view_3d.moc"
