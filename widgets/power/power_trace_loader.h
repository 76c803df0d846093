// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Loads the samples of a workspace's power traces off the GUI thread (issue #19 "Scale"): the window opens with
// each trace's cached summary (Workspace::power_trace_summaries(), a few KB per trace), and the samples of a
// 10- or 100-million-sample log arrive later, with progress in the status bar and a Cancel button. Small
// workspaces are loaded at once (load_now), so their views are filled before reload() returns, as before.
#include <QObject>
#include <QWidget>
#include <memory>
#include <vector>

#include "power/shared_traces.h"
#include "store/workspace.h"

class QLabel;
class QProgressBar;
class QToolButton;

namespace bs::ui {

class PowerTraceLoader : public QWidget {
  Q_OBJECT
 public:
  // Above this many samples (timestamps and values of every trace together) the load goes to a worker thread.
  static constexpr std::size_t kBackgroundSamples = 2'000'000;

  explicit PowerTraceLoader(QWidget* parent = nullptr);  // a status bar widget: text, bar, Cancel; hidden when idle
  ~PowerTraceLoader() override;                          // cancels a load in progress and waits for it

  static std::size_t sample_count(const std::vector<StoredPowerTrace>& traces);
  // Fills every trace's samples on the calling thread.
  static void load_now(const Workspace& ws, std::vector<StoredPowerTrace>& traces, const CancelToken* cancel = nullptr);
  // Loads `traces` from the workspace file `path` (a connection of its own) on a worker thread; a load still
  // running is cancelled and its result dropped. Emits loaded() on the GUI thread when done.
  void start(const std::string& path, std::vector<StoredPowerTrace> traces);
  void cancel();   // the user's Cancel: failed() follows
  void abandon();  // a newer state of the workspace replaces the load: nothing follows
  bool running() const { return static_cast<bool>(cancel_); }

 signals:
  void loaded(const bs::ui::SharedTraces& traces);  // the samples moved in, not copied
  void failed(const QString& message);              // cancelled by the user, or the file could not be read

 private:
  QLabel* text_;
  QProgressBar* bar_;
  QToolButton* cancel_button_;
  std::shared_ptr<CancelToken> cancel_;  // of the load in progress; null when idle
  int generation_ = 0;                   // results of a superseded load are dropped
};

}  // namespace bs::ui
