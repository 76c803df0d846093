// SPDX-License-Identifier: GPL-3.0-or-later
#include "workspace/import_controller.h"

#include <algorithm>
#include <atomic>
#include <memory>

#include <QFileInfo>
#include <QFutureWatcher>
#include <QPointer>
#include <QProgressDialog>
#include <QtConcurrent>

#include "workspace/import_service.h"

namespace bs::ui {
namespace {

constexpr int kFewProblems = 4;  // up to this many skips + failures are spelled out in the message itself

QString file_name(const std::string& path) { return QFileInfo(QString::fromStdString(path)).fileName(); }

// "already imported on 2026-11-20 (same content)", naming the earlier file when it had another name.
QString duplicate_reason(const FileOutcome& f) {
  const QString earlier = file_name(f.earlier_path);
  const QString as = earlier == file_name(f.path) ? QString() : QObject::tr(" as %1").arg(earlier);
  if (f.earlier_imported_at.empty()) return QObject::tr("same content as %1 in this import").arg(earlier);
  return QObject::tr("already imported on %1%2 (same content)")
      .arg(QString::fromStdString(f.earlier_imported_at.substr(0, 10)), as);
}

// "/long/path/cut.csv:5: ..." -> "cut.csv:5: ...": the message names the file as the user knows it.
QString short_warning(const std::string& warning, const std::string& path) {
  const QString w = QString::fromStdString(warning);
  return warning.rfind(path, 0) == 0 ? file_name(path) + w.mid(static_cast<qsizetype>(path.size())) : w;
}

ImportReport report_of(const ImportResult& result) {
  ImportReport report;
  report.cancelled = result.cancelled;
  for (const FileOutcome& f : result.files) {
    switch (f.kind) {
      case FileOutcome::Kind::Imported:
        ++report.imported;
        for (const std::string& w : f.warnings) report.warnings << short_warning(w, f.path);
        break;
      case FileOutcome::Kind::Duplicate:
        report.skipped << file_name(f.path) + ": " + duplicate_reason(f);
        break;
      case FileOutcome::Kind::NotData:
        report.skipped << file_name(f.path) + ": " + QString::fromStdString(f.reason);
        break;
      case FileOutcome::Kind::Failed:
        report.failures << QString::fromStdString(f.reason);
        break;
      case FileOutcome::Kind::NotReached:
        break;
    }
  }
  return report;
}

}  // namespace

ImportMessage import_message(const ImportReport& r) {
  ImportMessage m;
  m.headline =
      QObject::tr("Imported %n file(s)", nullptr, r.imported) +
      (r.skipped.isEmpty() ? QString() : QObject::tr(", skipped %n", nullptr, static_cast<int>(r.skipped.size()))) +
      (r.failures.isEmpty() ? QString() : QObject::tr(", %n failed", nullptr, static_cast<int>(r.failures.size()))) +
      (r.warnings.isEmpty() ? QString()
                            : QObject::tr(", %n warning(s)", nullptr, static_cast<int>(r.warnings.size()))) +
      (r.cancelled ? QObject::tr(" (cancelled)") : QString());
  QStringList all;
  for (const QString& f : r.failures) all << QObject::tr("failed: %1").arg(f);
  for (const QString& s : r.skipped) all << QObject::tr("skipped %1").arg(s);
  for (const QString& w : r.warnings) all << QObject::tr("warning: %1").arg(w);
  if (all.size() <= kFewProblems)
    m.lines = all;
  else
    m.details = all.join('\n');
  return m;
}

ImportController::ImportController(QWidget* parent_window) : QObject(parent_window), window_(parent_window) {
  qRegisterMetaType<bs::ui::ImportReport>();
}

ImportReport ImportController::import_now(const QString& workspace_path, const QStringList& paths,
                                          const CancelToken& cancel,
                                          const std::function<void(int, int, const QString&)>& progress,
                                          FrameStorage frames, const std::optional<RawFrameOptions>& raw_geometry,
                                          const LogPlatformChooser& choose_platform) {
  ImportOptions options;
  if (choose_platform)
    options.choose_log_platform = [&choose_platform](const PowerTrace& log, const std::string& path,
                                                     const std::string& guess, const std::vector<std::string>& known) {
      QStringList platforms;
      for (const std::string& k : known) platforms << QString::fromStdString(k);
      return choose_platform(QString::fromStdString(log.label), QString::fromStdString(path),
                             QString::fromStdString(guess), platforms)
          .trimmed()
          .toStdString();
    };
  options.atomicity = ImportAtomicity::EachFile;
  options.frames = frames;
  options.raw_geometry = raw_geometry;
  options.raw_geometry_source = "the geometry dialog";
  if (progress)
    options.progress = [&progress](int done, int total, const std::string& file) {
      progress(done, total, QString::fromStdString(file));
    };
  std::vector<std::string> list;
  for (const QString& p : paths) list.push_back(p.toStdString());
  try {
    return report_of(import_paths(workspace_path.toStdString(), list, options, cancel));
  } catch (const std::exception& e) {  // the workspace cannot be opened or written, a folder cannot be listed
    ImportReport report;
    report.failures << QString::fromUtf8(e.what());
    return report;
  }
}

QWidget* ImportController::question_parent() const { return progress_ ? progress_.data() : window_; }

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
  progress_ = dialog;
  // The bar counts thousandths of files: a single 100-million-row log moves it too (the reader and the store
  // report through the cancel token, CancelToken::report), not only the step to the next file.
  struct Where {
    std::atomic<int> file{0}, total{1}, permille{-1};
    QString name;  // written before the file starts, read on the GUI thread after a queued call
  };
  auto where = std::make_shared<Where>();
  auto show = [guard, where](int file, int total, int permille, const QString& name, const QString& step) {
    QMetaObject::invokeMethod(
        guard.data(),
        [guard, file, total, permille, name, step] {
          if (!guard) return;
          guard->setMaximum(total * 1000);
          guard->setValue(std::min(total * 1000, file * 1000 + std::max(permille, 0)));
          guard->setLabelText(
              QObject::tr("File %1 of %2\n%3%4")
                  .arg(std::min(file + 1, total))
                  .arg(total)
                  .arg(QFileInfo(name).fileName())
                  .arg(step.isEmpty() ? QString() : QObject::tr(" — %1 %2 %").arg(step).arg(permille / 10)));
        },
        Qt::QueuedConnection);
  };
  auto progress = [where, show](int done, int total, const QString& file) {
    where->file = done;
    where->total = std::max(total, 1);
    where->permille = -1;
    if (!file.isEmpty()) where->name = file;
    show(done, std::max(total, 1), 0, file, {});
  };
  cancel->set_progress([where, show](double fraction, std::string_view step) {
    const int permille = static_cast<int>(std::clamp(fraction, 0.0, 1.0) * 1000);
    if (where->permille.exchange(permille) == permille) return;  // one queued update per thousandth, not per call
    show(where->file, where->total, permille, where->name,
         QString::fromUtf8(step.data(), static_cast<qsizetype>(step.size())));
  });
  auto* watcher = new QFutureWatcher<ImportReport>(this);
  connect(watcher, &QFutureWatcher<ImportReport>::finished, this, [this, watcher, dialog] {
    const ImportReport report = watcher->result();
    // Hidden now, not only deleted later: a message box about the import must not open under a modal dialog
    // that a deferred delete (which waits for the outer event loop) has not removed yet.
    dialog->hide();
    dialog->deleteLater();
    progress_ = nullptr;
    watcher->deleteLater();
    running_ = false;
    emit finished(report);
  });
  // The question about a log's platform is asked on the GUI thread; the importing thread waits for the answer.
  // The progress dialog is shown first and says what it waits for; the question opens over it, as its child, so
  // it is the last modal dialog shown and takes the input (a window-modal dialog shown after it would block it).
  LogPlatformChooser ask;
  if (choose_platform_)
    ask = [this, guard](const QString& log, const QString& path, const QString& guess, const QStringList& known) {
      QString answer;
      QMetaObject::invokeMethod(
          this,
          [&] {
            if (guard) {
              guard->setLabelText(
                  tr("Waiting for your answer: which platform %1 belongs to").arg(QFileInfo(path).fileName()));
              guard->show();
              guard->raise();
            }
            answer = choose_platform_(log, path, guess, known);
          },
          Qt::BlockingQueuedConnection);
      return answer;
    };
  watcher->setFuture(
      QtConcurrent::run([workspace_path, paths, cancel, progress, frames = frame_storage_, geometry = raw_geometry_,
                         ask] { return import_now(workspace_path, paths, *cancel, progress, frames, geometry, ask); }));
}

}  // namespace bs::ui
