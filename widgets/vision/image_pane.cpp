// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/image_pane.h"

#include <QFontMetrics>

#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>

namespace bs::ui {

ImagePane::ImagePane(const QString& title, QWidget* parent) : QWidget(parent), title_(title) {
  setMouseTracking(true);
  setMinimumSize(160, 140);
  setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
}

void ImagePane::set_title(const QString& title) {
  title_ = title;
  update();
}

void ImagePane::set_image(const QImage& image) {
  image_ = image;
  message_.clear();
  update();
}

void ImagePane::set_message(const QString& text) {
  message_ = text;
  image_ = QImage();
  update();
}

void ImagePane::set_view(double zoom, QPointF centre) {
  zoom_ = std::clamp(zoom, kMinZoom, kMaxZoom);
  centre_ = centre;
  update();
}

QRectF ImagePane::image_area() const {
  // The title wraps onto a second line when the pane is narrow (three panes side by side on a 1280 px window),
  // instead of being cut (issue #32.7).
  QFont bold = font();
  bold.setBold(true);
  const QFontMetrics fm(bold);
  const int lines = fm.horizontalAdvance(title_) > width() - 8 ? 2 : 1;
  const int title_h = lines * fm.height() + 8;
  return QRectF(0, title_h, width(), std::max(1, height() - title_h));
}

double ImagePane::scale() const {
  if (image_.isNull()) return 1;
  const QRectF a = image_area();
  return std::min(a.width() / image_.width(), a.height() / image_.height()) * zoom_;
}

QPointF ImagePane::widget_to_image(QPointF p) const {
  const QRectF a = image_area();
  const QPointF c(centre_.x() * image_.width(), centre_.y() * image_.height());
  return c + (p - a.center()) / scale();
}

QPointF ImagePane::image_to_widget(QPointF p) const {
  const QRectF a = image_area();
  const QPointF c(centre_.x() * image_.width(), centre_.y() * image_.height());
  return a.center() + (p - c) * scale();
}

void ImagePane::zoom_at(QPointF anchor, double factor) {
  if (image_.isNull()) return;
  const QPointF fixed = widget_to_image(anchor);
  zoom_ = std::clamp(zoom_ * factor, kMinZoom, kMaxZoom);
  // Choose the centre so that `fixed` stays under `anchor` at the new scale.
  const QPointF c = fixed - (anchor - image_area().center()) / scale();
  centre_ = QPointF(c.x() / image_.width(), c.y() / image_.height());
  update();
  emit view_changed(zoom_, centre_);
}

void ImagePane::set_overlays(std::vector<Overlay> overlays) {
  overlays_ = std::move(overlays);
  update();
}

void ImagePane::set_marker(std::optional<QPointF> image_point) {
  marker_ = image_point;
  update();
}

void ImagePane::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.fillRect(rect(), QColor(40, 40, 40));
  const QRectF area = image_area();
  p.fillRect(QRectF(0, 0, width(), area.top()), palette().window());
  QFont bold = font();
  bold.setBold(true);
  p.setFont(bold);
  p.setPen(palette().windowText().color());
  p.drawText(QRectF(4, 0, width() - 8, area.top()), Qt::AlignLeft | Qt::AlignVCenter | Qt::TextWordWrap, title_);
  p.setFont(font());
  p.setClipRect(area);
  if (image_.isNull()) {
    p.setPen(QColor(220, 220, 220));
    p.drawText(area.adjusted(8, 8, -8, -8), Qt::AlignCenter | Qt::TextWordWrap, message_);
    return;
  }
  const double s = scale();
  // Magnified pixels stay crisp squares (pixel inspection); reduced images are smoothed.
  p.setRenderHint(QPainter::SmoothPixmapTransform, s < 1);
  const QPointF top_left = image_to_widget(QPointF(0, 0));
  p.drawImage(QRectF(top_left, QSizeF(image_.width() * s, image_.height() * s)), image_);
  p.setRenderHint(QPainter::Antialiasing, true);
  for (const Overlay& o : overlays_) {
    QPolygonF w;
    for (const QPointF& q : o.points) w << image_to_widget(q);
    p.setPen(QPen(o.colour, 1.5));
    p.setBrush(Qt::NoBrush);
    if (o.closed)
      p.drawPolygon(w);
    else
      p.drawPolyline(w);
  }
  if (marker_) {
    const QPointF m = image_to_widget(*marker_);
    p.setPen(QPen(QColor(255, 60, 60), 1.5));
    p.drawLine(m + QPointF(-9, 0), m + QPointF(-3, 0));
    p.drawLine(m + QPointF(3, 0), m + QPointF(9, 0));
    p.drawLine(m + QPointF(0, -9), m + QPointF(0, -3));
    p.drawLine(m + QPointF(0, 3), m + QPointF(0, 9));
  }
}

void ImagePane::wheelEvent(QWheelEvent* e) {
  const double steps = e->angleDelta().y() / 120.0;
  if (steps != 0) zoom_at(e->position(), std::pow(1.25, steps));
  e->accept();
}

void ImagePane::mousePressEvent(QMouseEvent* e) {
  if (e->button() == Qt::LeftButton) drag_from_ = e->position();
}

void ImagePane::mouseMoveEvent(QMouseEvent* e) {
  if (drag_from_ && !image_.isNull()) {
    const QPointF d = (e->position() - *drag_from_) / scale();
    drag_from_ = e->position();
    centre_ -= QPointF(d.x() / image_.width(), d.y() / image_.height());
    update();
    emit view_changed(zoom_, centre_);
  }
  if (!image_.isNull()) emit cursor_moved(widget_to_image(e->position()));
}

void ImagePane::mouseReleaseEvent(QMouseEvent* e) {
  if (e->button() == Qt::LeftButton) drag_from_.reset();
}

void ImagePane::leaveEvent(QEvent*) { emit cursor_left(); }

}  // namespace bs::ui
