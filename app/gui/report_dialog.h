// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// File > Export report (issue #43.2): where to write the report, and the decision it will state on its first page,
// shown before it is written: the constraints, battery, mission and library candidates set in the Platforms tab (kept
// in the workspace), the recommendation they give, and the power log each platform's numbers come from. To change
// them, "Change in the Platforms tab" leaves the dialog there.
#include <QDialog>

class QLabel;
class QLineEdit;
class QPushButton;

namespace bs::ui {

class ReportDialog : public QDialog {
  Q_OBJECT
 public:
  // `decision`: the lines to show (rich text allowed), e.g. "<b>Constraints:</b> a power budget of 10 W".
  ReportDialog(const QString& default_path, const QStringList& decision, QWidget* parent = nullptr);
  QString path() const;                              // as typed; ".html" added when it has neither ending
  bool pdf() const;                                  // the path ends in .pdf
  bool change_requested() const { return change_; }  // left to change the decision in the Platforms tab

 private:
  QLineEdit* path_;
  QLabel* decision_;
  QPushButton* export_;
  bool change_ = false;
};

}  // namespace bs::ui
