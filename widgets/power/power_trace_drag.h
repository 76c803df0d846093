// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Ctrl + drag on a trace of the Power tab's plot shifts that trace in time (issue #19 "Overlays": drag, typed
// offset, or alignment at a phase). A press within a few pixels of a visible graph grabs it; the plot does not pan
// meanwhile. Graph i of the plot is trace i of the view.
#include <QObject>
#include <cstddef>
#include <optional>

class QCustomPlot;
class QMouseEvent;

namespace bs::ui {

class PowerTraceDrag : public QObject {
  Q_OBJECT
 public:
  explicit PowerTraceDrag(QCustomPlot* plot);
  static constexpr double kGrabPx = 8;  // how close to a graph's line a Ctrl + press grabs it

 signals:
  // While dragging: trace `trace` moved by `by_s` seconds since the press (final: the button was released).
  void dragged(std::size_t trace, double by_s, bool final);

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  std::optional<std::size_t> graph_at(const QMouseEvent* e) const;
  QCustomPlot* plot_;
  std::optional<std::size_t> trace_;  // being dragged
  double press_x_ = 0;                // on the time axis
};

}  // namespace bs::ui
