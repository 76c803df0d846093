// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// "Run on this machine" for the Headroom tab: the probe's rate, seconds per phase, threads, per-cycle computation,
// priority and real-time request, the loads (the CLI's syntax: pipeline@30fps, dnn, flops:64) and an external
// command, "Record power"; Run starts core's run_headroom off the GUI thread with progress and cancel, and hands
// the finished measurement (with its power trace) over to be stored. Every setting is remembered (QSettings).
#include <QWidget>
#include <atomic>
#include <memory>
#include <mutex>
#include <optional>

#include "headroom/headroom_run.h"
#include "util/cancel.h"

class QCheckBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QSpinBox;
template <class T>
class QFutureWatcher;

namespace bs::sensors {
class PowerRecorder;
}

namespace bs::ui {

class PowerSensorBox;

class HeadroomRunPanel : public QWidget {
  Q_OBJECT
 public:
  explicit HeadroomRunPanel(QWidget* parent = nullptr);
  ~HeadroomRunPanel() override;
  QDoubleSpinBox* rate() const { return rate_; }
  QDoubleSpinBox* seconds() const { return seconds_; }
  QSpinBox* threads() const { return threads_; }
  QDoubleSpinBox* computation() const { return computation_; }
  QSpinBox* priority() const { return priority_; }
  QCheckBox* realtime() const { return realtime_; }
  QLineEdit* loads() const { return loads_; }
  QLineEdit* command() const { return command_; }
  PowerSensorBox* power_box() const { return power_; }
  QPushButton* run_button() const { return run_; }
  QPushButton* cancel_button() const { return cancel_; }
  QLabel* status() const { return status_; }
  bool running() const;

 public slots:
  void start();
  void cancel();

 signals:
  void measured(const bs::headroom::RunOutput& output);
  void failed(const QString& message);

 private:
  struct Outcome {
    std::optional<headroom::RunOutput> output;
    QString error;
    bool cancelled = false;
  };
  void finished();
  void save_settings() const;

  QDoubleSpinBox* rate_;
  QDoubleSpinBox* seconds_;
  QSpinBox* threads_;
  QDoubleSpinBox* computation_;
  QSpinBox* priority_;
  QCheckBox* realtime_;
  QLineEdit* loads_;
  QLineEdit* command_;
  PowerSensorBox* power_;
  QPushButton* run_;
  QPushButton* cancel_;
  QProgressBar* progress_;
  QLabel* status_;
  QFutureWatcher<Outcome>* watcher_;
  std::shared_ptr<CancelToken> token_;
  std::shared_ptr<sensors::PowerRecorder> recorder_;
  // Written by the run's thread, read by a GUI timer.
  struct Progress {
    std::atomic<int> percent{0};
    std::mutex mutex;
    std::string step;
  };
  std::shared_ptr<Progress> progress_state_;
};

}  // namespace bs::ui
