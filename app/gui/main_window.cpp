// SPDX-License-Identifier: GPL-3.0-or-later
#include "main_window.h"

#include "analysis/peaks/peak_ceilings.h"
#include "vision/lens_tab.h"

#include <qcustomplot.h>
#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QPushButton>
#include <QSplitter>
#include <QStatusBar>
#include <algorithm>

#include <QTabWidget>
#include <QUndoStack>
#include <QVBoxLayout>
#include "analysis/peaks/flops.h"
#include "analysis/peaks/foreign_sweeps.h"
#include "device_palette.h"
#include "headroom/headroom_import.h"
#include "headroom/headroom_run_panel.h"
#include "headroom/headroom_view.h"
#include "kernels/kernel_runner.h"
#include "kernels/measured_set_home.h"
#include "peaks/flops_plot.h"
#include "peaks/peak_table.h"
#include "peaks/roofline_view.h"
#include "platform/efficiency_view.h"
#include "platform/platform_view.h"
#include "power/battery_view.h"
#include "power/log_choice_bar.h"
#include "power/power_trace_loader.h"
#include "power/power_view.h"
#include "remote/remote_run.h"
#include "report/run_names.h"
#include "store/run_label_store.h"
#include "sustain/sustain_import.h"
#include "sustain/sustain_run_panel.h"
#include "sustain/sustain_view.h"
#include "vision/frames_view.h"
#include "vision/pipeline_home.h"
#include "vision/pipeline_measure_panel.h"
#include "vision/pipeline_view.h"
#include "workspace/import_controller.h"
#include "workspace/import_warnings_dialog.h"
#include "workspace/recent_files.h"
#include "workspace/workspace_tree.h"

