// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Save selection as phase (issue #43.4): a phase belongs to the log it was drawn on, not to every log the selection
// overlaps (on main a phase drawn over the NUC's log landed on the Jetson's too). The dialog asks the phase's name and
// its log, offering the visible logs the selection covers, the one drawn on first; "every log it covers" stays
// available as the last choice, for a phase that truly is shared (a run timed on both machines at once).
#include <QDialog>
#include <vector>

class QComboBox;
class QLineEdit;

namespace bs::ui {

class SavePhaseDialog : public QDialog {
  Q_OBJECT
 public:
  // `logs`: the names of the logs the selection covers ("NUC — nuc-current.csv"); `preferred` the index of the one
  // drawn on (the first choice).
  SavePhaseDialog(const std::vector<QString>& logs, std::size_t preferred, QWidget* parent = nullptr);
  QString name() const;
  // Indexes into `logs` that get the phase: one, or every one for the last choice.
  std::vector<std::size_t> chosen() const;

 private:
  QLineEdit* name_;
  QComboBox* log_;
  std::size_t count_;
};

}  // namespace bs::ui
