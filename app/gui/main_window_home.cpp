// SPDX-License-Identifier: GPL-3.0-or-later
// What the tabs measure here goes home (#52's one way home): each measurement's batch comes from its kind's builder
// (flops_home, pipeline_home, measured_set_home, headroom_import, sustain_import), the same the CLI stores through,
// and is stored by bring_home in one place, so the window builds no batch and wraps no store call of its own.
#include <QMessageBox>
#include <QStatusBar>

#include "kernels/flops_home.h"
#include "kernels/kernel_runner.h"
#include "main_window.h"
#include "peaks/peak_table.h"
#include "store/home_batch.h"

namespace bs::ui {

void MainWindow::store_home(const HomeBatch& home, const QString& failure_title) {
  if (!workspace_) new_untitled_workspace();
  try {
    bring_home(*workspace_, home);
    work_since_open_ = true;
  } catch (const WorkspaceError& e) {
    QMessageBox::critical(this, failure_title, QString::fromUtf8(e.what()));
  }
  reload();
}

void MainWindow::store_measured_runs(const std::vector<FlopsRun>& runs, bool cancelled) {
  live_.clear();
  if (runs.empty()) {
    refresh_views();
    statusBar()->showMessage(tr("Kernel run cancelled before any point completed"), 10000);
    return;
  }
  // A power trace recorded beside the sweep goes into the same import.
  store_home(flops_home(runs, runner_->take_power_trace(), "Kernel Runner"), tr("Cannot store the run"));
  // The new run's peak row comes into view in the FLOPS tab's table, selected, wherever the table was scrolled.
  const FlopsRun& first = runs.front();
  peaks_->show_row(first.platform, first.device, first.backend, first.dims);
  statusBar()->showMessage(tr("Stored %n measured run(s)%1", nullptr, static_cast<int>(runs.size()))
                               .arg(cancelled ? tr(" (cancelled: partial)") : QString()),
                           10000);
}

}  // namespace bs::ui
