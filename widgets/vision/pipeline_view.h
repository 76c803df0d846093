// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <QWidget>
#include <vector>

#include "model/dnn_run.h"
#include "model/pipeline_run.h"

class QLabel;
class QTableWidget;

namespace bs::ui {

class PipelineMeasurePanel;
class InferenceTable;

// The paper's pipeline timings as a table: one row per (stage, platform) with mean ± SD (n) in ms, p95, the rate
// the stage alone sustains and the run's measured throughput; sortable by any column (numerically), each row's
// provenance (measured on which host, or reconstructed from the paper) in its tooltip. The rows come from core
// (pipeline_table_rows) so the view and the exported tables agree. Above the table, a panel measures the pipeline
// on this machine (run_measured hands the run to the main window to store).
class PipelineView : public QWidget {
  Q_OBJECT
 public:
  enum Column { Stage, Platform, Device, Time, P95, StageRate, Throughput, Data, LensColumn, ColumnCount };
  explicit PipelineView(QWidget* parent = nullptr);
  void set_data(std::vector<PipelineRun> runs);
  // bench dnn runs: the inference table under the pipeline's (hidden while there are none).
  void set_inference_runs(std::vector<DnnRun> runs);
  InferenceTable* inference_table() const { return inference_; }
  QTableWidget* table() const { return table_; }
  PipelineMeasurePanel* measure_panel() const { return measure_; }

 signals:
  void run_measured(const bs::PipelineRun& run);

 private:
  void fill();
  void export_table(bool latex);

  PipelineMeasurePanel* measure_;
  QLabel* summary_;
  QTableWidget* table_;
  InferenceTable* inference_;
  std::vector<PipelineRun> runs_;
};

}  // namespace bs::ui