namespace bs::ui {
namespace {
constexpr std::int64_t kFirstForeignSweepId = -1'000'000;
}  // namespace

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent),
      tree_(new WorkspaceTree(this)),
      plot_(new FlopsPlot(this)),
      peaks_(new PeakTableView(this)),
      importer_(new ImportController(this)),
      runner_(new KernelRunner(this)),
      power_(new PowerView(this)),
      platforms_(new PlatformView(this)),
      roofline_(new RooflineView(this)),
      frames_(new FramesView(this)),
      pipeline_(new PipelineView(this)),
      efficiency_(new EfficiencyView(this)),
      battery_(new BatteryView(this)) {
  setAcceptDrops(true);
  auto* views = new QTabWidget(this);
  // Tabs in the order a lab reads its evidence: compute, power, what both mean per platform, then vision.
  const auto tab = [views](QWidget* w, const QString& name, const QString& tip) {
    views->setTabToolTip(views->addTab(w, name), tip);
  };
  // The peak table belongs to the FLOPS view (it was a dock under every tab, a quarter of the window on views that
  // have nothing to do with it): the tab is the plot over its table, split as the user leaves it.
  flops_split_ = new QSplitter(Qt::Vertical, this);
  flops_split_->setObjectName(QStringLiteral("flopsSplit"));
  flops_split_->addWidget(plot_);
  flops_split_->addWidget(peaks_);
  flops_split_->setStretchFactor(0, 3);
  flops_split_->setStretchFactor(1, 1);
  flops_split_->setChildrenCollapsible(false);
  tab(flops_split_, tr("FLOPS"),
      tr("FLOPS against workers for the runs ticked in the workspace tree, with their peaks"));
  tab(power_, tr("Power"), tr("Current/power logs: traces, statistics over a selected range (the paper's Figure 4)"));
  // Efficiency, Battery and Platforms use one power log per platform: a bar above each says which, and offers the
  // others where a platform has several (issue #43.4).
  const auto with_log_choice = [this](QWidget* view) {
    auto* page = new QWidget(this);
    auto* layout = new QVBoxLayout(page);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    auto* bar = new LogChoiceBar(page);
    bar->setContentsMargins(6, 4, 6, 0);
    connect(bar, &LogChoiceBar::log_chosen, this, &MainWindow::choose_power_log);
    log_choices_.push_back(bar);
    layout->addWidget(bar);
    layout->addWidget(view, 1);
    return page;
  };
  tab(with_log_choice(efficiency_), tr("Efficiency"), tr("GFLOPS/W per platform: the paper's and at mean power"));
  tab(with_log_choice(battery_), tr("Battery"), tr("Battery life per platform, presets saved in the workspace"));
  tab(with_log_choice(platforms_), tr("Platforms"),
      tr("One row per platform, and which one to pick under your constraints (kept in the workspace)"));
  connect(platforms_, &PlatformView::decision_edited, this, &MainWindow::store_decision);
  connect(platforms_, &PlatformView::source_requested, this, &MainWindow::show_source);
  // One battery for both tabs: the Platforms tab offers (and by default uses) what the Battery tab shows.
  connect(battery_, &BatteryView::setup_changed, this,
          [this] { platforms_->set_battery_tab_setup(battery_->setup(), battery_->modified()); });
  connect(battery_, &BatteryView::setup_edited, platforms_, &PlatformView::battery_tab_edited);
  tab(roofline_, tr("Roofline"), tr("Compute and memory ceilings per device, with the kernels placed on them"));
  tab(pipeline_, tr("Pipeline"), tr("Vision pipeline stage times per platform (demosaic + reprojection, detection)"));
  connect(pipeline_, &PipelineView::run_measured, this, [this](const PipelineRun& run) {
    // With "Record power" on, the trace goes into the same import as the run.
    store_home(pipeline_home(run, pipeline_->measure_panel()->take_power_trace(), "Pipeline tab"),
               tr("Cannot store the run"));
  });
  // Whether the control loop keeps its deadlines while the vision runs: the probe idle and beside each load.
  headroom_ = new HeadroomView(this);
  tab(headroom_, tr("Headroom"),
      tr("Control-loop headroom: a periodic loop's wake-up latency and deadline misses, idle and beside the vision "
         "pipeline, the detector, the kernels or a command"));
  connect(headroom_->run_panel(), &HeadroomRunPanel::measured, this, [this](const headroom::RunOutput& out) {
    store_home(headroom::headroom_import(out.measurement, out.power, "Headroom tab"),
               tr("Cannot store the measurement"));
  });
  // Measured on a robot (issue #44): imported with the robot's provenance as the Kernel Runner's remote jobs are.
  connect(headroom_->run_panel(), &HeadroomRunPanel::remote_finished, this, &MainWindow::store_remote_run);
  connect(pipeline_->measure_panel(), &PipelineMeasurePanel::remote_finished, this, &MainWindow::store_remote_run);
  // Whether the speed holds for a whole match: a load for minutes with its clocks and temperatures (#53).
  sustain_ = new SustainView(this);
  tab(sustain_, tr("Sustained"),
      tr("Sustained performance: a load's rate, the clocks, temperatures and power on one time axis; stability and "
         "throttling"));
  connect(sustain_->run_panel(), &SustainRunPanel::measured, this, [this](const sustain::RunOutput& out) {
    store_home(sustain::sustain_import(out.run, out.power, "Sustained tab"), tr("Cannot store the sustained run"));
  });
  connect(sustain_->run_panel(), &SustainRunPanel::robot_finished, this, &MainWindow::store_remote_run);
  tab(frames_, tr("Frames"), tr("Camera frames: raw mosaic, demosaiced and reprojected (the paper's Figure 3)"));
  lens_ = new LensTab(this);
  tab(lens_, tr("Lens"), tr("Reprojection tuner (lens model, view, masks, auto-calibration) beside the lens in 3D"));
  connect_lens_and_frames();
  setCentralWidget(views);
  auto* tree_dock = new QDockWidget(tr("Workspace"), this);
  tree_dock->setObjectName("workspaceDock");
  tree_dock->setWidget(tree_);
  addDockWidget(Qt::LeftDockWidgetArea, tree_dock);
  auto* runner_dock = new QDockWidget(tr("Kernel Runner"), this);
  runner_dock->setObjectName("kernelRunnerDock");
  runner_dock->setWidget(runner_);
  // The runner shares the left column with the workspace tree (as a tab) so the plot keeps the window's width;
  // it comes to the front when a sweep starts.
  addDockWidget(Qt::LeftDockWidgetArea, runner_dock);
  tabifyDockWidget(tree_dock, runner_dock);
  tree_dock->raise();
  resizeDocks({tree_dock}, {340}, Qt::Horizontal);
  connect(runner_, &KernelRunner::started, runner_dock, &QDockWidget::raise);
  // Above the views, out of the tab widget's way: shown only while the workspace holds damaged items.
  damage_banner_ = new DamageBanner(this);
  damage_bar_ = new QToolBar(tr("Damaged items"), this);
  damage_bar_->setObjectName(QStringLiteral("damageBar"));
  damage_bar_->setMovable(false);
  damage_bar_->setFloatable(false);
  damage_bar_->toggleViewAction()->setVisible(false);
  damage_bar_->addWidget(damage_banner_);
  addToolBar(Qt::TopToolBarArea, damage_bar_);
  damage_bar_->hide();
  connect(damage_banner_, &DamageBanner::remove_requested, this, &MainWindow::remove_damaged);
  resize(first_start_size());
  default_state_ = saveState();        // View > Reset layout returns here
  flops_split_->setSizes({560, 300});  // the paper's 13 peak rows without scrolling at the default size
  default_split_ = flops_split_->saveState();
  edits_ = new QUndoStack(this);
  connect(tree_, &WorkspaceTree::rename_requested, this, &MainWindow::rename_item);
  connect(tree_, &WorkspaceTree::remove_requested, this, &MainWindow::remove_item);
  connect(tree_, &WorkspaceTree::color_requested, this, &MainWindow::set_device_color);
  connect(tree_, &WorkspaceTree::supply_voltage_requested, this, &MainWindow::ask_log_voltage);
  connect(tree_, &WorkspaceTree::platform_requested, this, &MainWindow::ask_log_platform);
  importer_->set_log_platform_chooser(
      [this](const QString& log, const QString& path, const QString& guess, const QStringList& platforms) {
        return choose_log_platform(log, path, guess, platforms);
      });
  connect(views, &QTabWidget::currentChanged, this, &MainWindow::update_edit_actions);
  create_actions();
  connect(tree_, &WorkspaceTree::visibility_changed, this, &MainWindow::refresh_views);
  connect(importer_, &ImportController::finished, this, [this](const ImportReport& r) {
    if (r.imported > 0) work_since_open_ = true;
    reload();
    show_import_report(r);
  });
  connect(runner_, &KernelRunner::live_run, this, &MainWindow::show_live_run);
  connect(runner_, &KernelRunner::finished, this, &MainWindow::store_measured_runs);
  connect(runner_, &KernelRunner::remote_finished, this, &MainWindow::store_remote_run);
  connect(runner_, &KernelRunner::ceilings_measured, this, [this](const ResultSet& set) {
    store_home(measured_set_home(set, "Kernel Runner: Measure ceilings"), tr("Cannot store the ceilings"));
    statusBar()->showMessage(tr("Stored the empirical ceilings of %1").arg(QString::fromStdString(set.device)), 10000);
  });
  connect(runner_, &KernelRunner::failed, this, [this](const QString& message) {
    live_.clear();
    refresh_views();
    QMessageBox::warning(this, tr("Kernel run failed"), message);
  });
  status_label_ = new QLabel(this);
  statusBar()->addWidget(status_label_, 1);  // hidden while a temporary message shows
  save_state_ = new QLabel(this);
  save_state_->setObjectName(QStringLiteral("save_state"));
  statusBar()->addPermanentWidget(save_state_);
  trace_loader_ = new PowerTraceLoader(this);
  statusBar()->addPermanentWidget(trace_loader_);
  connect(trace_loader_, &PowerTraceLoader::loaded, this, &MainWindow::show_traces);
  connect(trace_loader_, &PowerTraceLoader::failed, this,
          [this](const QString& message) { statusBar()->showMessage(message, 15000); });
  restore_layout();
  update_title();
}

