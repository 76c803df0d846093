// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The Platforms tab's candidates: computers the lab does not own yet, chosen from the library of published results
// (a computer menu or typed ids: "orin,pi5"), ranked beside the own platforms under the tab's constraints, within
// one network, scenario and precision only (core: analysis/library/candidates.h). The table shows every row's
// origin with its own marker (● measured, ■ reconstructed, ◆ published; published rows in italics on a tint),
// the differences that remain and, in the tooltip, the source and any plausibility flag; the figure beside it
// plots inferences per second against power with one marker per origin and one colour per class. The chosen
// computers' ROS 2 graph benchmark results (ros2_benchmark, RobotPerf) are a table on a page of their own beside it,
// each row in its class and saying what its value is (core: analysis/library/graph_benchmarks_table.h).
#include <QWidget>
#include <optional>
#include <vector>

#include "analysis/library/candidates.h"

class QCustomPlot;
class QLabel;
class QLineEdit;
class QTabWidget;
class QTableWidget;
class QToolButton;

namespace bs::ui {

class CandidatesPanel : public QWidget {
  Q_OBJECT
 public:
  explicit CandidatesPanel(QWidget* parent = nullptr);
  // The own platforms and results, with the constraints and battery of the tab; recomputes the ranking.
  void set_own(std::vector<PlatformRow> rows, std::vector<PipelineRun> pipelines, std::vector<DnnRun> dnn,
               std::vector<ResultSet> result_sets, const Constraints& constraints, const ComparisonOptions& options,
               std::optional<std::vector<headroom::LoopVerdict>> loop = std::nullopt,
               std::optional<std::vector<sustain::SustainVerdict>> sustained = std::nullopt);
  // "orin,pi5": library computer ids or aliases, or result ids. An unknown word is said in the panel's note.
  void set_selection(const QString& spec);
  QString selection() const;
  QTableWidget* table() const { return table_; }
  QTableWidget* graph_table() const { return graph_table_; }
  QTabWidget* views() const { return views_; }  // page 0: inference candidates; page 1: graph benchmarks
  QCustomPlot* plot() const { return plot_; }
  const std::vector<CandidateClass>& classes() const { return classes_; }
  const std::vector<PeakClass>& peaks() const { return peaks_; }

 signals:
  // The user typed a selection (and left the field) or ticked a computer in the menu; set_selection() emits nothing.
  void selection_edited();

 protected:
  // A replot while the tab was hidden leaves the plot's buffer stale: draw it again when shown.
  void showEvent(QShowEvent* event) override;

 private:
  void recompute();
  void fill();
  void fill_graphs(const std::vector<const LibraryResult*>& chosen);
  void export_csv();
  void export_graphs_csv();

  QLineEdit* spec_;
  QToolButton* computers_;
  QLabel* note_;
  QTableWidget* table_;
  QCustomPlot* plot_;
  QTabWidget* views_;  // the inference candidates' table and figure; the graph benchmarks (shown when there are any)
  QWidget* graphs_;    // the graph benchmarks' title, export button and table
  QTableWidget* graph_table_;
  std::vector<GraphBenchmarkClass> graph_classes_;
  std::vector<PlatformRow> rows_;
  std::vector<PipelineRun> pipelines_;
  std::vector<DnnRun> dnn_;
  std::vector<ResultSet> sets_;
  Constraints constraints_;
  ComparisonOptions options_;
  std::optional<std::vector<headroom::LoopVerdict>> loop_;         // the control loop's verdicts, when one is required
  std::optional<std::vector<sustain::SustainVerdict>> sustained_;  // the sustained verdicts, when one is required
  std::vector<CandidateClass> classes_;
  std::vector<PeakClass> peaks_;
};

// The origin as the views show it: marker and word ("◆ published").
QString origin_marker_text(DataOrigin origin);

}  // namespace bs::ui
