// SPDX-License-Identifier: GPL-3.0-or-later
// The frame triptych: its three images are core's (render_triptych), zoom and pan move the three panes together,
// the inspector's values are core's (source_of / output_of, the raw and demosaiced samples), the newest lens
// request wins, 16-bit frames go through the window, Figure 3 exports as PNG and PDF, and the Frames tab lists a
// workspace's frames.
#include <QFile>
#include <QFileInfo>
#include <QLabel>
#include <QListWidget>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QWheelEvent>

#include <cstring>

#include "triptych_panels.h"
#include "vision/frame_triptych.h"
#include "vision/frames/frame_image.h"
#include "vision/frames/synthetic.h"
#include "vision/frames_view.h"
#include "vision/image_pane.h"
#include "vision/lens/view_geometry.h"
#include "workspace/import_controller.h"
#include "workspace/registry.h"

using namespace bs;

namespace {

vision::Lens small_lens() {
  vision::Lens lens = vision::Lens::paper();
  lens.r_pp *= 4;
  lens.width = 320;
  lens.height = 256;
  return lens;
}

Frame small_frame(int bits) {
  const vision::Lens lens = small_lens();
  const cv::Mat raw = vision::mosaic(vision::render_fisheye(lens, bits), vision::BayerPattern::BGGR);
  Frame f;
  f.label = "small";
  f.width = raw.cols;
  f.height = raw.rows;
  f.bit_depth = bits;
  f.pattern = "BGGR";
  f.synthetic = true;
  vision::View view;
  view.width = 320;
  view.height = 256;
  f.lens_json = vision::lens_to_json(lens, view).dump();
  f.pixels.assign(raw.datastart, raw.dataend);
  return f;
}

double max_diff(const cv::Mat& a, const cv::Mat& b) {
  return a.size() == b.size() ? cv::norm(a, b, cv::NORM_INF) : 1e9;
}

void wheel(QWidget* w, QPointF at, int delta) {
  QWheelEvent e(at, w->mapToGlobal(at), QPoint(), QPoint(0, delta), Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase,
                false);
  QApplication::sendEvent(w, &e);
}

}  // namespace

class TestFrameTriptych : public QObject {
  Q_OBJECT
 private slots:
  void images_are_cores() {
    ui::FrameTriptych t;
    t.resize(1200, 500);
    const Frame f = small_frame(8);
    t.set_frame(f);
    QVERIFY(t.wait_until_rendered(30000));
    const auto fl = vision::lens_for_frame(f);
    QVERIFY(fl.from_frame);
    const auto want = vision::render_triptych(f, vision::DemosaicMethod::Bilinear, fl.lens, fl.view);
    QCOMPARE(max_diff(t.images().mosaic, want.mosaic), 0.0);
    QCOMPARE(max_diff(t.images().demosaiced, want.demosaiced), 0.0);
    QCOMPARE(max_diff(t.images().reprojected, want.reprojected), 0.0);
    QVERIFY(t.captions()[0].startsWith("(a)") && t.captions()[1].startsWith("(b)") &&
            t.captions()[2].startsWith("(c)"));
    QVERIFY(t.captions()[0].contains("BGGR"));

    QSignalSpy rendered(&t, &ui::FrameTriptych::rendered);
    t.set_demosaic_method(vision::DemosaicMethod::MalvarHeCutler);
    QVERIFY(t.wait_until_rendered(30000));
    QCOMPARE(rendered.count(), 1);
    const auto mhc = vision::render_triptych(f, vision::DemosaicMethod::MalvarHeCutler, fl.lens, fl.view);
    QCOMPARE(max_diff(t.images().demosaiced, mhc.demosaiced), 0.0);
    QVERIFY(max_diff(t.images().demosaiced, want.demosaiced) > 0);  // the method really changed the pixels
    QVERIFY(t.captions()[1].contains("Malvar"));
  }

