// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <QAbstractTableModel>
#include <QTableView>

#include "analysis/peaks/flops.h"

namespace bs::ui {

// Rows of bs::peak_table() (paper Tables 1 and 2 plus ratios), with a numeric sort role per column.
class PeakTableModel : public QAbstractTableModel {
  Q_OBJECT
 public:
  enum Column {
    Platform,
    Device,
    Backend,
    Dims,
    Run,
    Peak,
    Workers,
    Reported,
    Ratio,
    OfTheoretical,
    OfCeiling,
    OfSpec,
    Origin,
    ColumnCount
  };
  static constexpr int kSortRole = Qt::UserRole + 1;
  // true for every cell of a row whose peak carries plausibility flags (analysis/plausibility.h). Such a row is
  // tinted, its peak shows "⚠", and every cell's tooltip starts with the reasons.
  static constexpr int kFlaggedRole = Qt::UserRole + 2;

  using QAbstractTableModel::QAbstractTableModel;
  // `color_indices` parallels `rows`: the device colour of each row. `run_names[PeakRow::run_index]` is what tells
  // the row's run from others of the same device, backend and D (its label from F2, else a date or host; issue
  // #43.4: two sweeps of one machine were two identical rows), shown in the Run column.
  void set_rows(std::vector<PeakRow> rows, std::vector<int> color_indices, std::vector<std::string> run_names = {});
  const PeakRow& row_at(int row) const { return rows_[static_cast<std::size_t>(row)]; }
  const std::vector<PeakRow>& rows() const { return rows_; }  // grouped by platform

  int rowCount(const QModelIndex& parent = {}) const override;
  int columnCount(const QModelIndex& parent = {}) const override;
  QVariant data(const QModelIndex& index, int role) const override;
  QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

 private:
  std::vector<PeakRow> rows_;
  std::vector<int> colors_;
  std::vector<QString> runs_;  // per row: the Run column
};

// "43.16 ± 13.81 GFLOPS": the peak's mean and SD under one prefix, so the cell is short enough never to be elided
// (on main "43.16 GFLOPS ± 13.81 GFLOPS" was elided to "43.16 GFLOPS…13.81 GFLOPS", which reads as a range).
QString peak_mean_sd_text(const PeakRow& row);

// Sortable view of the peak table; Ctrl+C copies the selection as tab-separated text.
class PeakTableView : public QTableView {
  Q_OBJECT
 public:
  explicit PeakTableView(QWidget* parent = nullptr);
  PeakTableModel* peak_model() const { return model_; }
  QString selection_as_tsv() const;
  // Selects the row of that run's peak and scrolls it into view (a run that just landed); false when absent.
  bool show_row(const std::string& platform, const std::string& device, const std::string& backend, int dims);

 protected:
  void keyPressEvent(QKeyEvent* event) override;

 private:
  PeakTableModel* model_;
};

}  // namespace bs::ui
