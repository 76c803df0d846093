// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// "Run" for the Sustained tab: the load (the CLI's syntax: flops[:W], pipeline[@FPS], dnn[:NET][@RATE]), how long
// and how often to take its rate, clocks and temperatures, "Record power", and where: this computer or a robot over
// SSH (RunHereOrRobot). Here, core's run_sustain runs off the GUI thread; each interval comes back at once for the
// live plot (`live_interval`), and the finished run is handed over to be stored (`measured`). On a robot, the same
// settings go as `benchscope-cli sustain` words (core: commands/sustain_grammar.h), the intervals its job streams
// feed the same live plot, Cancel stops it there and the job comes home with the robot's provenance
// (`robot_finished`). Every setting is remembered (QSettings).
#include <QWidget>
#include <memory>
#include <optional>

#include "model/sustain_run.h"
#include "remote/run_controls.h"
#include "sustain/sustain_runner.h"

class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QPushButton;

namespace bs::ui {

class SustainRunPanel : public QWidget {
  Q_OBJECT
 public:
  explicit SustainRunPanel(QWidget* parent = nullptr);
  ~SustainRunPanel() override;
  QLineEdit* load() const { return load_; }
  QDoubleSpinBox* seconds() const { return seconds_; }
  QDoubleSpinBox* interval() const { return interval_; }
  // Where, Run, Cancel, the progress bar and the status line, as every run panel has them.
  const RunControls& controls() const { return controls_; }

 public slots:
  void start();

 signals:
  void live_interval(const bs::SustainRun& so_far);     // after each interval, here or on a robot: the live plot
  void measured(const bs::sustain::RunOutput& output);  // after stopped()
  void stopped();                                       // a run here or on a robot ended, however it ended
  void robot_finished(bs::ui::RemoteRun* run, const QString& platform);
  void failed(const QString& message);

 private:
  void save_settings() const;
  void here_finished(bool cancelled);

  QLineEdit* load_;
  QDoubleSpinBox* seconds_;
  QDoubleSpinBox* interval_;
  RunControls controls_;  // where, Run, Cancel, progress, status, and the controller behind them
  // What the run here produced, written on its worker thread before it returns and read after here_finished.
  std::shared_ptr<std::optional<sustain::RunOutput>> output_;
};

}  // namespace bs::ui