  void banner_says_how_the_lens_was_obtained() {
    // Issue #20 part 4: the frame's lens file records its calibration; the Frames banner shows it.
    Frame f = small_frame(8);
    auto [lens, view] = vision::lens_from_json(nlohmann::json::parse(f.lens_json));
    lens.calibration.method = vision::LensCalibration::Method::CircleFit;
    lens.calibration.rms_px = 0.05;
    f.lens_json = vision::lens_to_json(lens, view).dump();
    ui::FrameTriptych t;
    t.set_frame(f);
    QVERIFY2(t.banner_text().contains("Lens: recorded with the capture"), qPrintable(t.banner_text()));
    QVERIFY2(t.banner_text().contains("obtained by circle-fit, RMS 0.05 px"), qPrintable(t.banner_text()));
    // Issue #32.1: a lens from elsewhere (the Lens tab) is named as such, not as the frame's.
    t.set_lens(lens, view, "tuned in the Lens tab, not saved");
    QVERIFY2(t.banner_text().contains("Lens: tuned in the Lens tab, not saved"), qPrintable(t.banner_text()));
    QVERIFY(t.wait_until_rendered(30000));
  }

  void newest_lens_wins() {
    ui::FrameTriptych t;
    const Frame f = small_frame(8);
    t.set_frame(f);
    vision::Lens lens = small_lens();
    vision::View view;
    view.width = 240;
    view.height = 200;
    for (int yaw = 0; yaw <= 30; yaw += 3) {  // a tuner dragging a slider: eleven requests in a row
      view.yaw_deg = yaw;
      t.set_lens(lens, view);
    }
    QVERIFY(t.wait_until_rendered(30000));
    QCOMPARE(t.view().yaw_deg, 30.0);
    const auto want = vision::render_triptych(f, vision::DemosaicMethod::Bilinear, lens, view);
    QCOMPARE(max_diff(t.images().reprojected, want.reprojected), 0.0);
    QVERIFY(t.pane(2)->title().contains("240×200"));
  }

