// SPDX-License-Identifier: GPL-3.0-or-later
#include "import_controller.h"

#include <QDir>
#include <QDirIterator>
#include <QFileInfo>
#include <QFutureWatcher>
#include <QPointer>
#include <QProgressDialog>
#include <QtConcurrent>

#include "importer.h"
#include "store/workspace.h"

namespace bs::ui {
namespace {

struct Candidate {
  QString path;
  bool from_folder;
};

QList<Candidate> expand(const QStringList& paths) {
  QList<Candidate> out;
  for (const QString& p : paths) {
    if (!QFileInfo(p).isDir()) {
      out.append({p, false});
      continue;
    }
    QStringList found;
    QDirIterator it(p, QDir::Files | QDir::NoDotAndDotDot, QDirIterator::Subdirectories);
    while (it.hasNext()) found << it.next();
    found.sort();
    for (const QString& f : found) out.append({f, true});
  }
  return out;
}

}  // namespace

ImportController::ImportController(QWidget* parent_window) : QObject(parent_window), window_(parent_window) {
  qRegisterMetaType<bs::ui::ImportReport>();
}

ImportReport ImportController::import_now(const QString& workspace_path, const QStringList& paths,
                                          const CancelToken& cancel,
                                          const std::function<void(int, int, const QString&)>& progress,
                                          FrameStorage frames, const std::optional<RawFrameOptions>& raw_geometry) {
  ImportReport report;
  const QList<Candidate> files = expand(paths);
  std::unique_ptr<Workspace> ws;
  for (int i = 0; i < files.size(); ++i) {
    const QString& path = files[i].path;
    if (progress) progress(i, static_cast<int>(files.size()), path);
    if (cancel.cancelled()) {
      report.cancelled = true;
      break;
    }
    try {
      const std::string p = path.toStdString();
      ImportBatch batch = import_file_with_raw_geometry(p, raw_geometry, cancel, "the geometry dialog");
      for (Frame& f : batch.frames) f.storage = frames;
      if (!ws) ws = std::make_unique<Workspace>(workspace_path.toStdString());
      ws->add_import(batch, file_content_hash(p), &cancel);
      ++report.imported;
    } catch (const ImportError& e) {
      const bool not_data = e.category() == ImportErrorCategory::UnknownFormat ||
                            e.category() == ImportErrorCategory::Binary;
      if (files[i].from_folder && not_data) report.skipped << QStringLiteral("%1: %2").arg(path, QString::fromStdString(e.reason()));
      else report.failures << QString::fromStdString(e.what());
    } catch (const WorkspaceError& e) {
      if (e.kind() == WorkspaceError::Kind::Constraint) report.skipped << QStringLiteral("%1: %2").arg(path, e.what());
      else report.failures << QString::fromUtf8(e.what());
    } catch (const Cancelled&) {
      report.cancelled = true;
      break;
    } catch (const std::exception& e) {
      report.failures << QStringLiteral("%1: %2").arg(path, QString::fromUtf8(e.what()));
    }
  }
  if (progress) progress(static_cast<int>(files.size()), static_cast<int>(files.size()), {});
  return report;
}

void ImportController::start(const QString& workspace_path, const QStringList& paths) {
  if (running_) return;
  running_ = true;
  auto cancel = std::make_shared<CancelToken>();
  auto* dialog = new QProgressDialog(tr("Importing…"), tr("Cancel"), 0, 0, window_);
  dialog->setWindowTitle(tr("Import"));
  dialog->setWindowModality(Qt::WindowModal);
  dialog->setMinimumDuration(300);
  dialog->setMinimumWidth(480);
  connect(dialog, &QProgressDialog::canceled, this, [cancel] { cancel->cancel(); });
  QPointer<QProgressDialog> guard(dialog);
  auto progress = [guard](int done, int total, const QString& file) {
    QMetaObject::invokeMethod(guard.data(), [guard, done, total, file] {
      if (!guard) return;
      guard->setMaximum(total);
      guard->setValue(done);
      guard->setLabelText(QObject::tr("File %1 of %2\n%3").arg(done + 1).arg(total).arg(QFileInfo(file).fileName()));
    }, Qt::QueuedConnection);
  };
  auto* watcher = new QFutureWatcher<ImportReport>(this);
  connect(watcher, &QFutureWatcher<ImportReport>::finished, this, [this, watcher, dialog] {
    const ImportReport report = watcher->result();
    dialog->deleteLater();
    watcher->deleteLater();
    running_ = false;
    emit finished(report);
  });
  watcher->setFuture(QtConcurrent::run([workspace_path, paths, cancel, progress, frames = frame_storage_,
                                        geometry = raw_geometry_] {
    return import_now(workspace_path, paths, *cancel, progress, frames, geometry);
  }));
}

}  // namespace bs::ui
