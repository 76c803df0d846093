// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A preview image scaled to fit (aspect kept) with vector overlays in image pixel coordinates; clicks are reported in
// image pixel coordinates. Used by the reprojection tuner for the fisheye and the reprojected previews.
#include <QImage>
#include <QPolygonF>
#include <QWidget>
#include <vector>

namespace bs::ui {

class PreviewPane : public QWidget {
  Q_OBJECT
 public:
  struct Overlay {
    QPolygonF points;  // image pixel coordinates
    QColor colour;
    bool closed = false;   // a polygon (filled translucent) rather than a polyline
    bool markers = false;  // draw a small cross on every point
    double width = 2;      // pen width, widget pixels
  };
  struct Circle {
    QPointF centre;
    double radius = 0;
    QColor colour;
  };

  explicit PreviewPane(const QString& empty_text, QWidget* parent = nullptr);
  void set_image(const QImage& image);
  const QImage& image() const { return image_; }
  void set_overlays(std::vector<Overlay> overlays);
  void set_circles(std::vector<Circle> circles);
  void set_caption(const QString& caption);
  // Widget position -> image pixel coordinates (may lie outside the image).
  QPointF to_image(QPointF widget_pos) const;
  QPointF to_widget(QPointF image_pos) const;

 signals:
  void clicked(QPointF image_pos);
  void double_clicked(QPointF image_pos);

 protected:
  void paintEvent(QPaintEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseDoubleClickEvent(QMouseEvent* event) override;
  QSize sizeHint() const override { return {420, 340}; }

 private:
  QRectF target() const;
  QImage image_;
  QString empty_text_, caption_;
  std::vector<Overlay> overlays_;
  std::vector<Circle> circles_;
};

}  // namespace bs::ui
