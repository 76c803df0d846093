// SPDX-License-Identifier: GPL-3.0-or-later
#include "peaks/peak_overlay.h"

#include "common/plot_legend.h"

#include <algorithm>

#include <qcustomplot.h>
#include <QFontMetricsF>
#include <array>
#include <cmath>

#include "common/overlay_geometry.h"

namespace bs::ui {
namespace {

constexpr double kGap = 6;            // pixels between a peak marker and its label
constexpr double kMarkerHalf = 5;     // half the peak marker size: labels must not hide other markers
constexpr int kPadding = 2;           // label padding, pixels
constexpr double kMaxHeadroom = 0.3;  // at most this much of an axis is added to keep the legend off the data

}  // namespace

PeakOverlay::PeakOverlay(QCustomPlot* plot) : QObject(plot), plot_(plot) {
  connect(plot_, &QCustomPlot::afterLayout, this, &PeakOverlay::on_after_layout);
}

void PeakOverlay::clear() {
  curves_.clear();
  labels_.clear();
  legend_pending_ = true;
}

void PeakOverlay::add_curve(QCPGraph* graph) { curves_.emplace_back(graph); }

void PeakOverlay::add_peak_label(double key, double value, const QString& text, const QColor& color) {
  auto* item = new QCPItemText(plot_);
  item->setText(text);
  QFont font = plot_->font();
  font.setPointSizeF(font.pointSizeF() * 0.85);
  item->setFont(font);
  item->setColor(color.darker(150));  // device colour, dark enough to read as text on white
  item->setBrush(QColor(255, 255, 255, 215));
  item->setPen(Qt::NoPen);
  item->setPadding(QMargins(kPadding, kPadding, kPadding, kPadding));
  item->setPositionAlignment(Qt::AlignCenter);
  item->position->setType(QCPItemPosition::ptAbsolute);
  item->setVisible(false);  // until the first layout has placed it
  labels_.push_back({item, key, value});
}

int PeakOverlay::shown_label_count() const {
  int n = 0;
  for (const Label& l : labels_) n += l.item && l.item->visible();
  return n;
}

std::vector<QCPItemText*> PeakOverlay::labels() const {
  std::vector<QCPItemText*> out;
  for (const Label& l : labels_)
    if (l.item) out.push_back(l.item);
  return out;
}

void PeakOverlay::on_after_layout() {
  // A new plot size (the window was resized or first shown) changes where the data lies in pixels. The widget's
  // size, not the axis rect's: moving the legend under the plot changes the latter, and must not trigger again.
  const QSize size = plot_->size();
  if (size != laid_out_size_) legend_pending_ = true;
  laid_out_size_ = size;
  if (legend_pending_) place_legend();
  place_labels();
}

namespace {

std::vector<QPolygonF> curves_in_pixels(QCustomPlot* plot, const std::vector<QPointer<QCPGraph>>& graphs) {
  std::vector<QPolygonF> out;
  for (const auto& g : graphs) {
    if (!g || !g->visible()) continue;
    QPolygonF points;
    points.reserve(g->data()->size());
    for (auto it = g->data()->constBegin(); it != g->data()->constEnd(); ++it)
      points << QPointF(plot->xAxis->coordToPixel(it->key), plot->yAxis->coordToPixel(it->value));
    out.push_back(thin_polyline(points));
  }
  return out;
}

QRectF marker_box(QCustomPlot* plot, double key, double value) {
  const QPointF p(plot->xAxis->coordToPixel(key), plot->yAxis->coordToPixel(value));
  return QRectF(p.x() - kMarkerHalf, p.y() - kMarkerHalf, 2 * kMarkerHalf, 2 * kMarkerHalf);
}

}  // namespace

std::vector<QRectF> PeakOverlay::marker_boxes() const {
  std::vector<QRectF> boxes;
  for (const Label& l : labels_)
    if (l.item) boxes.push_back(marker_box(plot_, l.key, l.value));
  return boxes;
}

void PeakOverlay::place_legend() {
  QCPAxisRect* rect = plot_->axisRect();
  const QRectF area = rect->rect();
  if (!plot_->legend->visible() || area.width() < 50 || area.height() < 50) return;  // not laid out yet
  if (legend_is_below(plot_)) {
    // Under the plot since an earlier size: try inside again, after a layout pass with the legend in place.
    put_legend_inside(plot_);
    plot_->replot(QCustomPlot::rpQueuedReplot);
    return;  // still pending
  }
  legend_pending_ = false;
  const QSizeF size = plot_->legend->outerRect().size();
  // The inset layout keeps its own margin from the axes: the legend can only sit inside that.
  const Qt::Alignment corner =
      least_covered_corner(rect->insetLayout()->rect(), size, curves_in_pixels(plot_, curves_), marker_boxes(), 0);
  rect->insetLayout()->setInsetAlignment(0, corner);
  // This layout pass has already placed the legend: redo just the inset so this very frame shows the new corner.
  rect->insetLayout()->update(QCPLayoutElement::upLayout);
  make_room_for_legend(corner);
}

namespace {

// `range` widened by `fraction` of its on-screen length on one side; logarithmic axes widen by a factor.
QCPRange widened(const QCPRange& range, bool log, bool upper, double fraction) {
  if (log) {
    const double factor = std::pow(range.upper / range.lower, fraction);
    return upper ? QCPRange(range.lower, range.upper * factor) : QCPRange(range.lower / factor, range.upper);
  }
  const double step = range.size() * fraction;
  return upper ? QCPRange(range.lower, range.upper + step) : QCPRange(range.lower - step, range.upper);
}

}  // namespace

void PeakOverlay::make_room_for_legend(Qt::Alignment corner) {
  const QRectF legend = plot_->legend->outerRect();
  const auto cost = [&] { return coverage_cost(legend, curves_in_pixels(plot_, curves_), marker_boxes()); };
  if (cost() < 1) return;
  // Widen the axis on the legend's side until the legend hides no data, trying the worker axis and the FLOPS axis
  // separately and keeping the smaller widening. A linear axis only grows away from zero: negative workers or
  // FLOPS would be nonsense on screen.
  struct Option {
    QCPAxis* axis;
    bool upper;
    double fraction = 0;
  };
  std::array<Option, 2> options = {Option{plot_->xAxis, bool(corner & Qt::AlignRight)},
                                   Option{plot_->yAxis, bool(corner & Qt::AlignTop)}};
  for (Option& o : options) {
    const bool log = o.axis->scaleType() == QCPAxis::stLogarithmic;
    if (!log && !o.upper) continue;
    const QCPRange original = o.axis->range();
    for (double f = 0.03; f <= kMaxHeadroom + 1e-9; f += 0.03) {
      o.axis->setRange(widened(original, log, o.upper, f));
      if (cost() < 1) {
        o.fraction = f;
        break;
      }
    }
    o.axis->setRange(original);
  }
  const Option* best = nullptr;
  for (const Option& o : options)
    if (o.fraction > 0 && (!best || o.fraction < best->fraction)) best = &o;
  if (!best) {
    // No affordable room (a small window): the legend goes under the plot, where it hides nothing.
    const int columns = std::max(1, static_cast<int>(plot_->width() / std::max(1.0, legend.width() + 12)));
    put_legend_below(plot_, columns);
    plot_->replot(QCustomPlot::rpQueuedReplot);
    return;
  }
  best->axis->setRange(
      widened(best->axis->range(), best->axis->scaleType() == QCPAxis::stLogarithmic, best->upper, best->fraction));
  // The axes computed their ticks before this layout hook ran: draw once more with the new range.
  plot_->replot(QCustomPlot::rpQueuedReplot);
}

void PeakOverlay::place_labels() {
  if (labels_.empty()) return;
  const QRectF area = plot_->axisRect()->rect();
  std::vector<QPointF> anchors;
  std::vector<QSizeF> sizes;
  std::vector<QRectF> obstacles;
  if (plot_->legend->visible()) obstacles.push_back(QRectF(plot_->legend->rect()).adjusted(-2, -2, 2, 2));
  for (const Label& l : labels_) {
    if (!l.item) continue;
    const QRectF marker = marker_box(plot_, l.key, l.value);
    anchors.push_back(marker.center());
    obstacles.push_back(marker);
    const QSizeF text = QFontMetricsF(l.item->font()).size(Qt::TextSingleLine, l.item->text());
    sizes.push_back(text + QSizeF(2 * kPadding, 2 * kPadding));
  }
  const auto placed = place_labels_greedy(area, anchors, sizes, obstacles, curves_in_pixels(plot_, curves_), kGap);
  std::size_t i = 0;
  for (const Label& l : labels_) {
    if (!l.item) continue;
    const auto& spot = placed[i++];
    // A peak scrolled out of view keeps its label hidden: it would otherwise point at nothing.
    const bool in_view = area.contains(anchors[i - 1]);
    l.item->setVisible(in_view);
    if (spot) {
      l.item->position->setCoords(spot->center());
    } else {
      // No free spot (a crowded log axis): never drop a peak's label silently. It goes beside its marker, kept
      // inside the plot, even if it then touches a curve.
      const QSizeF size = sizes[i - 1];
      QRectF box(anchors[i - 1] + QPointF(kMarkerHalf + kGap, -size.height() / 2), size);
      if (box.right() > area.right()) box.moveRight(anchors[i - 1].x() - kMarkerHalf - kGap);
      box.moveTop(std::clamp(box.top(), area.top(), std::max(area.top(), area.bottom() - box.height())));
      box.moveLeft(std::clamp(box.left(), area.left(), std::max(area.left(), area.right() - box.width())));
      l.item->position->setCoords(box.center());
    }
  }
}

}  // namespace bs::ui
