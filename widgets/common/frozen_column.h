// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Keeps a table's first column in place while the rest scrolls sideways (Qt's "frozen column" pattern): a second
// view over the same model shows only that column, laid over the table's left edge and kept in step with its
// rows, scrolling, sorting and column width. Used where the first column names what a row is (the platform) and
// the numbers run off to the right on a small window.
#include <QObject>

class QTableView;

namespace bs::ui {

class FrozenFirstColumn : public QObject {
  Q_OBJECT
 public:
  // Installs itself on `table` (which owns it). The table's model must already be set. The owner of the table
  // deletes this before the table goes (a table deleting its model resets it, and the overlay must not follow).
  explicit FrozenFirstColumn(QTableView* table);
  ~FrozenFirstColumn() override;
  QTableView* view() const { return frozen_; }
  // Call after the table's columns changed (count, hidden columns): only the first stays visible in the overlay.
  void sync_columns();

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  void update_geometry();
  QTableView* table_;
  QTableView* frozen_;
};

}  // namespace bs::ui
