// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <QWidget>
#include <vector>

#include "model/dnn_run.h"

class QLabel;
class QTableWidget;

namespace bs::ui {

// The detection-network inference runs (`bench dnn`) as a sortable table: one row per platform, network, input
// and cv::dnn target, the cells of core's inference_table() (so the views, the CLI and the report agree), the
// best value of each numeric column marked, each row's provenance in its tooltip. Runs of built-in architectures
// carry "architecture timing: no detections" in their Network cell and are shown in italics. Hidden while there
// are no runs. Used by the Platforms and Pipeline views.
class InferenceTable : public QWidget {
  Q_OBJECT
 public:
  explicit InferenceTable(QWidget* parent = nullptr);
  void set_runs(std::vector<DnnRun> runs);
  QTableWidget* table() const { return table_; }
  const std::vector<DnnRun>& runs() const { return runs_; }

 private:
  QLabel* title_;
  QTableWidget* table_;
  std::vector<DnnRun> runs_;
};

}  // namespace bs::ui
