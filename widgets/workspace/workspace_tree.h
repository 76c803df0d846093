// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <QSet>
#include <QStandardItemModel>
#include <QTreeView>
#include <cstdint>
#include <map>
#include <string>

#include "store/workspace.h"

namespace bs::ui {

// What a row of the tree stands for, as far as renaming and removing go.
struct TreeItemRef {
  enum class Kind {
    None,
    Platform,
    Device,
    Run,
    PowerLog,
    Frame,
    PipelineRun,
    ResultSet,
    Headroom,
    InferenceRun,
    SustainedRun,
    BatteryPreset
  };
  Kind kind = Kind::None;
  qint64 id = 0;         // run, trace, frame, pipeline run, result set or headroom measurement id
  qint64 import_id = 0;  // the import that brought it (0: none, e.g. a preset or a platform)
  QString name;          // what is shown and renamed: platform name, log label, preset name, a run's label, ...
  QString platform;      // a device's platform (devices are named within their platform)
  int color_index = -1;  // a device's colour
  // A stored run (id > 0) is renamed by its label; sweeps derived from other tools' results (id < 0) are not.
  bool renamable() const {
    return kind == Kind::Platform || kind == Kind::PowerLog || kind == Kind::Frame || (kind == Kind::Run && id > 0);
  }
  bool removable() const { return import_id > 0 || kind == Kind::BatteryPreset; }
};

// Everything else the workspace holds, listed below the runs in sections ("Power logs", "Frames", ...).
struct WorkspaceItem {
  TreeItemRef ref;
  QString text;     // the row's text
  QString tooltip;  // provenance
};

// Platform -> device -> backend -> run, with tristate checkboxes that show or hide runs in every view; then one
// section per other kind of item. Right-click, F2 and Delete ask to rename or remove (the window does it, undoably).
class WorkspaceTree : public QTreeView {
  Q_OBJECT
 public:
  explicit WorkspaceTree(QWidget* parent = nullptr);
  // Keeps the visibility of runs already known. `labels`: the user's names of runs by id, shown first in the run's
  // row; rows of one backend that would read the same add what differs (date and time, host).
  void set_runs(const std::vector<StoredRun>& runs, const std::map<std::int64_t, std::string>& labels = {});
  QSet<qint64> visible_runs() const;
  void set_run_visible(qint64 run_id, bool visible);
  bool select_run(qint64 run_id);  // expands its parents, selects and scrolls to it; false when unknown
  int run_count() const;
  // Replaces the sections below the runs; call after set_runs.
  void set_items(const std::vector<WorkspaceItem>& items);
  int item_count(TreeItemRef::Kind kind) const;
  TreeItemRef ref_at(const QModelIndex& index) const;
  TreeItemRef current_ref() const { return ref_at(currentIndex()); }

 signals:
  void visibility_changed(const QSet<qint64>& visible_run_ids);
  void rename_requested(const bs::ui::TreeItemRef& item);
  void remove_requested(const bs::ui::TreeItemRef& item);
  void color_requested(const bs::ui::TreeItemRef& device, int color_index);
  // A power log's "Supply voltage…" and "Platform…" (issue #32.2, #32.3).
  void supply_voltage_requested(const bs::ui::TreeItemRef& log);
  void platform_requested(const bs::ui::TreeItemRef& log);

 protected:
  void keyPressEvent(QKeyEvent* event) override;

 private:
  void on_item_changed(QStandardItem* item);
  void show_menu(const QPoint& pos);
  void collect(const QStandardItem* item, QSet<qint64>& out) const;
  QStandardItem* find_run(QStandardItem* parent, qint64 run_id) const;
  QStandardItemModel model_;
  QSet<qint64> hidden_;
  bool updating_ = false;
};

}  // namespace bs::ui