MainWindow::~MainWindow() {
  // The undo stack is deleted with the window's children, after the tabs: it must not report to them on its way.
  edits_->disconnect();
}

bool MainWindow::open_workspace(const QString& path) {
  if (workspace_ && !settle_unsaved_changes()) return false;
  try {
    auto ws = std::make_unique<Workspace>(path.toStdString());
    edits_->clear();  // its steps act on the workspace being closed
    workspace_ = std::move(ws);
    lens_->clear_frame();  // its frame ids are the closed workspace's
  } catch (const WorkspaceError& e) {
    QMessageBox::critical(this, tr("Cannot open workspace"), QString::fromUtf8(e.what()));
    return false;
  }
  if (!untitled_dir_ || !path.startsWith(untitled_dir_->path())) {
    untitled_dir_.reset();
    recent_->add(path);
  }
  work_since_open_ = false;
  reload();
  return true;
}

void MainWindow::new_untitled_workspace() {
  auto dir = std::make_unique<QTemporaryDir>();
  const QString path = dir->filePath("untitled.bsw");
  untitled_dir_ = std::move(dir);
  open_workspace(path);
}

void MainWindow::import_paths(const QStringList& paths) {
  if (!workspace_) new_untitled_workspace();
  importer_->set_raw_geometry(ask_raw_geometry(paths));
  importer_->start(QString::fromStdString(workspace_->path()), paths);
}

