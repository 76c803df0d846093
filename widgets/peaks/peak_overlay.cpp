// SPDX-License-Identifier: GPL-3.0-or-later
#include "peaks/peak_overlay.h"

#include "common/plot_legend.h"

#include <algorithm>

#include <qcustomplot.h>
#include <QFontMetricsF>
#include <array>
#include <cmath>

#include "overlay_geometry.h"
#include "plot_labels.h"

namespace bs::ui {
namespace {

constexpr double kMaxHeadroom = 0.3;  // at most this much of an axis is added to keep the legend off the data

}  // namespace

PeakOverlay::PeakOverlay(QCustomPlot* plot)
    : QObject(plot), plot_(plot), labels_(new AnchoredLabels(plot, /*auto_place=*/false)) {
  connect(plot_, &QCustomPlot::afterLayout, this, &PeakOverlay::on_after_layout);
}

void PeakOverlay::clear() {
  curves_.clear();
  labels_->clear();
  legend_pending_ = true;
}

void PeakOverlay::add_curve(QCPGraph* graph) {
  curves_.emplace_back(graph);
  labels_->add_curve(graph);
}

void PeakOverlay::add_peak_label(double key, double value, const QString& text, const QColor& color, QCPGraph* curve) {
  labels_->add(key, value, text, color, curve);
}

int PeakOverlay::shown_label_count() const { return labels_->shown_count(); }

std::vector<QCPItemText*> PeakOverlay::labels() const { return labels_->labels(); }

void PeakOverlay::on_after_layout() {
  // A new plot size (the window was resized or first shown) changes where the data lies in pixels. The widget's
  // size, not the axis rect's: moving the legend under the plot changes the latter, and must not trigger again.
  const QSize size = plot_->size();
  if (size != laid_out_size_) legend_pending_ = true;
  laid_out_size_ = size;
  if (legend_pending_) place_legend();
  labels_->place();
}

void PeakOverlay::place_legend() {
  QCPAxisRect* rect = plot_->axisRect();
  const QRectF area = rect->rect();
  if (!plot_->legend->visible() || area.width() < 50 || area.height() < 50) return;  // not laid out yet
  if (moved_below_) {
    // Under the plot since an earlier size (this overlay put it there): try inside again, after a layout pass with
    // the legend in place.
    moved_below_ = false;
    put_legend_inside(plot_);
    plot_->replot(QCustomPlot::rpQueuedReplot);
    return;  // still pending
  }
  // A figure export moves the legend out of the axes (below them): nothing to place, no room to make.
  if (plot_->legend->layout() != rect->insetLayout()) return;
  legend_pending_ = false;
  const QSizeF size = plot_->legend->outerRect().size();
  // The inset layout keeps its own margin from the axes: the legend can only sit inside that.
  const Qt::Alignment corner =
      least_covered_corner(rect->insetLayout()->rect(), size, graphs_in_pixels(curves_), labels_->marker_boxes(), 0);
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
  const auto cost = [&] { return coverage_cost(legend, graphs_in_pixels(curves_), labels_->marker_boxes()); };
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
    moved_below_ = true;
    plot_->replot(QCustomPlot::rpQueuedReplot);
    return;
  }
  best->axis->setRange(
      widened(best->axis->range(), best->axis->scaleType() == QCPAxis::stLogarithmic, best->upper, best->fraction));
  // The axes computed their ticks before this layout hook ran: draw once more with the new range.
  plot_->replot(QCustomPlot::rpQueuedReplot);
}

}  // namespace bs::ui
