// SPDX-License-Identifier: GPL-3.0-or-later
#include "power/power_trace_drag.h"

#include <qcustomplot.h>
#include <QMouseEvent>

namespace bs::ui {

PowerTraceDrag::PowerTraceDrag(QCustomPlot* plot) : QObject(plot), plot_(plot) { plot_->installEventFilter(this); }

std::optional<std::size_t> PowerTraceDrag::graph_at(const QMouseEvent* e) const {
  std::optional<std::size_t> best;
  double best_px = kGrabPx;
  for (int i = 0; i < plot_->graphCount(); ++i) {
    QCPGraph* g = plot_->graph(i);
    if (!g->visible() || g->dataCount() == 0) continue;
    // selectTest: the pixel distance to the graph's line (-1: too far), whether or not the graph is selectable.
    const double px = g->selectTest(e->position(), false);
    if (px >= 0 && px <= best_px) best_px = px, best = static_cast<std::size_t>(i);
  }
  return best;
}

bool PowerTraceDrag::eventFilter(QObject* watched, QEvent* event) {
  if (watched != plot_) return false;
  switch (event->type()) {
    case QEvent::MouseButtonPress: {
      auto* e = static_cast<QMouseEvent*>(event);
      if (e->button() != Qt::LeftButton || !(e->modifiers() & Qt::ControlModifier)) return false;
      trace_ = graph_at(e);
      if (!trace_) return false;
      press_x_ = plot_->xAxis->pixelToCoord(e->position().x());
      plot_->setCursor(Qt::ClosedHandCursor);
      return true;  // swallowed: the plot must not pan while a trace moves
    }
    case QEvent::MouseMove: {
      if (!trace_) return false;
      auto* e = static_cast<QMouseEvent*>(event);
      emit dragged(*trace_, plot_->xAxis->pixelToCoord(e->position().x()) - press_x_, false);
      return true;
    }
    case QEvent::MouseButtonRelease: {
      if (!trace_) return false;
      auto* e = static_cast<QMouseEvent*>(event);
      const std::size_t trace = *trace_;
      trace_.reset();
      plot_->setCursor(Qt::ArrowCursor);
      emit dragged(trace, plot_->xAxis->pixelToCoord(e->position().x()) - press_x_, true);
      return true;
    }
    default:
      return false;
  }
}

}  // namespace bs::ui
