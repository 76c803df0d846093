// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <QSet>
#include <QStandardItemModel>
#include <QTreeView>

#include "store/workspace.h"

namespace bs::ui {

// Platform -> device -> backend -> run, with tristate checkboxes that show or hide runs in every view.
class WorkspaceTree : public QTreeView {
  Q_OBJECT
 public:
  explicit WorkspaceTree(QWidget* parent = nullptr);
  void set_runs(const std::vector<StoredRun>& runs);  // keeps the visibility of runs already known
  QSet<qint64> visible_runs() const;
  void set_run_visible(qint64 run_id, bool visible);
  bool select_run(qint64 run_id);  // expands its parents, selects and scrolls to it; false when unknown
  int run_count() const;

 signals:
  void visibility_changed(const QSet<qint64>& visible_run_ids);

 private:
  void on_item_changed(QStandardItem* item);
  void collect(const QStandardItem* item, QSet<qint64>& out) const;
  QStandardItem* find_run(QStandardItem* parent, qint64 run_id) const;
  QStandardItemModel model_;
  QSet<qint64> hidden_;
  bool updating_ = false;
};

}  // namespace bs::ui