void MainWindow::import_paths_now(const QStringList& paths) {
  if (!workspace_) new_untitled_workspace();
  // Without a prompt (the GUI's command line) a log without a platform takes the guess, which the status says.
  LogPlatformChooser ask;
  if (platform_prompt_) ask = platform_prompt_;
  const ImportReport report = ImportController::import_now(
      QString::fromStdString(workspace_->path()), paths, CancelToken{}, {}, FrameStorage::Reference, std::nullopt, ask);
  reload();
  if (!report.failures.isEmpty()) show_import_report(report);
}

void MainWindow::show_import_report(const ImportReport& r) {
  // Few skips or failures: their reasons are in the message itself; many: counted, and listed under Details.
  const ImportMessage m = import_message(r);
  // Warnings (a last line that may be cut, a board total that is a lower bound) stay longer than a plain count.
  statusBar()->showMessage(
      r.failures.isEmpty() && !m.lines.isEmpty() ? m.headline + " — " + m.lines.join("; ") : m.headline,
      r.warnings.isEmpty() ? 10000 : 60000);
  // Warnings are listed, each whole, in a window that does not block the views they explain (issue #51).
  if (!r.warnings.isEmpty()) {
    if (!import_warnings_) import_warnings_ = new ImportWarningsDialog(this);
    import_warnings_->set_report(r);
    import_warnings_->show();
    import_warnings_->raise();
  }
  if (r.failures.isEmpty()) return;
  const QString text =
      tr("%n file(s) could not be imported; nothing of them was stored.", nullptr, static_cast<int>(r.failures.size()));
  QMessageBox box(QMessageBox::Warning, tr("Import problems"),
                  m.lines.isEmpty() ? text + "\n" + m.headline : text + "\n\n" + m.lines.join('\n'), QMessageBox::Ok,
                  this);
  if (!m.details.isEmpty()) box.setDetailedText(m.details);
  box.exec();
}

