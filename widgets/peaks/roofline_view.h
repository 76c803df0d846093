// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <QWidget>
#include <map>
#include <vector>

#include "analysis/roofline/roofline.h"
#include "analysis/roofline/stage_roofline.h"

class QCustomPlot;
class QLabel;

namespace bs::ui {

class AnchoredLabels;

// Roofline per device on log-log axes: the compute ceiling from the stated (or measured) peak, the memory ceiling
// from measured bandwidth (STREAM triad from "run bandwidth", or clpeak), and the rotation kernel's runs placed at
// their intensity and peak FLOPS; the preprocessing stage of each pipeline run (stars) at its modelled arithmetic
// intensity and measured throughput (analysis/stage_roofline.h), with the ± SD range, under its device's roof.
// Device colours as in every other view; hovering a star shows its numbers and the run it came from.
class RooflineView : public QWidget {
  Q_OBJECT
 public:
  explicit RooflineView(QWidget* parent = nullptr);
  // colors: (platform, device) -> colour index of the device in the workspace.
  void set_data(std::vector<FlopsRun> runs, std::vector<ResultSet> sets,
                std::map<std::pair<std::string, std::string>, int> colors, std::vector<PipelineRun> pipelines = {});
  QCustomPlot* plot() const { return plot_; }
  const std::vector<RooflineCeiling>& ceilings() const { return ceilings_; }
  const std::vector<RooflinePoint>& points() const { return points_; }
  const StagePlacements& stages() const { return stages_; }
  // The tooltip text of a placed stage (what hovering its star shows).
  QString stage_tooltip(const StagePlacement& s) const;

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  void redraw();
  QCustomPlot* plot_;
  QLabel* note_;
  // The "⚠" labels of flagged peaks, then the pipeline stages' labels: apart from each other, inside the axes.
  AnchoredLabels* flag_labels_;
  std::vector<FlopsRun> runs_;
  std::vector<ResultSet> sets_;
  std::map<std::pair<std::string, std::string>, int> colors_;
  std::vector<RooflineCeiling> ceilings_;
  std::vector<RooflinePoint> points_;
  std::vector<PipelineRun> pipelines_;
  StagePlacements stages_;
};

}  // namespace bs::ui
