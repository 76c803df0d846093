// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <QDialog>

#include "analysis/platform/regression_compare.h"

class QCheckBox;
class QDoubleSpinBox;
class QLabel;
class QTableWidget;

namespace bs::ui {

// Regression compare of the open workspace (A, the baseline) against another one (B): per measure mean ± SD (n)
// on both sides, the change, Mann-Whitney p and the verdict, regressions in red and improvements in green. The
// same core function as `benchscope-cli compare`, so the GUI and a lab's CI agree.
class CompareDialog : public QDialog {
  Q_OBJECT
 public:
  CompareDialog(std::vector<FlopsRun> runs_a, std::vector<ResultSet> sets_a, std::vector<FlopsRun> runs_b,
                std::vector<ResultSet> sets_b, const QString& name_a, const QString& name_b, QWidget* parent = nullptr);
  QTableWidget* table() const { return table_; }
  int regressions() const { return regressions_; }
  void set_threshold_percent(double percent);

 private:
  void recompute();
  std::vector<FlopsRun> runs_a_, runs_b_;
  std::vector<ResultSet> sets_a_, sets_b_;
  QDoubleSpinBox *threshold_, *alpha_;
  QCheckBox *every_point_, *show_unchanged_;
  QLabel* summary_;
  QTableWidget* table_;
  int regressions_ = 0;
};

}  // namespace bs::ui
