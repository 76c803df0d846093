// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One image of the frame triptych: a title, the image scaled to fit, zoom with the wheel (about the cursor) and
// pan by dragging. The zoom/centre state is exposed so the triptych can keep its three panes in step; overlays
// (polylines and circles in image pixel coordinates) and a cross-hair marker are drawn on top.
#include <QImage>
#include <QPointF>
#include <QPolygonF>
#include <QWidget>
#include <optional>
#include <vector>

namespace bs::ui {

class ImagePane : public QWidget {
  Q_OBJECT
 public:
  explicit ImagePane(const QString& title, QWidget* parent = nullptr);

  void set_title(const QString& title);
  QString title() const { return title_; }
  void set_image(const QImage& image);  // any size; pixel (i, j) covers [i, i+1) x [j, j+1) in image coordinates
  const QImage& image() const { return image_; }
  void set_message(const QString& text);  // shown instead of an image (no frame, an error)

  // Shared view state: zoom 1 shows the whole image; centre is the image point (as a fraction of its width and
  // height) at the middle of the pane. Setting it emits nothing.
  void set_view(double zoom, QPointF centre);
  double zoom() const { return zoom_; }
  QPointF centre() const { return centre_; }
  static constexpr double kMinZoom = 0.5, kMaxZoom = 64;

  // Zooms by `factor` keeping the image point under widget position `anchor` fixed, as the wheel does; emits
  // view_changed.
  void zoom_at(QPointF anchor, double factor);

  QPointF widget_to_image(QPointF p) const;
  QPointF image_to_widget(QPointF p) const;

  struct Overlay {
    QPolygonF points;  // image coordinates
    bool closed = true;
    QColor colour;
  };
  void set_overlays(std::vector<Overlay> overlays);
  void set_marker(std::optional<QPointF> image_point);  // a cross-hair at the linked position, or none

 signals:
  void view_changed(double zoom, QPointF centre);
  void cursor_moved(QPointF image_point);  // image coordinates, may lie outside the image
  void cursor_left();

 protected:
  void paintEvent(QPaintEvent*) override;
  void wheelEvent(QWheelEvent* e) override;
  void mousePressEvent(QMouseEvent* e) override;
  void mouseMoveEvent(QMouseEvent* e) override;
  void mouseReleaseEvent(QMouseEvent* e) override;
  void leaveEvent(QEvent*) override;

 private:
  QRectF image_area() const;  // below the title
  double scale() const;       // widget pixels per image pixel

  QString title_, message_;
  QImage image_;
  double zoom_ = 1;
  QPointF centre_{0.5, 0.5};
  std::vector<Overlay> overlays_;
  std::optional<QPointF> marker_;
  std::optional<QPointF> drag_from_;
};

}  // namespace bs::ui
