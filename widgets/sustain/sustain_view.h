// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The Sustained tab (#53): will it hold its speed for a whole match? One stored sustained record at a time (a run
// of `sustain` here or on a robot, or an imported log's clocks and temperatures), chosen from a list naming its
// platform, load and date: rate, clocks, temperatures and power on one time axis (figures/sustain_figure.h, bands
// over throttled spans, the onset marked), and what core concludes, in the CLI's words (sustain/sustain_text.h):
// stability against the stable threshold, throttling with its onset or why it is unknown, sustained against peak
// rate. The thresholds are settable here and re-judge at once; while a run here goes on, its intervals are drawn
// as they come. Ctrl+E exports the plot.
#include <QWidget>
#include <optional>
#include <vector>

#include "store/workspace.h"
#include "sustain/sustain_analysis.h"

class QComboBox;
class QCustomPlot;
class QDoubleSpinBox;
class QLabel;

namespace bs::ui {

class SustainRunPanel;

class SustainView : public QWidget {
  Q_OBJECT
 public:
  explicit SustainView(QWidget* parent = nullptr);
  // Every stored record in the workspace's order; the one shown stays chosen while it is still there, and a new one
  // (a higher id) comes to the front.
  void set_records(std::vector<StoredSustainRun> records);
  bool select(std::int64_t id);  // false when there is none with this id

  SustainRunPanel* run_panel() const { return run_; }
  QComboBox* chooser() const { return chooser_; }
  QDoubleSpinBox* stable_percent() const { return stable_; }
  QDoubleSpinBox* throttle_threshold() const { return threshold_; }
  QCustomPlot* plot() const { return plot_; }
  QLabel* summary() const { return summary_; }
  QLabel* source() const { return source_; }
  const SustainRun* current() const;  // the record shown (the live run while one goes on)
  sustain::SustainAnalysis current_analysis() const;

 private:
  void show_current();
  void show_live(const SustainRun& so_far);
  void draw(const SustainRun& run, const QString& origin);
  sustain::AnalysisOptions options() const;

  SustainRunPanel* run_;
  QComboBox* chooser_;
  QDoubleSpinBox* stable_;
  QDoubleSpinBox* threshold_;
  QLabel* summary_;
  QLabel* source_;
  QLabel* empty_;
  QCustomPlot* plot_;
  std::vector<StoredSustainRun> records_;
  std::optional<SustainRun> live_;  // the run going on here, drawn interval by interval
  std::int64_t newest_seen_ = -1;   // the highest id shown so far
};

}  // namespace bs::ui
