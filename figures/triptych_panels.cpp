// SPDX-License-Identifier: GPL-3.0-or-later
#include "triptych_panels.h"

#include <QFileInfo>
#include <QPageSize>
#include <QPainter>
#include <QPdfWriter>
#include <algorithm>

namespace bs::ui {
namespace {

constexpr double kGapIn = 0.06;         // between panels
constexpr double kCaptionGapIn = 0.04;  // between a panel and its caption

double panel_aspect(const std::array<QImage, 3>& panels) {
  // The tallest panel decides the row height, so no image is cropped.
  double aspect = 0;
  for (const QImage& p : panels)
    if (!p.isNull()) aspect = std::max(aspect, static_cast<double>(p.height()) / p.width());
  return aspect > 0 ? aspect : 0.8;
}

}  // namespace

double triptych_figure_height_in(const std::array<QImage, 3>& panels, double width_in, double font_pt) {
  const double panel_w = (width_in - 2 * kGapIn) / 3;
  // Two caption lines: long captions wrap under a panel one third of a column wide.
  return panel_w * panel_aspect(panels) + kCaptionGapIn + 2.4 * font_pt / 72.0;
}

void paint_triptych_figure(QPainter& p, const QRectF& area, const std::array<QImage, 3>& panels,
                           const std::array<QString, 3>& captions, double dpi, double font_pt) {
  const double gap = kGapIn * dpi;
  const double panel_w = (area.width() - 2 * gap) / 3;
  const double panel_h = panel_w * panel_aspect(panels);
  QFont font(QStringLiteral("DejaVu Sans"));
  font.setPixelSize(std::max(1, static_cast<int>(font_pt / 72.0 * dpi + 0.5)));
  p.setFont(font);
  p.setRenderHint(QPainter::SmoothPixmapTransform, true);
  p.setRenderHint(QPainter::Antialiasing, true);
  for (int i = 0; i < 3; ++i) {
    const QRectF cell(area.left() + i * (panel_w + gap), area.top(), panel_w, panel_h);
    const QImage& img = panels[static_cast<std::size_t>(i)];
    if (!img.isNull()) {
      QSizeF s = img.size();
      s.scale(cell.size(), Qt::KeepAspectRatio);
      const QRectF target(cell.left() + (cell.width() - s.width()) / 2, cell.top(), s.width(), s.height());
      p.drawImage(target, img);
    }
    const QRectF caption(cell.left(), cell.bottom() + kCaptionGapIn * dpi, panel_w,
                         area.bottom() - cell.bottom() - kCaptionGapIn * dpi);
    p.setPen(Qt::black);
    p.drawText(caption, Qt::AlignHCenter | Qt::AlignTop | Qt::TextWordWrap, captions[static_cast<std::size_t>(i)]);
  }
}

bool export_triptych_figure(const QString& path, const std::array<QImage, 3>& panels,
                            const std::array<QString, 3>& captions, QString* error, double width_in) {
  for (const QImage& img : panels)
    if (img.isNull()) {
      if (error) *error = QObject::tr("the triptych has not been rendered yet");
      return false;
    }
  const double height_in = triptych_figure_height_in(panels, width_in);
  if (QFileInfo(path).suffix().compare(QLatin1String("pdf"), Qt::CaseInsensitive) == 0) {
    QPdfWriter pdf(path);
    const int dpi = 1200;  // the page's coordinate resolution; the images keep their own pixels
    pdf.setResolution(dpi);
    pdf.setPageSize(QPageSize(QSizeF(width_in * 72, height_in * 72), QPageSize::Point));
    pdf.setPageMargins(QMarginsF(0, 0, 0, 0));
    pdf.setCreator(QStringLiteral("BenchScope"));
    pdf.setTitle(QObject::tr("Figure 3: raw mosaic, demosaiced, reprojected"));
    QPainter p;
    if (!p.begin(&pdf)) {
      if (error) *error = QObject::tr("cannot write %1").arg(path);
      return false;
    }
    paint_triptych_figure(p, QRectF(0, 0, width_in * dpi, height_in * dpi), panels, captions, dpi);
    p.end();
    return true;
  }
  const double dpi = 300;
  QImage out(static_cast<int>(width_in * dpi + 0.5), static_cast<int>(height_in * dpi + 0.5), QImage::Format_RGB32);
  out.fill(Qt::white);
  out.setDotsPerMeterX(static_cast<int>(dpi / 0.0254 + 0.5));
  out.setDotsPerMeterY(static_cast<int>(dpi / 0.0254 + 0.5));
  {
    QPainter p(&out);
    paint_triptych_figure(p, QRectF(0, 0, out.width(), out.height()), panels, captions, dpi);
  }
  if (!out.save(path)) {
    if (error) *error = QObject::tr("cannot write %1 (unknown image format or no permission)").arg(path);
    return false;
  }
  return true;
}

}  // namespace bs::ui
