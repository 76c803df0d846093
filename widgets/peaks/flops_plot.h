// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <QWidget>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "store/workspace.h"

class QCustomPlot;
class QCPGraph;
class QCheckBox;

namespace bs::ui {
class PeakOverlay;

// FLOPS against workers for the visible runs: colour per device, line style per D, mean ± SD band where runs
// are repeated, a labelled marker at each series' peak, the legend inside the plot in its emptiest corner,
// log/linear axes, zoom/pan and a hover read-out.
class FlopsPlot : public QWidget {
  Q_OBJECT
 public:
  explicit FlopsPlot(QWidget* parent = nullptr);
  // `labels`: the user's names of runs by id (store/run_label_store.h). Series that would read the same add what
  // differs (label, date and time, host, N); repeated runs of one series take their own marker.
  void set_runs(const std::vector<const StoredRun*>& runs, const std::map<std::int64_t, std::string>& labels = {});
  void set_log_x(bool on);
  void set_log_y(bool on);
  bool log_x() const;
  bool log_y() const;
  void reset_view();

  QCustomPlot* plot() const { return plot_; }
  int series_count() const { return static_cast<int>(series_.size()); }
  // The graphs of the runs themselves, without the error-band and peak-marker helper graphs.
  std::vector<QCPGraph*> series_graphs() const;
  QString value_axis_label() const;
  PeakOverlay* overlay() const { return overlay_; }
  // The hover text for the data point nearest to a pixel position (empty when none is close).
  QString read_out_at(const QPointF& pixel) const;

 private:
  struct Series {
    QCPGraph* graph;
    const StoredRun* run;
  };
  void rebuild();
  void on_mouse_move(QMouseEvent* event);

  QCustomPlot* plot_;
  PeakOverlay* overlay_ = nullptr;
  QCheckBox* log_x_box_;
  QCheckBox* log_y_box_;
  std::vector<const StoredRun*> runs_;
  std::map<std::int64_t, std::string> labels_;
  std::vector<Series> series_;
  double scale_ = 1;  // FLOPS per displayed unit (1e12 when the axis reads TFLOPS)
};

}  // namespace bs::ui
