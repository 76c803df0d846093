// SPDX-License-Identifier: GPL-3.0-or-later
#include "triptych_figure.h"

#include <QFile>
#include <QFontMetricsF>
#include <QJsonObject>
#include <QPainter>
#include <QPdfWriter>
#include <QSvgGenerator>
#include <stdexcept>

#include "paper_figures.h"
#include "vision/demosaic/bayer.h"
#include "vision/frames/frame_image.h"
#include "vision/frames/synthetic.h"
#include "vision/lens/lens.h"
#include "vision/reproject/triptych.h"

namespace bs::ui {
namespace {

QImage to_qimage(const cv::Mat& m) {
  if (m.type() == CV_8UC1)
    return QImage(m.data, m.cols, m.rows, static_cast<qsizetype>(m.step), QImage::Format_Grayscale8).copy();
  return QImage(m.data, m.cols, m.rows, static_cast<qsizetype>(m.step), QImage::Format_BGR888).copy();
}

const char* const kCaptions[] = {"(a) raw Bayer mosaic (BGGR) as grey", "(b) demosaiced (bilinear)",
                                 "(c) reprojected, 150\u00b0 rectilinear"};
constexpr int kCaptionFlags = Qt::AlignHCenter | Qt::AlignTop | Qt::TextWordWrap;

// Height in points the wrapped captions need under panels a third of `w` wide (measured at 72 dpi, so 1 unit =
// 1 pt as on the PDF and SVG pages).
double caption_height(double w, double font_pt) {
  QImage probe(1, 1, QImage::Format_RGB32);
  probe.setDotsPerMeterX(static_cast<int>(std::lround(72 / 0.0254)));
  probe.setDotsPerMeterY(static_cast<int>(std::lround(72 / 0.0254)));
  QFont f("DejaVu Sans");
  f.setPointSizeF(font_pt);
  const QFontMetricsF fm(f, &probe);
  const double panel_w = (w - 2 * w * 0.015) / 3;
  double h = 0;
  for (const char* c : kCaptions)
    h = std::max(h, fm.boundingRect(QRectF(0, 0, panel_w, 1000), kCaptionFlags, QString::fromUtf8(c)).height());
  return h + font_pt * 0.4;
}

// Draws the three panels and their captions into a w x h (points) area.
void paint(QPainter& p, const QImage (&images)[3], double w, double h, double font_pt) {
  QFont f("DejaVu Sans");
  f.setPointSizeF(font_pt);
  p.setFont(f);
  const double gap = w * 0.015, panel_w = (w - 2 * gap) / 3, caption_h = caption_height(w, font_pt);
  const double panel_h = std::min(h - caption_h, panel_w * images[0].height() / images[0].width());
  for (int i = 0; i < 3; ++i) {
    const QRectF r(i * (panel_w + gap), 0, panel_w, panel_h);
    p.drawImage(r, images[i]);
    p.drawText(QRectF(r.left(), panel_h, panel_w, caption_h), kCaptionFlags, QString::fromUtf8(kCaptions[i]));
  }
}

}  // namespace

namespace {

struct Panels {
  cv::Mat raw, rgb, out;  // 8-bit for display
  QJsonObject source;
  int width = 0, height = 0;
};

// The capture of the workspace: its lens (recorded with the frame, else the paper's), bilinear demosaic, 16-bit
// samples shown through their full range.
Panels from_frame(const Frame& frame, const CancelToken& cancel) {
  const vision::FrameLens fl = vision::lens_for_frame(frame);
  const vision::TriptychImages t =
      vision::render_triptych(frame, vision::DemosaicMethod::Bilinear, fl.lens, fl.view, &cancel);
  const double full = vision::full_scale(frame);
  Panels p{vision::window_to_8bit(t.mosaic, 0, full),
           vision::window_to_8bit(t.demosaiced, 0, full),
           vision::window_to_8bit(t.reprojected, 0, full),
           {},
           frame.width,
           frame.height};
  p.source = QJsonObject{
      {"file", QString::fromStdString(frame.provenance.source_file)},
      {"origin", frame.synthetic ? "synthetic" : QString::fromUtf8(to_string(frame.provenance.origin).data())},
      {"how", QString("frame %1 (%2x%3 %4, %5-bit), %6 lens, demosaiced bilinear, reprojected")
                  .arg(QString::fromStdString(frame.label))
                  .arg(frame.width)
                  .arg(frame.height)
                  .arg(QString::fromStdString(frame.pattern))
                  .arg(frame.bit_depth)
                  .arg(fl.from_frame ? "the frame's recorded" : "the paper's")}};
  return p;
}

// Without a capture: the test chart through the paper's lens at half resolution (same field of view).
Panels synthetic(const CancelToken& cancel) {
  vision::Lens lens = vision::Lens::paper();
  lens.width /= 2;
  lens.height /= 2;
  lens.r_pp *= 2;
  vision::View view;
  view.width = lens.width;
  view.height = lens.height;
  const cv::Mat truth = vision::render_fisheye(lens);
  cancel.throw_if_cancelled();
  Panels p;
  p.raw = vision::mosaic(truth, vision::BayerPattern::BGGR);
  p.rgb = vision::demosaic(p.raw, vision::BayerPattern::BGGR, vision::DemosaicMethod::Bilinear);
  p.out = vision::ReprojectionLut(lens, view).apply(p.rgb);
  p.width = lens.width;
  p.height = lens.height;
  p.source =
      QJsonObject{{"file", "synthetic"},
                  {"origin", "synthetic"},
                  {"how", QString("no frame in the workspace: chart rendered through the paper's lens (195 degree "
                                  "equidistant) at %1x%2, mosaiced BGGR, demosaiced bilinear, reprojected to "
                                  "150 degrees")
                              .arg(lens.width)
                              .arg(lens.height)}};
  return p;
}

}  // namespace

QJsonArray render_triptych_figure(const QString& stem, const FigureOptions& o, QStringList& files, double& height_mm,
                                  const Frame* frame, const CancelToken& cancel) {
  const Panels panels = frame ? from_frame(*frame, cancel) : synthetic(cancel);
  cancel.throw_if_cancelled();
  const QImage images[3] = {to_qimage(panels.raw), to_qimage(panels.rgb), to_qimage(panels.out)};
  const double w = o.width_mm * 72.0 / 25.4;
  const double h = (w * 0.97 / 3) * panels.height / panels.width + caption_height(w, o.font_pt);
  height_mm = h * 25.4 / 72.0;
  for (const QString& format : o.formats) {
    cancel.throw_if_cancelled();
    const QString path = stem + "." + format;
    QPainter p;
    bool ok = false;
    if (format == "pdf") {
      QPdfWriter pdf(path);
      pdf.setPageSize(QPageSize(QSizeF(o.width_mm, h * 25.4 / 72.0), QPageSize::Millimeter));
      pdf.setPageMargins(QMarginsF(0, 0, 0, 0));
      pdf.setResolution(72);  // one unit = one point, so fonts and sizes read as in the template
      pdf.setCreator("BenchScope");
      pdf.setTitle("Raw mosaic | demosaiced | reprojected");
      if ((ok = p.begin(&pdf))) {
        paint(p, images, w, h, o.font_pt);
        ok = p.end();
      }
    } else if (format == "svg") {
      QSvgGenerator svg;
      svg.setFileName(path);
      svg.setSize(QSize(static_cast<int>(w), static_cast<int>(h)));
      svg.setViewBox(QRectF(0, 0, w, h));
      svg.setResolution(72);
      if ((ok = p.begin(&svg))) {
        paint(p, images, w, h, o.font_pt);
        ok = p.end();
      }
    } else if (format == "png") {
      const double scale = o.dpi / 72.0;
      QImage img(static_cast<int>(std::lround(w * scale)), static_cast<int>(std::lround(h * scale)),
                 QImage::Format_RGB32);
      img.fill(Qt::white);
      // Paint in points (a 72 dpi device scaled up), then label the file with its real resolution.
      img.setDotsPerMeterX(static_cast<int>(std::lround(72 / 0.0254)));
      img.setDotsPerMeterY(static_cast<int>(std::lround(72 / 0.0254)));
      if ((ok = p.begin(&img))) {
        p.setRenderHint(QPainter::SmoothPixmapTransform);
        p.setRenderHint(QPainter::Antialiasing);
        p.scale(scale, scale);
        paint(p, images, w, h, o.font_pt);
        ok = p.end();
        img.setDotsPerMeterX(static_cast<int>(std::lround(o.dpi / 0.0254)));
        img.setDotsPerMeterY(static_cast<int>(std::lround(o.dpi / 0.0254)));
        ok = ok && img.save(path, "PNG");
      }
    } else {
      throw std::runtime_error("unknown figure format '" + format.toStdString() + "' (pdf, svg, png)");
    }
    if (!ok || !QFile::exists(path)) throw std::runtime_error(path.toStdString() + ": cannot write the figure");
    files << path;
  }
  return QJsonArray{panels.source};
}

}  // namespace bs::ui