void MainWindow::reload() {
  runs_ = workspace_ ? workspace_->runs() : std::vector<StoredRun>{};
  // FLOPS sweeps inside stored Google Benchmark results (analysis/foreign_sweeps.h) are runs in every view. They
  // are derived, not stored, so their ids are negative and far below those of the sweep running now (-1, -2, ...);
  // result sets come in id order, so a later import does not shift the ids of earlier sweeps.
  if (workspace_) {
    std::int64_t id = kFirstForeignSweepId;
    for (const StoredResultSet& s : workspace_->result_sets())
      for (FlopsRun& run : foreign_sweeps(s.set))
        runs_.push_back(StoredRun{{{id--, s.import_id}, s.device_id, s.color_index}, std::move(run)});
  }
  run_labels_ = workspace_ ? run_labels(*workspace_, runs_) : std::map<std::int64_t, std::string>{};
  tree_->set_runs(runs_, run_labels_);
  tree_->set_items(workspace_items());
  std::vector<FlopsRun> all;
  for (const StoredRun& r : runs_) all.push_back(r.run);
  power_->set_workspace(workspace_.get());  // saved phases go there; the battery pack comes from it
  battery_->set_workspace(workspace_.get());
  platforms_->set_workspace(workspace_.get());
  // Power traces: summaries now, samples now for a small workspace, else on a worker thread (PowerTraceLoader)
  // while the window already answers; the trace views are filled when they arrive (show_traces).
  std::vector<StoredPowerTrace> traces =
      workspace_ ? workspace_->power_trace_summaries() : std::vector<StoredPowerTrace>{};
  // Each platform's chosen log first: the comparisons use a platform's first log (store/decision_store.h).
  if (workspace_) order_chosen_logs_first(*workspace_, traces);
  if (workspace_ && PowerTraceLoader::sample_count(traces) > PowerTraceLoader::kBackgroundSamples) {
    trace_loader_->start(workspace_->path(), std::move(traces));
    show_traces(share_traces(std::vector<PowerTrace>{}));
  } else {
    trace_loader_->abandon();
    if (workspace_) PowerTraceLoader::load_now(*workspace_, traces);
    show_traces(share_traces(std::move(traces)));
  }
  std::vector<DnnRun> inference_runs;
  if (workspace_)
    for (auto& d : workspace_->dnn_runs()) inference_runs.push_back(std::move(d.run));
  platforms_->set_inference_runs(inference_runs);
  pipeline_->set_inference_runs(std::move(inference_runs));
  std::vector<ResultSet> sets;
  std::map<std::pair<std::string, std::string>, int> device_colors;
  for (const StoredRun& r : runs_) device_colors[{r.run.platform, r.run.device}] = r.color_index;
  if (workspace_)
    for (const StoredResultSet& s : workspace_->result_sets()) {
      device_colors[{s.set.platform, s.set.device}] = s.color_index;
      sets.push_back(s.set);
    }
  platforms_->set_result_sets(sets);  // imported MLPerf LoadGen results are own candidates
  roofline_->set_data(all, std::move(sets), std::move(device_colors), pipeline_runs());
  frames_->set_workspace(workspace_.get());
  {
    std::vector<StoredHeadroom> stored =
        workspace_ ? workspace_->headroom_measurements() : std::vector<StoredHeadroom>{};
    std::vector<headroom::HeadroomMeasurement> measurements;
    for (const StoredHeadroom& s : stored) measurements.push_back(s.measurement);
    platforms_->set_headroom(std::move(measurements));  // the Platforms tab's control-loop requirement
    headroom_->set_measurements(std::move(stored));
  }
  {
    std::vector<StoredSustainRun> stored = workspace_ ? workspace_->sustain_runs() : std::vector<StoredSustainRun>{};
    std::vector<SustainRun> records;
    for (const StoredSustainRun& s : stored) records.push_back(s.run);
    platforms_->set_sustained(std::move(records));  // the Platforms tab's sustained requirement
    sustain_->set_records(std::move(stored));
  }
  feed_lens_tab();
  refresh_views();
  show_damage();
  update_title();
}

std::vector<PipelineRun> MainWindow::pipeline_runs() const {
  std::vector<PipelineRun> pipelines;
  if (workspace_)
    for (auto& p : workspace_->pipeline_runs()) pipelines.push_back(std::move(p.run));
  return pipelines;
}

void MainWindow::show_traces(const SharedTraces& traces) {
  std::vector<FlopsRun> all;
  std::vector<std::pair<std::string, int>> platform_colors;
  for (const StoredRun& r : runs_) {
    all.push_back(r.run);
    platform_colors.emplace_back(r.run.platform, r.color_index);
  }
  std::vector<std::string> trace_platforms;
  for (const PowerTrace& t : traces->traces) trace_platforms.push_back(t.platform);
  platform_colors = platform_color_indices(platform_colors, std::move(trace_platforms));  // one per platform
  // One set of samples for every view (a 100-million-sample log is 1.6 GB): shared, never copied.
  power_->set_data(traces, bs::peak_table(all), platform_colors);
  efficiency_->set_data(all, traces->traces);
  battery_->set_data(traces, platform_colors);
  std::vector<PipelineRun> pipelines = pipeline_runs();
  pipeline_->set_data(pipelines);
  platforms_->set_data(std::move(all), traces, std::move(pipelines));
  show_log_choices(traces);
}

