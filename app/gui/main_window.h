// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <QMainWindow>
#include <QTemporaryDir>
#include <QToolBar>
#include <functional>
#include <memory>

class QAction;
class QLabel;
class QUndoStack;

#include "analysis/platform/platform_comparison.h"
#include "frames/frame_raw.h"
#include "paper_figures.h"
#include "power/log_voltage_dialog.h"
#include "power/shared_traces.h"
#include "store/decision_store.h"
#include "store/home_batch.h"
#include "store/workspace.h"
#include "workspace/damage_banner.h"
#include "workspace/import_controller.h"
#include "workspace/workspace_tree.h"

class QSplitter;

namespace bs::ui {

class PowerTraceLoader;
class ImportWarningsDialog;
class FlopsPlot;
class PeakTableView;
class ImportController;
class RecentFiles;
class KernelRunner;
class RemoteRun;
class PowerView;
class PlatformView;
class PipelineView;
class RooflineView;
class FramesView;
class EfficiencyView;
class BatteryView;
class LensTab;
class HeadroomView;
class SustainView;
class LogChoiceBar;
struct ImportReport;

// The window: workspace tree (left dock), FLOPS plot (centre), peak table (bottom dock). It owns the open
// workspace and wires actions to the views; the views compute nothing themselves.
class MainWindow : public QMainWindow {
  Q_OBJECT
 public:
  explicit MainWindow(QWidget* parent = nullptr);
  ~MainWindow() override;

  bool open_workspace(const QString& path);  // shows a dialog and returns false on error
  void new_untitled_workspace();
  // Imports synchronously (GUI command line, tests); the menu and drag-and-drop use the background controller.
  void import_paths_now(const QStringList& paths);
  void import_paths(const QStringList& paths);

  WorkspaceTree* tree() const { return tree_; }
  // View > Reset layout: docks, the FLOPS and Platforms tabs' splits and the window size as on first start.
  PowerTraceLoader* trace_loader() const { return trace_loader_; }  // long power logs load here
  void reset_layout();
  FlopsPlot* flops_plot() const { return plot_; }
  PeakTableView* peak_table() const { return peaks_; }
  KernelRunner* kernel_runner() const { return runner_; }
  PowerView* power_view() const { return power_; }
  PlatformView* platform_view() const { return platforms_; }
  RooflineView* roofline_view() const { return roofline_; }
  FramesView* frames_view() const { return frames_; }
  PipelineView* pipeline_view() const { return pipeline_; }
  EfficiencyView* efficiency_view() const { return efficiency_; }
  BatteryView* battery_view() const { return battery_; }
  HeadroomView* headroom_view() const { return headroom_; }
  SustainView* sustain_view() const { return sustain_; }
  LensTab* lens_tab() const { return lens_; }  // the lead feeds it a capture: lens_tab()->set_fisheye(bgr, name)
  const Workspace* workspace() const { return workspace_.get(); }
  QUndoStack* edits() const { return edits_; }  // Edit > Undo's steps (workspace edits)
  // Something the user did that the workspace does not hold yet (a lens tuned and not saved), or an untitled
  // workspace (deleted when it closes) holding the user's imports, runs or edits.
  bool has_unsaved_changes() const;
  // Asks about it (Save / Discard / Cancel) and saves on Save; false on Cancel. Quitting and opening another
  // workspace go through here. Tests answer in place of the message box.
  bool settle_unsaved_changes();
  void set_unsaved_prompt(std::function<int(const QString& text)> prompt) { unsaved_prompt_ = std::move(prompt); }
  // A power log's platform and supply voltage (or borrowed voltage channel), one undo step each
  // (main_window_logs.cpp; the tree's "Platform…" and "Supply voltage…" ask, then call these).
  void set_log_platform(std::int64_t trace_id, const QString& platform);
  void set_log_voltage(std::int64_t trace_id, const LogVoltageChoice& choice);
  // Answers, in place of the dialog, which platform an imported log without one belongs to (tests).
  void set_platform_prompt(LogPlatformChooser prompt) { platform_prompt_ = std::move(prompt); }
  // The Lens tab's "Save lens for this frame / camera": one undo step in Edit > Undo.
  void save_tuned_lens(bool for_camera);

 protected:
  void dragEnterEvent(QDragEnterEvent* event) override;
  void dropEvent(QDropEvent* event) override;
  void closeEvent(QCloseEvent* event) override;
  void show_source(const PlatformRow& row, const QString& column);

