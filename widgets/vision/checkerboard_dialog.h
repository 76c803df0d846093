// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// "Calibrate from checkerboard…" (Lens tab): pick photos of a printed checkerboard, give its squares and their size,
// and calibrate the lens with OpenCV (vision/checkerboard_calibration.h) in the background, with progress and
// cancel. The table lists every image with its RMS reprojection error or the reason it was rejected; Apply hands
// the lens to the tab (one undo step there), Save… writes a lens file.
#include <QDialog>
#include <QFutureWatcher>
#include <memory>
#include <optional>

#include "util/cancel.h"
#include "vision/lens/checkerboard_calibration.h"
#include "vision/lens/tuner_state.h"

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace bs::ui {

class CheckerboardDialog : public QDialog {
  Q_OBJECT
 public:
  // `base`: the tab's lens, view and masks now. Its field of view is the starting value (a checkerboard does not
  // measure it); Save… writes the calibrated lens with base's view and masks.
  explicit CheckerboardDialog(const vision::TunerParams& base, QWidget* parent = nullptr);
  ~CheckerboardDialog() override;  // cancels a running calibration and waits for it

  void set_images(const QStringList& paths);
  QStringList images() const { return paths_; }
  void set_board(int cols, int rows, double square_mm);
  void set_model(vision::CalibrationModel model);
  void set_fov(double deg);

  void start();   // calibrates in the background; finished() tells when it is done
  void cancel();  // asks the running calibration to stop (it stops between images)
  bool running() const { return watcher_->isRunning(); }
  const std::optional<vision::CheckerboardResult>& result() const { return result_; }
  QString error() const { return error_; }
  QString summary_text() const;
  QTableWidget* table() const { return table_; }
  QProgressBar* progress_bar() const { return progress_; }
  QPushButton* apply_button() const { return apply_; }
  void save(const QString& path) const;  // the calibrated lens as a lens file; throws std::runtime_error

 signals:
  void calibration_finished(bool ok);
  void apply_requested(const vision::Lens& lens);

 private:
  struct Outcome {
    std::optional<vision::CheckerboardResult> result;
    QString error;
    bool cancelled = false;
  };
  void fill_table();
  void run_finished();
  void update_buttons();

  vision::TunerParams base_;
  QStringList paths_;
  std::optional<vision::CheckerboardResult> result_;
  QString error_;
  std::shared_ptr<CancelToken> cancel_;
  QFutureWatcher<Outcome>* watcher_;

  QSpinBox *cols_, *rows_;
  QDoubleSpinBox *square_, *fov_;
  QComboBox* model_;
  QPushButton *add_, *remove_, *clear_, *calibrate_, *cancel_button_, *apply_, *save_;
  QProgressBar* progress_;
  QLabel *step_, *summary_;
  QTableWidget* table_;
};

}  // namespace bs::ui
