// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <QObject>
#include <QPointer>
#include <QRectF>
#include <QSize>
#include <vector>

class QCustomPlot;
class QCPGraph;
class QCPItemText;

namespace bs::ui {
class AnchoredLabels;

// Keeps a plot's legend and its peak labels where they hide the least data. After every layout pass (zoom, pan,
// resize) the labels are re-placed around their peaks, skipping any that would collide; the legend moves to the
// least crowded corner only when the data, the axis scales or the plot size change, so it never jumps while the
// user pans or zooms. When no corner is free, the axis on the legend's side is widened a little (at most 30%) to make
// room, as one would by hand.
class PeakOverlay : public QObject {
  Q_OBJECT
 public:
  explicit PeakOverlay(QCustomPlot* plot);

  // Forget every curve and label. Call before QCustomPlot::clearGraphs()/clearItems() delete them.
  void clear();
  // A data series the overlays should avoid covering.
  void add_curve(QCPGraph* graph);
  // A label beside the peak marker at (key, value) in plot coordinates on `curve` (added with add_curve; never
  // labelled nearer another curve). Add in priority order (highest first): when labels collide, the later one is
  // hidden.
  void add_peak_label(double key, double value, const QString& text, const QColor& color, QCPGraph* curve = nullptr);
  void request_legend_placement() { legend_pending_ = true; }

  int shown_label_count() const;
  std::vector<QCPItemText*> labels() const;

 private:
  void on_after_layout();
  void place_legend();
  void make_room_for_legend(Qt::Alignment corner);

  QCustomPlot* plot_;
  AnchoredLabels* labels_;  // the peak labels: the same placement as in figure exports (figures/plot_labels.h)
  std::vector<QPointer<QCPGraph>> curves_;
  bool legend_pending_ = true;
  bool moved_below_ = false;  // this overlay put the legend under the plot (no room inside at that size)
  QSize laid_out_size_;
};

}  // namespace bs::ui