 private:
  void create_actions();          // main_window_menus.cpp
  void compare_with_workspace();  // main_window_menus.cpp
  void show_help();               // main_window_menus.cpp (F1)
  // main_window_layout.cpp
  QSize first_start_size() const;  // 1400x900, or less where the screen is smaller
  void restore_layout();
  void clamp_to_screen();  // the window inside the available area of its screen
  void save_layout() const;
  // main_window_export.cpp
  void export_current_figure();
  void reproduce_paper_figures();
  void export_report();
  QStringList report_decision_lines() const;
  FigureData figure_data() const;
  // main_window_frames.cpp
  void connect_lens_and_frames();
  void feed_lens_tab();
  // main_window_logs.cpp
  QStringList known_platforms() const;
  QString choose_log_platform(const QString& log, const QString& path, const QString& guess,
                              const QStringList& platforms);
  void ask_log_voltage(const TreeItemRef& log);
  void ask_log_platform(const TreeItemRef& log);
  void tune_frame(std::int64_t frame_id);  // the Lens tab tunes this workspace frame
  // A .raw file among `paths` (or in their folders) without a sidecar: asks its geometry; nullopt when none or
  // cancelled (such files then fail with an error that says how to give the geometry).
  std::optional<RawFrameOptions> ask_raw_geometry(const QStringList& paths);
  QString export_folder() const;
  void reload();
  // main_window_edit.cpp: the tree's rename/remove, one undo step each
  std::vector<WorkspaceItem> workspace_items() const;
  void rename_item(const TreeItemRef& item);
  void remove_item(const TreeItemRef& item);
  void set_device_color(const TreeItemRef& device, int color_index);
  // An edit's first run, before push_edit records it: what it throws is reported (report_edit_error) and it returns
  // false, so that a failed edit leaves no step to undo.
  bool try_edit(const std::function<void()>& redo);
  // One step of Edit > Undo; `refresh` brings the views up to date after it (default: reload()).
  void push_edit(const QString& text, std::function<void()> redo, std::function<void()> undo,
                 std::function<void()> refresh = {});
  // main_window_decision.cpp: what the user sets that changes the decision, kept in the workspace (issue #43.2, .4)
  void store_decision(const StoredDecision& decision);
  void choose_power_log(const QString& platform, qint64 trace_id);
  void show_log_choices(const SharedTraces& traces);
  void report_edit_error(const QString& message);
  void update_edit_actions();
  void show_traces(const SharedTraces& traces);  // the views that draw or use power logs
  std::vector<PipelineRun> pipeline_runs() const;
  void refresh_views();
  void show_import_report(const ImportReport& report);

 public:
  // The last import's warnings, listed (nullptr before an import with warnings).
  ImportWarningsDialog* import_warnings() const { return import_warnings_; }

 private:
  void save_as();
  // File > Save (Ctrl+S): the workspace file holds every edit the moment it is made (one SQLite transaction each), so
  // Save keeps an untitled workspace under a name (Save as) and otherwise says that nothing is waiting; a lens tuned
  // in the Lens tab and not yet saved is saved for its frame first, as the quit question's Save does.
  void save();
  void update_title();  // and the status bar's note on how edits are kept
  void show_live_run(const FlopsRun& run);
  // What a panel measured here goes home (main_window_home.cpp): into the open workspace (an untitled one opened
  // first if none is), then reloaded; a refusal (the same measurement stored already, a full disk) is shown in a
  // box titled `failure_title`. Every measurement made here is stored through it (a robot's job: store_remote_run).
  void store_home(const HomeBatch& home, const QString& failure_title);
  void store_measured_runs(const std::vector<FlopsRun>& runs, bool cancelled);  // the Kernel Runner's sweep
  // A robot's job came home: its results imported with their provenance under `platform` (main_window_remote.cpp).
  void store_remote_run(RemoteRun* run, const QString& platform);
  void show_damage();     // the read-only banner, after every (re)load
  void remove_damaged();  // the banner's button: asks, then removes every damaged item

  std::unique_ptr<Workspace> workspace_;
  std::vector<StoredRun> runs_;
  std::map<std::int64_t, std::string> run_labels_;  // the user's names of runs (store/run_label_store.h)
  std::vector<StoredRun> live_;                     // a sweep in progress, drawn before it is stored
  std::unique_ptr<QTemporaryDir> untitled_dir_;     // holds an untitled workspace until "Save As"
  // The user imported, measured or edited something since this workspace was opened. It matters only for an
  // untitled workspace, whose temporary folder is deleted with it.
  bool work_since_open_ = false;
  bool untitled_work_at_risk() const { return untitled_dir_ && work_since_open_; }
  WorkspaceTree* tree_;
  QSplitter* flops_split_ = nullptr;  // the FLOPS tab: plot over the peak table
  QByteArray default_state_, default_split_;
  FlopsPlot* plot_;
  PeakTableView* peaks_;
  ImportController* importer_;
  RecentFiles* recent_ = nullptr;
  KernelRunner* runner_;
  PowerView* power_;
  PlatformView* platforms_;
  RooflineView* roofline_;
  FramesView* frames_;
  PipelineView* pipeline_;
  EfficiencyView* efficiency_;
  BatteryView* battery_;
  DamageBanner* damage_banner_ = nullptr;
  QToolBar* damage_bar_ = nullptr;  // holds the banner above the views; hidden while nothing is damaged
  LensTab* lens_ = nullptr;
  HeadroomView* headroom_ = nullptr;
  SustainView* sustain_ = nullptr;
  std::vector<LogChoiceBar*> log_choices_;  // above Efficiency, Battery and Platforms: each platform's power log
  QLabel* status_label_ = nullptr;          // workspace path and run counts
  ImportWarningsDialog* import_warnings_ = nullptr;  // not modal; created on the first import with warnings
  QLabel* save_state_ = nullptr;  // "Edits are written at once to …" / "Untitled: …" (permanent, right)
  QUndoStack* edits_ = nullptr;   // renames and removals in the workspace tree; cleared when another opens
  QAction* undo_edit_ = nullptr;
  QAction* redo_edit_ = nullptr;
  PowerTraceLoader* trace_loader_ = nullptr;           // samples of long power logs, loaded after the window shows
  std::function<int(const QString&)> unsaved_prompt_;  // null: a QMessageBox asks
  LogPlatformChooser platform_prompt_;                 // null: a dialog asks
};

}  // namespace bs::ui
