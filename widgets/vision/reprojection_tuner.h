// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Live reprojection tuner: lens model, r_pp or focal length, Kannala-Brandt k1..k4, principal point, lens and
// output FOV, output size, yaw/pitch/roll, occluder masks; undo/redo, reset, lens JSON save/load, LUT export;
// image-circle auto-calibration and a straight-line residual tool. The maths is core's (vision/tuner_state.h,
// fast_map.h, circle_detect.h, straight_line.h); the previews are rendered off the GUI thread, newest request wins.
#include <QFutureWatcher>
#include <QImage>
#include <QWidget>
#include <functional>
#include <memory>
#include <optional>

#include <opencv2/core.hpp>

#include "vision/lens/circle_detect.h"
#include "vision/lens/line_fit.h"
#include "vision/lens/tuner_state.h"

class QAction;
class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QListWidget;
class QPushButton;
class QSlider;
class QSpinBox;
class QToolBar;
class QToolButton;

namespace bs::ui {

class PreviewPane;

class ReprojectionTuner : public QWidget {
  Q_OBJECT
 public:
  explicit ReprojectionTuner(QWidget* parent = nullptr);
  ~ReprojectionTuner() override;
  bool eventFilter(QObject* watched, QEvent* event) override;

  // The fisheye frame to tune on (8-bit BGR or gray). Its size becomes the lens's source size.
  void set_fisheye(const cv::Mat& image, const QString& caption = {});
  const cv::Mat& fisheye() const { return fisheye_; }
  // New baseline (what Reset returns to); clears the history.
  void set_params(const vision::TunerParams& p);
  const vision::TunerParams& params() const { return state_.params(); }

  QAction* undo_action() const { return undo_; }
  QAction* redo_action() const { return redo_; }
  QAction* reset_action() const { return reset_; }
  PreviewPane* fisheye_pane() const { return fisheye_pane_; }
  PreviewPane* output_pane() const { return output_pane_; }
  QSlider* yaw_slider() const { return yaw_slider_; }
  QDoubleSpinBox* r_pp_spin() const { return scale_spin_; }

  // The generation of the newest request and of the preview on screen (equal when the preview is up to date).
  quint64 requested_generation() const { return requested_; }
  quint64 shown_generation() const { return shown_; }
  // Replace the lens (e.g. a checkerboard calibration's) as one undo step named `what`.
  void apply_lens(const vision::Lens& lens, const std::string& what);
  QToolBar* tool_bar() const { return bar_; }  // for the Lens tab's own actions
  // Detect the image circle and apply the proposed principal point and r_pp as one undo step. With a reference
  // lens (the frame's recorded or saved one), a proposal more than 2 % off its r_pp is applied with a warning that
  // gives both values (circle_warning()): the visible disc may span less than the lens FOV ("Circle spans").
  std::optional<vision::ImageCircle> auto_calibrate();
  void set_reference_lens(const std::optional<vision::Lens>& lens, const QString& source);
  QString circle_warning() const { return circle_warning_; }  // empty when none
  // Shown while the view reaches beyond the angle a checkerboard lens's corners covered (issue #43.8); empty else.
  QString extrapolation_note() const;
  QDoubleSpinBox* circle_fov_box() const { return circle_fov_; }
  QString status_text() const;
  // Straight-line tool: points clicked on the output preview (output pixels), kept as source pixels, so they stay
  // on the same scene points when the lens changes; the current line's residual is shown under the preview.
  // Clicks where the view has no source are ignored (returns false). The lines are part of the undo history
  // (vision::TunerState::lines): every click, proposal, deletion, load or clear is one step.
  bool add_line_point(QPointF output_px);
  void add_source_point(const cv::Point2d& source_px);
  void new_line();  // the next clicks start another line
  void clear_line_points();
  QString line_residual_text() const;
  const std::vector<vision::PickedLine>& picked_lines() const { return state_.lines(); }
  void set_picked_lines(std::vector<vision::PickedLine> lines);
  // "Propose lines": long edges of the fisheye frame that are straight in the world under the current lens
  // (vision::propose_lines), added as picked lines (those not already picked), one undo step. Returns how many.
  int propose_lines();
  // The selected line (index into picked_lines(), -1: none): highlighted in both previews; "Delete line" removes
  // it (one undo step). Clicking near a line on either preview (not while measuring or masking) selects it.
  void select_line(int index);
  int selected_line() const { return selected_; }
  bool delete_selected_line();
  QListWidget* lines_list() const { return lines_list_; }
  QPushButton* propose_button() const { return propose_button_; }
  QPushButton* delete_line_button() const { return delete_line_button_; }
  // Line refinement: fits r_pp, principal point and k1..k4 (Kannala-Brandt) to the picked lines, keeping the image
  // circle's rim, and applies the result as one undo step; with "reject outlier lines" on, lines straight to
  // worse than 3x the median line are left out (shown in red). Throws std::invalid_argument (too few lines...).
  vision::LineFitResult fit_lens_to_lines();
  QString line_fit_text() const { return line_fit_text_; }
  QString lines_summary_text() const;                        // all picked lines' straightness under the current lens
  QCheckBox* fit_centre_box() const { return fit_centre_; }  // off: the line fit keeps the principal point
  QCheckBox* reject_lines_box() const { return reject_lines_; }
  // Mask editing: while on, clicks on the fisheye preview add polygon points; a double click (or turning it off)
  // closes the polygon.
  void set_mask_editing(bool on);
  void add_mask_point(QPointF source_px);
  void finish_mask();
  void clear_masks();
  // File actions with the path given (the buttons ask with a dialog first). Throw std::runtime_error.
  void save_json(const QString& path) const;
  void load_json(const QString& path);
  void export_lut(const QString& path) const;