  void zoom_and_pan_are_synchronised() {
    ui::FrameTriptych t;
    t.resize(1200, 500);
    t.show();
    t.set_frame(small_frame(8));
    QVERIFY(t.wait_until_rendered(30000));
    ui::ImagePane* a = t.pane(0);
    const QPointF anchor(a->width() * 0.3, a->height() * 0.6);
    const QPointF under_before = a->widget_to_image(anchor);
    wheel(a, anchor, 240);  // two notches: 1.25^2
    QVERIFY(std::abs(a->zoom() - 1.5625) < 1e-9);
    QVERIFY(QLineF(a->widget_to_image(anchor), under_before).length() < 1e-6);  // zoom about the cursor
    for (int i = 1; i < 3; ++i) {
      QCOMPARE(t.pane(i)->zoom(), a->zoom());
      QCOMPARE(t.pane(i)->centre(), a->centre());
    }
    // Drag the reprojected pane: every pane follows.
    ui::ImagePane* c = t.pane(2);
    const QPoint from(c->width() / 2, c->height() / 2);
    QTest::mousePress(c, Qt::LeftButton, Qt::NoModifier, from);
    QMouseEvent move(QEvent::MouseMove, QPointF(from + QPoint(40, -25)),
                     c->mapToGlobal(QPointF(from + QPoint(40, -25))), Qt::NoButton, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(c, &move);
    QTest::mouseRelease(c, Qt::LeftButton, Qt::NoModifier, from + QPoint(40, -25));
    QVERIFY(c->centre() != a->centre() || c->centre() == t.pane(1)->centre());
    QCOMPARE(t.pane(0)->centre(), c->centre());
    QCOMPARE(t.pane(1)->centre(), c->centre());
    QVERIFY(c->centre().x() < 0.5 && c->centre().y() > 0.5);  // dragged right and up: the view moved left, down
  }

  void inspector_values_are_cores() {
    ui::FrameTriptych t;
    t.resize(1200, 500);
    const Frame f = small_frame(8);
    t.set_frame(f);
    QVERIFY(t.wait_until_rendered(30000));
    const cv::Mat raw = vision::frame_to_mat(f);
    // From the reprojected pane: output pixel -> fisheye by source_of.
    const cv::Point out(150, 90);
    const ui::PixelInspection r = t.inspect(2, QPointF(out.x + 0.5, out.y + 0.5));
    const auto src = vision::source_of(t.lens(), t.view(), out.x, out.y);
    QVERIFY(src && r.fisheye && r.output);
    QCOMPARE(*r.output, out);
    QCOMPARE(r.fisheye->x, static_cast<int>(std::lround(src->x)));
    QCOMPARE(r.fisheye->y, static_cast<int>(std::lround(src->y)));
    QCOMPARE(r.raw, int(raw.at<std::uint8_t>(r.fisheye->y, r.fisheye->x)));
    QCOMPARE(r.channel, "BGR"[vision::bayer_channel(vision::BayerPattern::BGGR, r.fisheye->y, r.fisheye->x)]);
    const cv::Vec3b bgr = t.images().demosaiced.at<cv::Vec3b>(r.fisheye->y, r.fisheye->x);
    QCOMPARE(*r.fisheye_rgb, cv::Vec3i(bgr[2], bgr[1], bgr[0]));
    const cv::Vec3b o = t.images().reprojected.at<cv::Vec3b>(out.y, out.x);
    QCOMPARE(*r.output_rgb, cv::Vec3i(o[2], o[1], o[0]));
    // From a fisheye pane: fisheye pixel -> output by output_of, and back.
    const ui::PixelInspection back = t.inspect(1, QPointF(r.fisheye->x + 0.5, r.fisheye->y + 0.5));
    const auto o2 = vision::output_of(t.lens(), t.view(), r.fisheye->x, r.fisheye->y);
    QVERIFY(o2 && back.output_exact);
    QCOMPARE(back.output_exact->x, o2->x);
    QVERIFY(std::abs(back.output_exact->x - out.x) < 2 && std::abs(back.output_exact->y - out.y) < 2);
    // Outside the image circle (a corner of the capture): no output pixel.
    QVERIFY(!t.inspect(0, QPointF(0.5, 0.5)).output);

    // A real mouse move over the reprojected pane: signal, text and cross-hairs.
    t.show();
    QSignalSpy moved(&t, &ui::FrameTriptych::cursor_moved);
    ui::ImagePane* c = t.pane(2);
    const QPointF w = c->image_to_widget(QPointF(out.x + 0.5, out.y + 0.5));
    // QTest::mouseMove moves the cursor, which the offscreen platform does not turn into events: send one.
    QMouseEvent hover(QEvent::MouseMove, QPointF(w.toPoint()), c->mapToGlobal(QPointF(w.toPoint())), Qt::NoButton,
                      Qt::NoButton, Qt::NoModifier);
    QApplication::sendEvent(c, &hover);
    QCOMPARE(moved.count(), 1);
    const QPointF fish = moved.last().at(0).toPointF(), outp = moved.last().at(1).toPointF();
    const QPointF hit = c->widget_to_image(w.toPoint());
    const auto src2 = vision::source_of(t.lens(), t.view(), std::floor(hit.x()), std::floor(hit.y()));
    QVERIFY(src2);
    QVERIFY(std::abs(fish.x() - src2->x) < 1e-9 && std::abs(fish.y() - src2->y) < 1e-9);
    QCOMPARE(outp, QPointF(std::floor(hit.x()), std::floor(hit.y())));
    QVERIFY2(t.inspector_text().contains("counts") && t.inspector_text().contains("px"),
             qPrintable(t.inspector_text()));
  }

  void sixteen_bit_window() {
    ui::FrameTriptych t;
    const Frame f = small_frame(12);
    t.set_frame(f);
    QVERIFY(t.wait_until_rendered(30000));
    QCOMPARE(t.images().mosaic.depth(), CV_16U);
    t.set_window(0, 4095);
    const cv::Mat raw = vision::frame_to_mat(f);
    const QImage a = t.panel_images()[0];
    QCOMPARE(a.format(), QImage::Format_Grayscale8);
    for (const cv::Point p : {cv::Point(160, 128), cv::Point(100, 60), cv::Point(5, 5)}) {
      const int v = raw.at<std::uint16_t>(p.y, p.x);
      QCOMPARE(qGray(a.pixel(p.x, p.y)), static_cast<int>(std::lround(v * 255.0 / 4095)));
    }
    t.set_window(1000, 1100);  // a narrow window: 1000 or below is black, 1100 or above white
    const QImage n = t.panel_images()[0];
    for (int y = 0; y < raw.rows; y += 17)
      for (int x = 0; x < raw.cols; x += 13) {
        const int v = raw.at<std::uint16_t>(y, x);
        if (v <= 1000) QCOMPARE(qGray(n.pixel(x, y)), 0);
        if (v >= 1100) QCOMPARE(qGray(n.pixel(x, y)), 255);
      }
  }

  void figure_export_png_and_pdf() {
    QTemporaryDir dir;
    ui::FrameTriptych t;
    t.set_frame(small_frame(8));
    QVERIFY(t.wait_until_rendered(30000));
    QString error;
    const QString png = dir.filePath("fig3.png"), pdf = dir.filePath("fig3.pdf");
    QVERIFY2(ui::export_triptych_figure(png, t.panel_images(), t.captions(), &error), qPrintable(error));
    QVERIFY2(ui::export_triptych_figure(pdf, t.panel_images(), t.captions(), &error), qPrintable(error));
    const QImage img(png);
    QCOMPARE(img.width(), 2148);  // 7.16 in at 300 dpi
    QVERIFY(img.height() > 500 && img.height() < 900);
    // The middle panel shows the demosaiced image: its centre pixel is not the white background.
    QVERIFY(img.pixel(img.width() / 2, img.height() * 2 / 5) != qRgb(255, 255, 255));
    QFile f(pdf);
    QVERIFY(f.open(QIODevice::ReadOnly));
    QVERIFY(f.read(5) == "%PDF-");
    QVERIFY(f.size() > 20000);  // three embedded images
    QVERIFY(!ui::export_triptych_figure(dir.filePath("x.png"), {}, t.captions(), &error));
  }

  void frames_tab_lists_the_workspace() {
    QTemporaryDir dir;
    Workspace ws(dir.filePath("w.bsw").toStdString());
    const std::string raw = BENCHSCOPE_SOURCE_DIR "/sample_data/paper-2018/frames/paper-capture.raw";
    ws.add_import(import_file(raw, CancelToken{}), file_content_hash(raw));
    ui::FramesView v;
    v.resize(1400, 700);
    v.set_workspace(&ws);
    QCOMPARE(v.frame_count(), 1);
    QVERIFY(v.list()->item(0)->text().contains("synthetic"));
    QVERIFY(v.triptych()->has_frame());
    QVERIFY(v.triptych()->wait_until_rendered(60000));
    QCOMPARE(v.triptych()->images().reprojected.cols, 1280);
    QCOMPARE(v.triptych()->lens().fov_deg, 195.0);
    QString error;
    QVERIFY2(v.export_figure(dir.filePath("f.pdf"), &error), qPrintable(error));
    v.set_workspace(nullptr);
    QVERIFY(!v.triptych()->has_frame());
  }

  void gui_import_can_copy_frames() {
    QTemporaryDir dir;
    const QString raw = BENCHSCOPE_SOURCE_DIR "/sample_data/paper-2018/frames/paper-capture.raw";
    const auto by_ref = ui::ImportController::import_now(dir.filePath("ref.bsw"), {raw}, CancelToken{});
    QCOMPARE(by_ref.imported, 1);
    const auto copied =
        ui::ImportController::import_now(dir.filePath("copy.bsw"), {raw}, CancelToken{}, {}, FrameStorage::Copy);
    QCOMPARE(copied.imported, 1);
    const Workspace ref(dir.filePath("ref.bsw").toStdString()), copy(dir.filePath("copy.bsw").toStdString());
    QCOMPARE(ref.frames().at(0).frame.storage, FrameStorage::Reference);
    QCOMPARE(copy.frames().at(0).frame.storage, FrameStorage::Copy);
    QCOMPARE(copy.frame_pixels(copy.frames().at(0).id).size(), std::size_t{1280 * 1024});
    QVERIFY(QFileInfo(dir.filePath("copy.bsw")).size() > QFileInfo(dir.filePath("ref.bsw")).size() + 1'000'000);
  }
};

QTEST_MAIN(TestFrameTriptych)
#include "test_frame_triptych.moc"
