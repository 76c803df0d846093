// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A statistics table of time ranges (the Power tab's selection, or its phases): rows given as text by
// analysis/range_table.h, so they are the same cells `benchscope-cli power --phases` prints, and a "Copy as table"
// button that puts them on the clipboard tab-separated with units in the headers. Optionally a "Save as phase…"
// button (the selection panel) that emits save_phase_requested(); the Power tab asks the name and the log.
#include <QWidget>
#include <string>
#include <vector>

class QLabel;
class QPushButton;
class QTableWidget;

namespace bs::ui {

class PowerStatsPanel : public QWidget {
  Q_OBJECT
 public:
  PowerStatsPanel(const QString& placeholder, bool can_save_phase, QWidget* parent = nullptr);
  // `headers` and every row have the same length; `tips` (optional, per row) become the rows' tooltips.
  void set_table(const QString& caption, const std::vector<std::string>& headers,
                 const std::vector<std::vector<std::string>>& rows, const std::vector<QString>& tips = {});
  void clear_table();  // shows the placeholder
  QTableWidget* table() const { return table_; }
  QString tsv() const;  // what "Copy as table" copies
  QPushButton* copy_button() const { return copy_; }
  QPushButton* save_button() const { return save_; }

 signals:
  void save_phase_requested();

 private:
  QLabel* caption_;
  QTableWidget* table_;
  QPushButton* copy_;
  QPushButton* save_ = nullptr;
  QString placeholder_;
  std::vector<std::string> headers_;
  std::vector<std::vector<std::string>> rows_;
};

}  // namespace bs::ui
