// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <QObject>
#include <QPointer>
#include <QStringList>
#include <functional>
#include <memory>

#include <optional>

#include "frames/frame_raw.h"
#include "model/frame.h"
#include "util/cancel.h"

class QWidget;

namespace bs::ui {

// What an import of several files did, for the status bar and the error dialog.
struct ImportReport {
  int imported = 0;
  QStringList skipped;   // "file name: reason" (already imported, not a data file)
  QStringList failures;  // one line per failed file: the importer's "file:line: field: reason"
  QStringList warnings;  // of the imported files, each naming file:line ("cut.csv:5: the last line ... cut off")
  bool cancelled = false;
};

// The words shown after an import. With few skipped or failed files each one's reason is in `lines` (shown in
// the message itself); with many, `lines` is empty and `details` lists them all.
struct ImportMessage {
  QString headline;   // "Imported 3 files, skipped 1, 1 warning"
  QStringList lines;  // "skipped nuc.csv: already imported on 2026-11-20 (same content)", "failed: bad.json:3: ...",
                      // "warning: cut.csv:5: the last line has no line ending ..."
  QString details;    // every skip and failure, one per line; empty when `lines` says it all
};
ImportMessage import_message(const ImportReport& report);

// Asked, for each power log whose file names no platform, which platform it belongs to (issue #32.3): the log's
// label, its file, the guess (never blank) and the workspace's platforms. An empty answer takes the guess.
using LogPlatformChooser =
    std::function<QString(const QString& log, const QString& path, const QString& guess, const QStringList& platforms)>;

// Imports files and folders into a workspace file off the GUI thread, with a progress dialog and Cancel. The
// worker opens its own connection to the workspace (SQLite in WAL mode allows a reader beside the writer), so the
// GUI's connection is never used from two threads. What is imported, skipped and how is the import service's
// (services/workspace/import_service.h): each file is one transaction.
class ImportController : public QObject {
  Q_OBJECT
 public:
  explicit ImportController(QWidget* parent_window);
  bool busy() const { return running_; }
  // Starts importing; finished() is emitted on the GUI thread when done.
  void start(const QString& workspace_path, const QStringList& paths);
  // Synchronous variant for tests and the command line of the GUI.
  // Frames are kept by reference unless `frames` is Copy (pixels stored in the workspace).
  static ImportReport import_now(const QString& workspace_path, const QStringList& paths, const CancelToken& cancel,
                                 const std::function<void(int, int, const QString&)>& progress = {},
                                 FrameStorage frames = FrameStorage::Reference,
                                 const std::optional<RawFrameOptions>& raw_geometry = std::nullopt,
                                 const LogPlatformChooser& choose_platform = {});
  // What start() asks about a log without a platform; called on the GUI thread (the import waits for the answer).
  // While it asks, the progress dialog is shown and says it waits for the answer, and the question's parent is the
  // progress dialog (question_parent()): a question never opens under the progress dialog, where a window-modal
  // progress dialog shown after it would take every click and key (issue #43.1).
  void set_log_platform_chooser(LogPlatformChooser chooser) { choose_platform_ = std::move(chooser); }
  // The window a question asked during start() belongs to: the progress dialog while one runs, else the window.
  QWidget* question_parent() const;
  // How start() stores the frames it imports (File > Copy imported frames into the workspace).
  void set_frame_storage(FrameStorage storage) { frame_storage_ = storage; }
  FrameStorage frame_storage() const { return frame_storage_; }
  // The geometry for .raw files without a sidecar in the next start() (the geometry dialog's answer).
  void set_raw_geometry(std::optional<RawFrameOptions> g) { raw_geometry_ = std::move(g); }

 signals:
  void finished(const bs::ui::ImportReport& report);

 private:
  QWidget* window_;
  bool running_ = false;
  FrameStorage frame_storage_ = FrameStorage::Reference;
  std::optional<RawFrameOptions> raw_geometry_;
  LogPlatformChooser choose_platform_;
  QPointer<QWidget> progress_;  // the running import's progress dialog
};

}  // namespace bs::ui
