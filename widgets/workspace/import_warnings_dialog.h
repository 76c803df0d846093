// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The warnings of the last import, each on a line of its own (issue #51): what a folder of MLPerf downloads, a
// power log or a latency file said about itself (a companion not paired, a power mean over the whole log, a computer
// not stated) is read here, not counted in the status bar. Not modal: it stays open beside the views it explains.
#include <QDialog>
#include <QStringList>

class QLabel;
class QListWidget;

namespace bs::ui {

struct ImportReport;

class ImportWarningsDialog : public QDialog {
  Q_OBJECT
 public:
  explicit ImportWarningsDialog(QWidget* parent = nullptr);
  // Shows the report's warnings and skipped files (a companion read with its summary, a description with no
  // summary), replacing the previous import's.
  void set_report(const ImportReport& report);
  QListWidget* list() const { return list_; }
  QString text() const;  // every line, as Copy puts it on the clipboard

 private:
  QLabel* headline_;
  QListWidget* list_;
};

}  // namespace bs::ui