void MainWindow::show_source(const PlatformRow& row, const QString& column) {
  // A peak cell leads to its run in the workspace tree; a power cell to the Power tab.
  const std::optional<PeakRow>& peak = column == column::kCpuPeak ? row.cpu : row.gpu;
  if ((column == column::kGpuPeak || column == column::kCpuPeak) && peak) {
    for (const StoredRun& r : runs_)
      if (r.run.platform == peak->platform && r.run.device == peak->device && r.run.backend == peak->backend &&
          r.run.variant == peak->variant && r.run.dims == peak->dims && tree_->select_run(r.id)) {
        if (auto* dock = findChild<QDockWidget*>("workspaceDock")) dock->raise();
        statusBar()->showMessage(tr("%1: %2").arg(QString::fromStdString(row.platform),
                                                  QString::fromStdString(row.sources.at(column.toStdString()).how)),
                                 10000);
        return;
      }
  }
  const auto it = row.sources.find(column.toStdString());
  if (column == column::kPower) static_cast<QTabWidget*>(centralWidget())->setCurrentWidget(power_);
  statusBar()->showMessage(it == row.sources.end() ? tr("No source recorded for this cell")
                                                   : tr("%1 — from %2")
                                                         .arg(QString::fromStdString(it->second.how),
                                                              QString::fromStdString(it->second.source_file)),
                           10000);
}

void MainWindow::refresh_views() {
  const QSet<qint64> visible = tree_->visible_runs();
  std::vector<const StoredRun*> shown;
  std::vector<FlopsRun> peak_input;
  std::vector<int> colors;
  for (const StoredRun& r : runs_) {
    if (!visible.contains(r.id)) continue;
    shown.push_back(&r);
    peak_input.push_back(r.run);
    colors.push_back(r.color_index);
  }
  for (const StoredRun& r : live_) {
    shown.push_back(&r);
    peak_input.push_back(r.run);
    colors.push_back(r.color_index);
  }
  plot_->set_runs(shown, run_labels_);
  // Each row against its device's empirical ceiling (result sets stored by Measure ceilings); a peak above the
  // computed peak is flagged even without one.
  std::vector<PeakRow> peak_rows = bs::peak_table(peak_input);
  std::vector<ResultSet> sets;
  if (workspace_)
    for (const StoredResultSet& s : workspace_->result_sets()) sets.push_back(s.set);
  apply_empirical_ceilings(peak_rows, sets);
  // The Run column: what tells a run from others of the same device, backend and D (its F2 label first).
  std::vector<RunIdentity> identities;
  for (const StoredRun* r : shown) {
    const auto label = run_labels_.find(r->id);
    identities.push_back(run_identity(r->run,
                                      r->run.platform + '\x1f' + r->run.device + '\x1f' + r->run.backend + '\x1f' +
                                          r->run.variant + '\x1f' + std::to_string(r->run.dims),
                                      label == run_labels_.end() ? std::string() : label->second));
  }
  std::vector<int> row_colors;  // per row (runs without a peak have no row)
  for (const PeakRow& row : peak_rows) row_colors.push_back(colors[row.run_index]);
  peaks_->peak_model()->set_rows(std::move(peak_rows), std::move(row_colors), distinguishing_parts(identities));
  // A permanent label: import summaries and action tips are temporary messages and must not erase it.
  status_label_->setText(tr("%1 — %2 of %3 runs shown%4")
                             .arg(workspace_ ? QString::fromStdString(workspace_->path()) : tr("no workspace"))
                             .arg(shown.size() - live_.size())
                             .arg(runs_.size())
                             .arg(live_.empty() ? QString() : tr(", plus the sweep running now")));
}

void MainWindow::show_live_run(const FlopsRun& run) {
  // The device keeps the colour it has in the workspace; a new device gets the next free one.
  int color = workspace_ ? static_cast<int>(workspace_->devices().size()) : 0;
  if (workspace_)
    for (const DeviceRecord& d : workspace_->devices())
      if (d.platform == run.platform && d.device == run.device) color = d.color_index;
  auto it = std::find_if(live_.begin(), live_.end(), [&](const StoredRun& s) { return s.run.dims == run.dims; });
  if (it == live_.end())
    it = live_.insert(live_.end(), StoredRun{{{-1 - static_cast<qint64>(live_.size()), 0}, 0, color}, {}});
  it->run = run;
  refresh_views();
}

void MainWindow::save_as() {
  if (!workspace_) return;
  QString path = QFileDialog::getSaveFileName(this, tr("Save workspace as"), {}, tr("BenchScope workspace (*.bsw)"));
  if (path.isEmpty()) return;
  if (!path.endsWith(".bsw")) path += ".bsw";
  try {
    workspace_->save_as(path.toStdString());
  } catch (const WorkspaceError& e) {
    QMessageBox::critical(this, tr("Cannot save workspace"), QString::fromUtf8(e.what()));
    return;
  }
  work_since_open_ = false;  // saved under its name: nothing of it is lost when it closes
  open_workspace(path);
}

