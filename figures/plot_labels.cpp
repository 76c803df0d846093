// SPDX-License-Identifier: GPL-3.0-or-later
#include "plot_labels.h"

#include <qcustomplot.h>
#include <QFontMetricsF>

#include <algorithm>

#include "overlay_geometry.h"

namespace bs::ui {
namespace {

constexpr double kGap = 6;         // pixels between a marker and its label
constexpr double kMarkerHalf = 5;  // half a peak marker's size: labels must not hide other markers
constexpr int kPadding = 2;        // label padding, pixels

QRectF marker_box(const QCustomPlot* plot, double key, double value) {
  const QPointF p(plot->xAxis->coordToPixel(key), plot->yAxis->coordToPixel(value));
  return QRectF(p.x() - kMarkerHalf, p.y() - kMarkerHalf, 2 * kMarkerHalf, 2 * kMarkerHalf);
}

QSizeF text_size(const QCPItemText* item) {
  const QMarginsF pad = item->padding();
  return QFontMetricsF(item->font()).size(Qt::TextSingleLine, item->text()) +
         QSizeF(pad.left() + pad.right(), pad.top() + pad.bottom());
}

}  // namespace

QRectF text_item_rect(const QCPItemText* item) {
  const QPointF p = item->position->pixelPosition();
  const QSizeF s = text_size(item);
  const Qt::Alignment a = item->positionAlignment();
  double x = p.x(), y = p.y();
  if (a & Qt::AlignHCenter)
    x -= s.width() / 2;
  else if (a & Qt::AlignRight)
    x -= s.width();
  if (a & Qt::AlignVCenter)
    y -= s.height() / 2;
  else if (a & Qt::AlignBottom)
    y -= s.height();
  return QRectF(QPointF(x, y), s);
}

std::vector<QPolygonF> graphs_in_pixels(const std::vector<QPointer<QCPGraph>>& graphs) {
  std::vector<QPolygonF> out;
  for (const auto& g : graphs) {
    if (!g || !g->visible()) continue;
    QPolygonF points;
    points.reserve(g->data()->size());
    for (auto it = g->data()->constBegin(); it != g->data()->constEnd(); ++it)
      points << QPointF(g->keyAxis()->coordToPixel(it->key), g->valueAxis()->coordToPixel(it->value));
    out.push_back(thin_polyline(points));
  }
  return out;
}

AnchoredLabels::AnchoredLabels(QCustomPlot* plot, bool auto_place) : QObject(plot), plot_(plot) {
  if (auto_place) connect(plot_, &QCustomPlot::afterLayout, this, &AnchoredLabels::place);
}

void AnchoredLabels::clear() {
  curves_.clear();
  labels_.clear();
}

void AnchoredLabels::add_curve(QCPGraph* graph) { curves_.emplace_back(graph); }

QCPItemText* AnchoredLabels::add(double key, double value, const QString& text, const QColor& color, QCPGraph* owner) {
  auto* item = new QCPItemText(plot_);
  item->setText(text);
  QFont font = plot_->font();
  font.setPointSizeF(font.pointSizeF() * 0.85);
  item->setFont(font);
  item->setColor(color.darker(150));  // the series' colour, dark enough to read as text on white
  item->setBrush(QColor(255, 255, 255, 215));
  item->setPen(Qt::NoPen);
  item->setPadding(QMargins(kPadding, kPadding, kPadding, kPadding));
  item->setPositionAlignment(Qt::AlignCenter);
  item->position->setType(QCPItemPosition::ptAbsolute);
  item->setClipToAxisRect(false);
  item->setVisible(false);  // until the first layout has placed it
  labels_.push_back({item, key, value, owner});
  return item;
}

int AnchoredLabels::shown_count() const {
  int n = 0;
  for (const Label& l : labels_) n += l.item && l.item->visible();
  return n;
}

std::vector<QCPItemText*> AnchoredLabels::labels() const {
  std::vector<QCPItemText*> out;
  for (const Label& l : labels_)
    if (l.item) out.push_back(l.item);
  return out;
}

std::vector<QRectF> AnchoredLabels::marker_boxes() const {
  std::vector<QRectF> boxes;
  for (const Label& l : labels_)
    if (l.item) boxes.push_back(marker_box(plot_, l.key, l.value));
  return boxes;
}

void AnchoredLabels::place() {
  if (labels_.empty()) return;
  const QRectF area = plot_->axisRect()->rect();
  std::vector<QPointF> anchors;
  std::vector<QSizeF> sizes;
  std::vector<QRectF> obstacles;
  // A legend over the axes (the views' layout) is an obstacle; one below them (an export) is outside the area.
  const bool legend_inside = plot_->legend->visible() && plot_->legend->layout() == plot_->axisRect()->insetLayout();
  const QRectF legend = QRectF(plot_->legend->outerRect()).adjusted(-2, -2, 2, 2);
  if (legend_inside) obstacles.push_back(legend);
  // The curves in pixels, and each label's own among them (graphs_in_pixels leaves hidden graphs out: index the
  // visible ones).
  std::vector<QPointer<QCPGraph>> shown_curves;
  for (const auto& g : curves_)
    if (g && g->visible()) shown_curves.push_back(g);
  const std::vector<QPolygonF> curves = graphs_in_pixels(shown_curves);
  std::vector<int> owners;
  for (const Label& l : labels_) {
    if (!l.item) continue;
    const QRectF marker = marker_box(plot_, l.key, l.value);
    anchors.push_back(marker.center());
    obstacles.push_back(marker);
    sizes.push_back(text_size(l.item));
    const auto own = std::find(shown_curves.begin(), shown_curves.end(), l.owner);
    owners.push_back(l.owner && own != shown_curves.end() ? static_cast<int>(own - shown_curves.begin()) : -1);
  }
  const auto placed = place_labels_greedy(area, anchors, sizes, obstacles, curves, kGap, owners);
  std::vector<QRectF> taken;
  for (const auto& spot : placed)
    if (spot) taken.push_back(*spot);
  std::size_t i = 0;
  for (const Label& l : labels_) {
    if (!l.item) continue;
    const auto& spot = placed[i++];
    // A point scrolled out of view keeps its label hidden: it would otherwise point at nothing.
    const bool in_view = area.contains(anchors[i - 1]);
    if (spot) {
      l.item->setVisible(in_view);
      l.item->position->setCoords(spot->center());
      continue;
    }
    // No spot free of curves (a crowded log axis): beside its marker, inside the axes, even if it touches a curve,
    // unless it would cover a label placed before it (a higher peak's) or the legend, or sit nearer another curve
    // than its own: then this, the lesser, is dropped. Its value stays in the tables and the hover read-out.
    const QSizeF size = sizes[i - 1];
    QRectF box(anchors[i - 1] + QPointF(kMarkerHalf + kGap, -size.height() / 2), size);
    if (box.right() > area.right()) box.moveRight(anchors[i - 1].x() - kMarkerHalf - kGap);
    box.moveTop(std::clamp(box.top(), area.top(), std::max(area.top(), area.bottom() - box.height())));
    box.moveLeft(std::clamp(box.left(), area.left(), std::max(area.left(), area.right() - box.width())));
    const bool collides = std::any_of(taken.begin(), taken.end(), [&](const QRectF& t) { return t.intersects(box); }) ||
                          (legend_inside && legend.intersects(box)) || nearer_another_curve(box, curves, owners[i - 1]);
    l.item->setVisible(in_view && !collides);
    l.item->position->setCoords(box.center());
    if (in_view && !collides) taken.push_back(box);
  }
}

}  // namespace bs::ui
