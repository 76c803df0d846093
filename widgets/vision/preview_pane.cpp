// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/preview_pane.h"

#include <QMouseEvent>
#include <QPainter>

namespace bs::ui {

PreviewPane::PreviewPane(const QString& empty_text, QWidget* parent) : QWidget(parent), empty_text_(empty_text) {
  setMinimumSize(200, 160);
  setCursor(Qt::CrossCursor);
}

void PreviewPane::set_image(const QImage& image) {
  image_ = image;
  update();
}
void PreviewPane::set_overlays(std::vector<Overlay> overlays) {
  overlays_ = std::move(overlays);
  update();
}
void PreviewPane::set_circles(std::vector<Circle> circles) {
  circles_ = std::move(circles);
  update();
}
void PreviewPane::set_caption(const QString& caption) {
  caption_ = caption;
  update();
}

QRectF PreviewPane::target() const {
  const QRectF area = QRectF(rect()).adjusted(2, 2, -2, caption_.isEmpty() ? -2 : -20);
  if (image_.isNull()) return area;
  QSizeF s = QSizeF(image_.size()).scaled(area.size(), Qt::KeepAspectRatio);
  return {area.left() + (area.width() - s.width()) / 2, area.top() + (area.height() - s.height()) / 2, s.width(),
          s.height()};
}

// Pixel centres: image pixel (0, 0) is the centre of the first pixel, so pixel x covers [x - 0.5, x + 0.5).
QPointF PreviewPane::to_image(QPointF p) const {
  const QRectF t = target();
  if (image_.isNull() || t.isEmpty()) return {};
  return {(p.x() - t.left()) * image_.width() / t.width() - 0.5,
          (p.y() - t.top()) * image_.height() / t.height() - 0.5};
}

QPointF PreviewPane::to_widget(QPointF q) const {
  const QRectF t = target();
  if (image_.isNull()) return {};
  return {t.left() + (q.x() + 0.5) * t.width() / image_.width(),
          t.top() + (q.y() + 0.5) * t.height() / image_.height()};
}

void PreviewPane::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.fillRect(rect(), palette().color(QPalette::Window).darker(115));
  if (image_.isNull()) {
    p.drawText(rect(), Qt::AlignCenter | Qt::TextWordWrap, empty_text_);
    return;
  }
  p.setRenderHint(QPainter::SmoothPixmapTransform);
  p.drawImage(target(), image_);
  p.setRenderHint(QPainter::Antialiasing);
  for (const auto& o : overlays_) {
    QPolygonF w;
    for (const auto& q : o.points) w << to_widget(q);
    QColor fill = o.colour;
    fill.setAlpha(70);
    p.setPen(QPen(o.colour, o.width));
    if (o.closed && w.size() >= 3) {
      p.setBrush(fill);
      p.drawPolygon(w);
    } else {
      p.setBrush(Qt::NoBrush);
      p.drawPolyline(w);
    }
    if (o.markers)
      for (const auto& q : w) {
        p.drawLine(q + QPointF(-4, 0), q + QPointF(4, 0));
        p.drawLine(q + QPointF(0, -4), q + QPointF(0, 4));
      }
  }
  for (const auto& c : circles_) {
    const double sx = target().width() / image_.width();
    p.setPen(QPen(c.colour, 2, Qt::DashLine));
    p.setBrush(Qt::NoBrush);
    p.drawEllipse(to_widget(c.centre), c.radius * sx, c.radius * sx);
    const QPointF m = to_widget(c.centre);
    p.drawLine(m + QPointF(-6, 0), m + QPointF(6, 0));
    p.drawLine(m + QPointF(0, -6), m + QPointF(0, 6));
  }
  if (!caption_.isEmpty()) {
    p.setPen(palette().color(QPalette::WindowText));
    p.drawText(QRectF(rect()).adjusted(4, height() - 19, -4, 0), Qt::AlignLeft | Qt::AlignVCenter, caption_);
  }
}

void PreviewPane::mousePressEvent(QMouseEvent* event) {
  if (event->button() == Qt::LeftButton && !image_.isNull()) emit clicked(to_image(event->position()));
}

void PreviewPane::mouseDoubleClickEvent(QMouseEvent* event) {
  if (event->button() == Qt::LeftButton && !image_.isNull()) emit double_clicked(to_image(event->position()));
}

}  // namespace bs::ui