void MainWindow::save() {
  if (!workspace_) return;
  if (lens_ && lens_->has_unsaved_lens()) save_tuned_lens(false);
  if (untitled_dir_) {
    save_as();
    return;
  }
  statusBar()->showMessage(tr("Nothing waits to be saved: every import, run and edit is already written to %1")
                               .arg(QString::fromStdString(workspace_->path())),
                           10000);
}

void MainWindow::show_damage() {
  const bool damaged = workspace_ && !workspace_->damage().empty();
  damage_banner_->set_damage(damaged ? workspace_->damage() : std::vector<WorkspaceDamage>{});
  damage_bar_->setVisible(damaged);
}

void MainWindow::remove_damaged() {
  if (!workspace_ || workspace_->damage().empty()) return;
  QMessageBox box(QMessageBox::Warning, tr("Remove damaged items"),
                  tr("Remove the %n damaged item(s) from %1? Each goes with what belongs to it (a run with its "
                     "timings, a power log with its samples). This cannot be undone.",
                     nullptr, static_cast<int>(workspace_->damage().size()))
                      .arg(QString::fromStdString(workspace_->path())),
                  QMessageBox::Cancel, this);
  box.setDetailedText(damage_list(workspace_->damage()));
  QPushButton* remove = box.addButton(tr("Remove"), QMessageBox::DestructiveRole);
  box.exec();
  if (box.clickedButton() != remove) return;
  try {
    workspace_->remove_damaged();
  } catch (const WorkspaceError& e) {
    QMessageBox::critical(this, tr("Cannot remove the damaged items"), QString::fromUtf8(e.what()));
  }
  edits_->clear();  // undo steps may name what was removed
  reload();
}

void MainWindow::update_title() {
  const QString name = !workspace_     ? tr("no workspace")
                       : untitled_dir_ ? tr("untitled")
                                       : QFileInfo(QString::fromStdString(workspace_->path())).fileName();
  const bool read_only = workspace_ && workspace_->read_only();
  setWindowTitle(read_only ? tr("BenchScope — %1 (read-only)").arg(name) : tr("BenchScope — %1").arg(name));
  // How edits are kept, in sight all the time: a person looking for File > Save learns there is nothing to press.
  if (!workspace_) {
    save_state_->clear();
    save_state_->setToolTip({});
  } else if (read_only) {
    save_state_->setText(tr("Read-only: nothing is written"));
    save_state_->setToolTip(
        tr("The workspace has damaged items (see the banner); it is opened read-only until they "
           "are removed"));
  } else if (untitled_dir_) {
    save_state_->setText(tr("Untitled: Ctrl+S keeps it under a name"));
    save_state_->setToolTip(
        tr("An untitled workspace lives in a temporary folder that is deleted when it closes. "
           "Save (Ctrl+S) writes it to a file of your choice; from then on every edit is "
           "written to that file at once."));
  } else {
    save_state_->setText(tr("Edits are written at once to %1").arg(name));
    save_state_->setToolTip(tr("%1\nEvery import, measured run and edit is written into the workspace file the "
                               "moment it is made (one transaction each): there is nothing to save, and Edit > "
                               "Undo takes an edit back. Save as (Ctrl+Shift+S) continues in a copy.")
                                .arg(QString::fromStdString(workspace_->path())));
  }
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
  if (event->mimeData()->hasUrls()) event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event) {
  QStringList paths;
  for (const QUrl& url : event->mimeData()->urls())
    if (url.isLocalFile()) paths << url.toLocalFile();
  if (paths.size() == 1 && paths[0].endsWith(".bsw")) {
    open_workspace(paths[0]);
  } else if (!paths.isEmpty()) {
    import_paths(paths);
  }
  event->acceptProposedAction();
}

void MainWindow::closeEvent(QCloseEvent* event) {
  if (importer_->busy()) {
    QMessageBox::information(this, tr("Import running"), tr("Cancel the running import before quitting."));
    event->ignore();
    return;
  }
  if (!settle_unsaved_changes()) {
    event->ignore();
    return;
  }
  save_layout();
  event->accept();
}

}  // namespace bs::ui