 signals:
  void lens_changed(const vision::Lens& lens, const vision::View& view);
  void preview_updated();

 private:
  struct Result {
    quint64 generation = 0;
    QImage image;
    QString error;
    double ms = 0;
  };
  void build_ui();
  QWidget* build_controls();
  // Applies `edit` to a copy of the current parameters as a change of `field` (merged while the same field moves).
  void change(const std::string& field, const std::function<void(vision::TunerParams&)>& edit);
  void state_changed();  // sync controls, preview, overlays, actions, signal
  void sync_controls();
  void update_overlays();
  void request_preview();
  void start_job();
  void job_finished();
  void update_scale_mode();
  void set_lines(std::vector<vision::PickedLine> lines, const std::string& what);  // one undo step
  void lines_changed();                                                            // overlays, list, labels
  void update_lines_list();
  int line_near(const std::vector<QPolygonF>& curves, QPointF p, double tol) const;

  vision::TunerState state_;
  cv::Mat fisheye_;
  std::optional<vision::ImageCircle> circle_;
  std::optional<vision::Lens> reference_;  // the frame's lens in the workspace, for Detect circle's comparison
  QString reference_source_, circle_warning_;
  QLabel* extrapolation_ = nullptr;
  void update_extrapolation_note();
  bool new_line_pending_ = false;  // the next click starts a line (else it goes to the last one)
  int selected_ = -1;
  std::vector<vision::PickedLine> left_out_;  // lines the last fit rejected, drawn red while they are picked
  QString line_fit_text_;
  vision::MaskPolygon editing_mask_;
  bool mask_editing_ = false;
  bool syncing_ = false;

  struct Buffers {
    cv::Mat map, image;
  };
  std::shared_ptr<Buffers> buffers_ = std::make_shared<Buffers>();
  quint64 requested_ = 0, shown_ = 0;
  bool running_ = false, pending_ = false;
  QFutureWatcher<Result>* watcher_;

  QAction *undo_, *redo_, *reset_;
  QToolBar* bar_ = nullptr;
  PreviewPane *fisheye_pane_, *output_pane_;
  QLabel *status_, *line_label_, *line_fit_label_;
  QComboBox* model_;
  QCheckBox* focal_mode_;
  QDoubleSpinBox *scale_spin_, *cx_, *cy_, *lens_fov_, *out_fov_;
  QDoubleSpinBox* k_[4];
  QSpinBox *out_w_, *out_h_;
  QSlider *yaw_slider_, *pitch_slider_, *roll_slider_;
  QDoubleSpinBox *yaw_, *pitch_, *roll_;
  QToolButton *mask_button_, *line_button_;
  QDoubleSpinBox* circle_fov_;
  QCheckBox *fit_centre_, *reject_lines_;
  QListWidget* lines_list_;
  QPushButton *propose_button_, *delete_line_button_;
};

}  // namespace bs::ui
