// SPDX-License-Identifier: GPL-3.0-or-later
// Results measured on a robot (issue #44): a remote job of the Kernel Runner, the Headroom or the Pipeline tab came
// home; its result workspace is imported in one transaction, every item stamped with the robot's identity and the
// command run there, under the platform name the user confirmed or renamed.
#include <QMessageBox>
#include <QStatusBar>

#include "kernels/kernel_runner.h"
#include "main_window.h"
#include "remote/job_agent.h"
#include "remote/job_client.h"
#include "remote/job_import.h"
#include "remote/remote_run.h"
#include "remote/robots.h"
#include "store/workspace.h"

namespace bs::ui {

void MainWindow::store_remote_run(RemoteRun* run, const QString& platform) {
  live_.clear();
  const remote::RemoteJob& job = run->job();
  const QString host = QString::fromStdString(run->target().destination);
  // The robots list's entry, worded as the CLI words it (core/remote/robots.h).
  remote::RobotRun record = remote::robot_run_started(job.id, run->command());
  const auto remember = [&](const std::string& what) {
    record.outcome = remote::robot_run_outcome(job.status, what);
    try {
      remote::RobotList().record_run(run->target().destination, record);
    } catch (const std::exception&) {  // the robots list is a convenience; the import is what matters
    }
  };
  // Only the result workspace is imported; the robot's printed output (kept with the job) was shown as it came.
  if (remote::staged_file(job, remote::kJobResultFile).empty()) {
    remember("nothing to import");
    refresh_views();
    statusBar()->showMessage(tr("%1: job %2 %3 with nothing to import")
                                 .arg(host, QString::fromStdString(job.id), QString::fromStdString(job.status)),
                             15000);
    return;
  }
  if (!workspace_) new_untitled_workspace();
  try {
    const remote::RemoteOrigin origin = remote::origin_of(run->target(), job, run->robot(), run->command());
    const remote::JobImport imported = remote::bring_job_home(*workspace_, job.files, origin, platform.toStdString());
    work_since_open_ = true;
    remember("imported " + imported.summary() + " into " + workspace_->path());
    statusBar()->showMessage(tr("Imported %1 from %2 (%3, job %4) as platform '%5'%6")
                                 .arg(QString::fromStdString(imported.summary()), host,
                                      QString::fromStdString(origin.hostname), QString::fromStdString(job.id), platform,
                                      job.status == "cancelled" ? tr(" (cancelled: partial)") : QString()),
                             15000);
  } catch (const std::exception& e) {
    remember(std::string("not imported: ") + e.what());
    QMessageBox::critical(this, tr("Cannot store the robot's results"),
                          tr("%1 (job %2): %3\n\nThe workspace is unchanged; the robot keeps the job, and "
                             "`benchscope-cli remote %1 fetch %2` brings it again.")
                              .arg(host, QString::fromStdString(job.id), QString::fromUtf8(e.what())));
  }
  reload();
}

}  // namespace bs::ui
