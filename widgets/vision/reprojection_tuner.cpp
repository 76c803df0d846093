// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/reprojection_tuner.h"

#include "common/file_command.h"
#include "common/wrapping_tool_bar.h"
#include "vision/lens/lens_limits.h"

#include <QAbstractSpinBox>
#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QFormLayout>
#include <QGroupBox>
#include <QGuiApplication>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QScrollArea>
#include <QSlider>
#include <QSpinBox>
#include <QSplitter>
#include <QToolBar>
#include <QToolButton>
#include <QVBoxLayout>
#include <QtConcurrent>
#include <cmath>
#include <type_traits>

#include <opencv2/imgproc.hpp>

#include "vision/lens/edge_proposals.h"
#include "vision/lens/straight_line.h"
#include "vision/preview_pane.h"
#include "vision/reproject/fast_map.h"

namespace bs::ui {
namespace {

constexpr double kCircleTolerance = 0.02;  // Detect circle vs the recorded lens: beyond 2 % apart, warn

constexpr double kPi = 3.14159265358979323846;
constexpr int kCoarseStep = 8;  // fast_map.h: under 0.01 px from the exact map for the paper's lens

QImage to_qimage(const cv::Mat& m) {
  if (m.type() == CV_8UC3)
    return QImage(m.data, m.cols, m.rows, static_cast<int>(m.step), QImage::Format_BGR888).copy();
  if (m.type() == CV_8UC1)
    return QImage(m.data, m.cols, m.rows, static_cast<int>(m.step), QImage::Format_Grayscale8).copy();
  return {};
}

QDoubleSpinBox* spin(double lo, double hi, int decimals, double step, const QString& suffix, const QString& tip) {
  auto* s = new QDoubleSpinBox;
  s->setRange(lo, hi);
  s->setDecimals(decimals);
  s->setSingleStep(step);
  s->setSuffix(suffix);
  s->setToolTip(tip);
  s->setKeyboardTracking(false);  // typing "1", "12", "120" is one change, not three
  return s;
}

}  // namespace

ReprojectionTuner::ReprojectionTuner(QWidget* parent) : QWidget(parent), watcher_(new QFutureWatcher<Result>(this)) {
  connect(watcher_, &QFutureWatcher<Result>::finished, this, &ReprojectionTuner::job_finished);
  build_ui();
  sync_controls();
  update_overlays();
  // Ctrl+Z / Ctrl+Shift+Z in a focused number field undo and redo the lens change, not the field's typing: the
  // fields would otherwise take the keys first (their line edits claim them in ShortcutOverride).
  for (QAbstractSpinBox* box : findChildren<QAbstractSpinBox*>()) box->installEventFilter(this);
}

bool ReprojectionTuner::eventFilter(QObject* watched, QEvent* event) {
  if (event->type() == QEvent::ShortcutOverride) {
    auto* key = static_cast<QKeyEvent*>(event);
    const bool undo_redo = key->matches(QKeySequence::Undo) || key->matches(QKeySequence::Redo) ||
                           key->keyCombination() == QKeyCombination(Qt::CTRL | Qt::SHIFT, Qt::Key_Z);
    if (undo_redo) {
      event->ignore();  // not claimed by the field: the tuner's Undo/Redo actions get the shortcut
      return true;
    }
  }
  return QWidget::eventFilter(watched, event);
}

ReprojectionTuner::~ReprojectionTuner() {
  // The job captures copies only, but its result slot must not run on a half-destroyed widget.
  watcher_->disconnect(this);
  watcher_->waitForFinished();
}

void ReprojectionTuner::build_ui() {
  auto* bar = new QToolBar(this);
  bar_ = bar;
  bar->setToolButtonStyle(Qt::ToolButtonTextOnly);
  undo_ = bar->addAction(tr("Undo"), this, [this] {
    if (state_.undo()) state_changed();
  });
  undo_->setShortcut(QKeySequence::Undo);
  undo_->setToolTip(tr("Undo the last parameter change (Ctrl+Z); a slider drag is one step"));
  redo_ = bar->addAction(tr("Redo"), this, [this] {
    if (state_.redo()) state_changed();
  });
  redo_->setShortcuts({QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z), QKeySequence(Qt::CTRL | Qt::Key_Y)});
  redo_->setToolTip(tr("Redo (Ctrl+Shift+Z)"));
  reset_ = bar->addAction(tr("Reset"), this, [this] {
    if (state_.reset()) state_changed();
  });
  reset_->setToolTip(tr("Back to the lens this tuner started with (undoable)"));
  for (QAction* a : {undo_, redo_}) a->setShortcutContext(Qt::WidgetWithChildrenShortcut);
  addAction(undo_);
  addAction(redo_);
  bar->addSeparator();
  bar->addAction(tr("Load lens…"), this,
                 [this] {
                   run_file_command(this, {FileCommand::Open, tr("Load lens"), {}, tr("Lens JSON (*.json)")},
                                    [this](const QString& path) { load_json(path); });
                 })
      ->setToolTip(tr("Load a BenchScope lens JSON (lens, view and masks)"));
  bar->addAction(tr("Save lens…"), this,
                 [this] {
                   run_file_command(this, {FileCommand::Save, tr("Save lens"), "lens.json", tr("Lens JSON (*.json)")},
                                    [this](const QString& path) { save_json(path); });
                 })
      ->setToolTip(tr("Save lens, view and masks as JSON"));
  bar->addAction(tr("Export LUT…"), this,
                 [this] {
                   run_file_command(this,
                                    {FileCommand::Save, tr("Export lookup table"), "view.bslut",
                                     tr("BenchScope LUT (*.bslut)"), tr("Export LUT")},
                                    [this](const QString& path) { export_lut(path); });
                 })
      ->setToolTip(tr("Write the exact lookup table (float32 source x, y per output pixel; docs/lut-format.md)"));
  bar->addSeparator();
  bar->addAction(tr("Detect circle"), this,
                 [this] {
                   if (!auto_calibrate()) status_->setText(tr("No image circle found in the fisheye frame."));
                 })
      ->setToolTip(tr("Find the fisheye image circle and set principal point and r_pp so the lens FOV fills it"));

  fisheye_pane_ = new PreviewPane(tr("No fisheye frame"));
  fisheye_pane_->setToolTip(
      tr("Fisheye source. With 'Add mask' on, click to add polygon points (source pixels), "
         "double-click to close the polygon."));
  output_pane_ = new PreviewPane(tr("Reprojected view appears here"));
  output_pane_->setToolTip(
      tr("Reprojected rectilinear view. With 'Measure line' on, click points along a line that "
         "is straight in the world; the residual is shown below."));
  connect(fisheye_pane_, &PreviewPane::clicked, this, [this](QPointF p) {
    if (mask_editing_) {
      add_mask_point(p);
      return;
    }
    std::vector<QPolygonF> curves;
    for (const auto& l : state_.lines()) {
      QPolygonF q;
      for (const auto& pt : l) q << QPointF(pt.x, pt.y);
      curves.push_back(q);
    }
    // 8 widget pixels, in image pixels.
    const double tol = 8 * fisheye_pane_->image().width() / std::max(1.0, double(fisheye_pane_->width()));
    select_line(line_near(curves, p, std::max(tol, 3.0)));
  });
  connect(fisheye_pane_, &PreviewPane::double_clicked, this, [this](QPointF) {
    if (mask_editing_) finish_mask();
  });
  connect(output_pane_, &PreviewPane::clicked, this, [this](QPointF p) {
    if (line_button_->isChecked()) {
      add_line_point(p);
      return;
    }
    const auto& prm = state_.params();
    std::vector<QPolygonF> curves;
    for (const auto& l : state_.lines()) {
      QPolygonF q;
      for (const auto& pt : l)
        if (const auto o = vision::view_pixel_of(prm.lens, prm.view, pt)) q << QPointF(o->x, o->y);
      curves.push_back(q);
    }
    const double tol = 8 * output_pane_->image().width() / std::max(1.0, double(output_pane_->width()));
    select_line(line_near(curves, p, std::max(tol, 3.0)));
  });

  auto* previews = new QSplitter(Qt::Vertical);
  previews->addWidget(fisheye_pane_);
  previews->addWidget(output_pane_);
  auto* scroll = new QScrollArea;
  scroll->setWidget(build_controls());
  scroll->setWidgetResizable(true);
  scroll->setMinimumWidth(scroll->widget()->sizeHint().width() + 20);
  auto* split = new QSplitter(Qt::Horizontal);
  split->addWidget(scroll);
  split->addWidget(previews);
  split->setStretchFactor(1, 1);

  status_ = new QLabel;
  status_->setWordWrap(true);
  // Issue #43.8: a checkerboard lens used beyond the angle its corners covered says so, whatever else is shown.
  extrapolation_ = new QLabel;
  extrapolation_->setObjectName(QStringLiteral("extrapolationNote"));
  extrapolation_->setWordWrap(true);
  extrapolation_->setStyleSheet(QStringLiteral("color: #8a4b00"));
  extrapolation_->hide();
  auto* lay = new QVBoxLayout(this);
  lay->setContentsMargins(0, 0, 0, 0);
  // The actions wrap onto a second row on a narrow window instead of hiding behind "»" (issue #32.7).
  lay->addWidget(new WrappingToolBar(bar, this));
  lay->addWidget(split, 1);
  lay->addWidget(extrapolation_);
  lay->addWidget(status_);
}

QString ReprojectionTuner::extrapolation_note() const { return extrapolation_->text(); }

void ReprojectionTuner::update_extrapolation_note() {
  const auto& p = state_.params();
  const std::string note = vision::extrapolation_note(p.lens, p.view);
  extrapolation_->setText(note.empty() ? QString() : tr("⚠ The calibration: %1.").arg(QString::fromStdString(note)));
  extrapolation_->setVisible(!note.empty());
}

QWidget* ReprojectionTuner::build_controls() {
  auto* w = new QWidget;
  auto* lay = new QVBoxLayout(w);

  auto* lens_box = new QGroupBox(tr("Lens"));
  auto* lf = new QFormLayout(lens_box);
  // Each value a field takes is one change of the parameters, named after the field (a run of them is one undo step);
  // none while the fields are being set from the parameters (syncing_).
  const auto edits = [this](auto* field, const std::string& name, auto set) {
    connect(field, &std::remove_pointer_t<decltype(field)>::valueChanged, this, [this, name, set](auto v) {
      if (!syncing_) change(name, [set, v](vision::TunerParams& p) { set(p, v); });
    });
  };
  model_ = new QComboBox;
  for (int i = 0; i < 6; ++i)
    model_->addItem(QString::fromUtf8(vision::to_string(static_cast<vision::LensType>(i)).data()));
  model_->setToolTip(
      tr("Projection model r(θ): equidistant r = θ/r_pp, equisolid 2f sin(θ/2), stereographic "
         "2f tan(θ/2), orthographic f sin θ, rectilinear f tan θ, Kannala-Brandt f θ(1+k1θ²+…)"));
  connect(model_, &QComboBox::currentIndexChanged, this, [this](int i) {
    if (!syncing_) change("model", [i](auto& p) { p.lens.type = static_cast<vision::LensType>(i); });
  });
  lf->addRow(tr("Model"), model_);
  focal_mode_ = new QCheckBox(tr("edit as focal length"));
  focal_mode_->setToolTip(
      tr("Edit the scale as focal length f = 1/r_pp in pixels instead of r_pp in radians per pixel"));
  connect(focal_mode_, &QCheckBox::toggled, this, [this] { update_scale_mode(); });
  lf->addRow(QString(), focal_mode_);
  scale_spin_ = spin(1e-5, 1.0, 7, 1e-5, tr(" rad/px"), {});
  connect(scale_spin_, &QDoubleSpinBox::valueChanged, this, [this](double v) {
    if (syncing_ || v <= 0) return;
    const double r_pp = focal_mode_->isChecked() ? 1.0 / v : v;
    change("r_pp", [r_pp](auto& p) { p.lens.r_pp = r_pp; });
  });
  lf->addRow(tr("Scale"), scale_spin_);
  for (int i = 0; i < 4; ++i) {
    k_[i] =
        spin(-10, 10, 6, 0.001, {},
             tr("Kannala-Brandt k%1 (dimensionless): θ_d = θ(1 + k1θ² + k2θ⁴ + k3θ⁶ + k4θ⁸), θ in radians").arg(i + 1));
    edits(k_[i], "k" + std::to_string(i + 1),
          [i](vision::TunerParams& p, double v) { p.lens.k[static_cast<std::size_t>(i)] = v; });
    lf->addRow(tr("k%1").arg(i + 1), k_[i]);
  }
  cx_ = spin(-1, 100000, 2, 0.5, tr(" px"), tr("Principal point x in source pixels (-1: image centre)"));
  cx_->setSpecialValueText(tr("centre"));
  cy_ = spin(-1, 100000, 2, 0.5, tr(" px"), tr("Principal point y in source pixels, rows down (-1: image centre)"));
  cy_->setSpecialValueText(tr("centre"));
  edits(cx_, "cx", [](vision::TunerParams& p, double v) { p.lens.cx = v; });
  edits(cy_, "cy", [](vision::TunerParams& p, double v) { p.lens.cy = v; });
  lf->addRow(tr("cx"), cx_);
  lf->addRow(tr("cy"), cy_);
  lens_fov_ = spin(1, 360, 1, 0.5, tr(" °"),
                   tr("Lens field of view in degrees: rays beyond FOV/2 off the axis are outside the image circle"));
  edits(lens_fov_, "lens_fov", [](vision::TunerParams& p, double v) { p.lens.fov_deg = v; });
  lf->addRow(tr("Lens FOV"), lens_fov_);
  lay->addWidget(lens_box);

  auto* view_box = new QGroupBox(tr("Output view"));
  auto* vf = new QFormLayout(view_box);
  out_fov_ =
      spin(1, 179, 1, 1, tr(" °"), tr("Output field of view in degrees across the image diagonal (paper: 150°)"));
  edits(out_fov_, "out_fov", [](vision::TunerParams& p, double v) { p.view.fov_deg = v; });
  vf->addRow(tr("FOV"), out_fov_);
  out_w_ = new QSpinBox;
  out_h_ = new QSpinBox;
  for (QSpinBox* s : {out_w_, out_h_}) {
    s->setRange(16, 8192);
    s->setSuffix(tr(" px"));
    s->setKeyboardTracking(false);
  }
  out_w_->setToolTip(tr("Output width in pixels"));
  out_h_->setToolTip(tr("Output height in pixels"));
  edits(out_w_, "out_w", [](vision::TunerParams& p, int v) { p.view.width = v; });
  edits(out_h_, "out_h", [](vision::TunerParams& p, int v) { p.view.height = v; });
  vf->addRow(tr("Width"), out_w_);
  vf->addRow(tr("Height"), out_h_);
  const auto angle_row = [&](const QString& name, const char* field, double vision::View::*member, QSlider*& slider,
                             QDoubleSpinBox*& box, const QString& tip) {
    slider = new QSlider(Qt::Horizontal);
    slider->setRange(-1800, 1800);  // tenths of a degree
    // Long enough that one pixel is about one degree, and the keys step by 1 degree (arrows) and 10 (page).
    slider->setMinimumWidth(360);
    slider->setSingleStep(10);
    slider->setPageStep(100);
    slider->setToolTip(tip);
    box = spin(-180, 180, 1, 0.5, tr(" °"), tip);
    edits(slider, field, [member](vision::TunerParams& p, int v) { p.view.*member = v / 10.0; });
    connect(slider, &QSlider::sliderReleased, this, [this] { state_.end_merge(); });
    edits(box, field, [member](vision::TunerParams& p, double v) { p.view.*member = v; });
    connect(box, &QDoubleSpinBox::editingFinished, this, [this] { state_.end_merge(); });
    // The value on its own row and the slider under it across both columns: the slider keeps its length without
    // widening the panel (the Lens tab then fits a 1280 px window beside the workspace dock).
    vf->addRow(name, box);
    vf->addRow(slider);
  };
  angle_row(tr("Yaw"), "yaw", &vision::View::yaw_deg, yaw_slider_, yaw_,
            tr("Yaw in degrees: turns the view about the vertical axis (+ right)"));
  angle_row(tr("Pitch"), "pitch", &vision::View::pitch_deg, pitch_slider_, pitch_,
            tr("Pitch in degrees: tilts the view about the horizontal axis (+ up)"));
  angle_row(tr("Roll"), "roll", &vision::View::roll_deg, roll_slider_, roll_,
            tr("Roll in degrees: rotates the view about its optical axis (+ turns the camera counter-clockwise: the "
               "scene turns clockwise in the view)"));
  lay->addWidget(view_box);

  auto* tools = new QGroupBox(tr("Masks and checks"));
  auto* tl = new QVBoxLayout(tools);
  // The tools' buttons: a mode that takes clicks on a preview (Add mask, Measure line) toggles; the rest act once.
  const auto mode_button = [](const QString& text, const QString& tip) {
    auto* b = new QToolButton;
    b->setText(text);
    b->setCheckable(true);
    b->setToolTip(tip);
    return b;
  };
  const auto button = [this](const QString& text, const QString& tip, auto on_click) {
    auto* b = new QPushButton(text);
    b->setToolTip(tip);
    connect(b, &QPushButton::clicked, this, on_click);
    return b;
  };
  auto* mask_row = new QHBoxLayout;
  mask_button_ = mode_button(tr("Add mask"),
                             tr("Click points around an occluder (e.g. the robot's nose) on the fisheye preview; "
                                "double-click or press again to close the polygon. Masked source pixels are blanked."));
  connect(mask_button_, &QToolButton::toggled, this, [this](bool on) { set_mask_editing(on); });
  auto* clear_masks_button =
      button(tr("Clear masks"), tr("Remove every mask polygon (undoable)"), [this] { clear_masks(); });
  mask_row->addWidget(mask_button_);
  mask_row->addWidget(clear_masks_button);
  tl->addLayout(mask_row);
  auto* circle_row = new QFormLayout;
  circle_fov_ = spin(0, 360, 1, 1, tr(" °"),
                     tr("Angle the detected image circle spans, for Detect circle (0: the lens FOV). Smaller when the "
                        "lit disc ends before the lens's FOV, e.g. 174° for the synthetic chart frames"));
  circle_fov_->setSpecialValueText(tr("lens FOV"));
  circle_row->addRow(tr("Circle spans"), circle_fov_);
  tl->addLayout(circle_row);
  auto* line_row = new QHBoxLayout;
  line_button_ =
      mode_button(tr("Measure line"), tr("Click 3 or more points along a line that is straight in the world, on the "
                                         "reprojected preview: with the right lens they lie on a straight line"));
  auto* next_line =
      button(tr("New line"), tr("Start another line: the next clicks belong to it"), [this] { new_line(); });
  auto* clear_line = button(tr("Clear points"), tr("Remove every picked line"), [this] { clear_line_points(); });
  line_row->addWidget(line_button_);
  line_row->addWidget(next_line);
  line_row->addWidget(clear_line);
  tl->addLayout(line_row);
  line_label_ = new QLabel(tr("Line residual: click 3+ points"));
  line_label_->setWordWrap(true);
  line_label_->setToolTip(tr("RMS and largest perpendicular distance in output pixels from the best-fit line"));
  tl->addWidget(line_label_);
  auto* propose_row = new QHBoxLayout;
  propose_button_ =
      button(tr("Propose lines"),
             tr("Find long edges in the fisheye frame that are straight in the world under the current lens (a little "
                "bend allowed, for a lens not yet right) and add them as lines to fit; edit them like picked lines. "
                "One undo step (Ctrl+Shift+P)"),
             [this] { propose_lines(); });
  propose_button_->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_P));
  delete_line_button_ =
      button(tr("Delete line"),
             tr("Remove the selected line (pick it in the list, or click near it on a preview); one undo step (Del)"),
             [this] { delete_selected_line(); });
  delete_line_button_->setEnabled(false);
  // Del only while the focus is in the tuner: the workspace tree beside it takes Del for its own removals.
  auto* delete_key = new QAction(this);
  delete_key->setShortcut(QKeySequence::Delete);
  delete_key->setShortcutContext(Qt::WidgetWithChildrenShortcut);
  connect(delete_key, &QAction::triggered, this, [this] { delete_selected_line(); });
  addAction(delete_key);
  propose_row->addWidget(propose_button_);
  propose_row->addWidget(delete_line_button_);
  tl->addLayout(propose_row);
  lines_list_ = new QListWidget;
  lines_list_->setToolTip(
      tr("Picked and proposed lines: points, length in the fisheye and straightness RMS under the current lens "
         "(fisheye pixels). Select one to highlight it; Delete line removes it"));
  lines_list_->setMaximumHeight(130);
  connect(lines_list_, &QListWidget::currentRowChanged, this, [this](int row) {
    if (!syncing_) select_line(row);
  });
  tl->addWidget(lines_list_);
  auto* fit_row = new QHBoxLayout;
  auto* fit_button = button(tr("Fit lens to lines"),
                            tr("Least-squares fit of r_pp, principal point and k1..k4 (Kannala-Brandt) that makes the "
                               "picked lines straight, keeping the image circle's rim; one undo step (Ctrl+Z)"),
                            [this] {
                              try {
                                fit_lens_to_lines();
                              } catch (const std::exception& e) {
                                line_fit_text_ = tr("Line fit: %1").arg(QString::fromStdString(e.what()));
                                line_fit_label_->setText(line_fit_text_);
                              }
                            });
  auto* save_lines = button(
      tr("Save lines…"), tr("Write the picked lines (source pixels) for benchscope-cli lens refine-lines"), [this] {
        run_file_command(this, {FileCommand::Save, tr("Save lines"), "lines.json", tr("Lines JSON (*.json)")},
                         [this](const QString& path) {
                           vision::save_lines_json(state_.lines(), state_.params().lens.width,
                                                   state_.params().lens.height, path.toStdString());
                         });
      });
  auto* load_lines =
      button(tr("Load lines…"),
             tr("Read picked lines from a benchscope-lines JSON file (e.g. synth-frame --scene room)"), [this] {
               run_file_command(
                   this, {FileCommand::Open, tr("Load lines"), {}, tr("Lines JSON (*.json)")},
                   [this](const QString& path) { set_picked_lines(vision::load_lines_json(path.toStdString())); });
             });
  fit_centre_ = new QCheckBox(tr("centre"));
  fit_centre_->setChecked(true);
  fit_centre_->setToolTip(
      tr("Fit the principal point too. Turn off to keep it, e.g. after Detect circle, which "
         "measures it to a fraction of a pixel: lines see it weakly (near the axis a shifted "
         "centre looks like a turned camera, and lines stay straight)"));
  reject_lines_ = new QCheckBox(tr("reject outliers"));
  reject_lines_->setChecked(true);
  reject_lines_->setToolTip(
      tr("Leave out lines straight to worse than 3x the median line under the fitted lens, and fit again: edges "
         "that are no lines of the world (two meeting at a slight angle) get into proposals. Left-out lines turn "
         "red"));
  fit_row->addWidget(fit_button);
  fit_row->addWidget(save_lines);
  fit_row->addWidget(load_lines);
  tl->addLayout(fit_row);
  auto* fit_options = new QHBoxLayout;
  fit_options->addWidget(new QLabel(tr("Fit:")));
  fit_options->addWidget(fit_centre_);
  fit_options->addWidget(reject_lines_);
  fit_options->addStretch(1);
  tl->addLayout(fit_options);
  line_fit_label_ = new QLabel(tr("Line fit: pick 3 or more lines, then fit"));
  line_fit_label_->setWordWrap(true);
  line_fit_label_->setToolTip(
      tr("Straightness of all picked lines: RMS distance in fisheye pixels of the points "
         "from the image of the best straight 3D line through them, before and after the fit"));
  tl->addWidget(line_fit_label_);
  lay->addWidget(tools);
  lay->addStretch(1);
  return w;
}

void ReprojectionTuner::update_scale_mode() {
  const bool focal = focal_mode_->isChecked();
  const QSignalBlocker block(scale_spin_);
  if (focal) {
    scale_spin_->setRange(1, 1e5);
    scale_spin_->setDecimals(2);
    scale_spin_->setSingleStep(1);
    scale_spin_->setSuffix(tr(" px"));
    scale_spin_->setToolTip(tr("Focal length f = 1/r_pp in pixels"));
    scale_spin_->setValue(1.0 / state_.params().lens.r_pp);
  } else {
    scale_spin_->setRange(1e-6, 1.0);
    scale_spin_->setDecimals(7);
    scale_spin_->setSingleStep(1e-5);
    scale_spin_->setSuffix(tr(" rad/px"));
    scale_spin_->setToolTip(tr("r_pp: radians of view per pixel of image radius (paper: 195° / 1280 px)"));
    scale_spin_->setValue(state_.params().lens.r_pp);
  }
}

void ReprojectionTuner::set_fisheye(const cv::Mat& image, const QString& caption) {
  fisheye_ = image;
  fisheye_pane_->set_image(to_qimage(image));
  fisheye_pane_->set_caption(caption);
  circle_.reset();
  vision::TunerParams p = state_.params();
  if (!image.empty() && (p.lens.width != image.cols || p.lens.height != image.rows)) {
    // Keep the lens's field of view across the new width (as benchscope-cli synth-frame --size does).
    p.lens.r_pp *= static_cast<double>(p.lens.width) / image.cols;
    p.lens.width = image.cols;
    p.lens.height = image.rows;
    state_.rebase(p);
  }
  state_changed();
}

void ReprojectionTuner::set_params(const vision::TunerParams& p) {
  state_.rebase(p);
  state_changed();
}

void ReprojectionTuner::change(const std::string& field, const std::function<void(vision::TunerParams&)>& edit) {
  vision::TunerParams p = state_.params();
  edit(p);
  if (state_.set(p, field)) state_changed();
}

void ReprojectionTuner::state_changed() {
  sync_controls();
  update_overlays();
  update_extrapolation_note();
  undo_->setEnabled(state_.can_undo());
  redo_->setEnabled(state_.can_redo());
  line_label_->setText(line_residual_text());  // the picked points move with the lens
  line_fit_label_->setText(lines_summary_text());
  if (selected_ >= static_cast<int>(state_.lines().size())) selected_ = -1;  // an undo took the line away
  update_lines_list();
  request_preview();
  emit lens_changed(state_.params().lens, state_.params().view);
}

void ReprojectionTuner::sync_controls() {
  syncing_ = true;
  const auto& p = state_.params();
  model_->setCurrentIndex(static_cast<int>(p.lens.type));
  update_scale_mode();
  for (int i = 0; i < 4; ++i) {
    k_[i]->setValue(p.lens.k[static_cast<std::size_t>(i)]);
    k_[i]->setEnabled(p.lens.type == vision::LensType::KannalaBrandt);
  }
  cx_->setValue(p.lens.cx);
  cy_->setValue(p.lens.cy);
  lens_fov_->setValue(p.lens.fov_deg);
  out_fov_->setValue(p.view.fov_deg);
  out_w_->setValue(p.view.width);
  out_h_->setValue(p.view.height);
  // A slider drag must not be fought by its own echo: only move sliders the user is not holding.
  const auto set_angle = [](QSlider* s, QDoubleSpinBox* b, double v) {
    if (!s->isSliderDown()) s->setValue(static_cast<int>(std::lround(v * 10)));
    b->setValue(v);
  };
  set_angle(yaw_slider_, yaw_, p.view.yaw_deg);
  set_angle(pitch_slider_, pitch_, p.view.pitch_deg);
  set_angle(roll_slider_, roll_, p.view.roll_deg);
  syncing_ = false;
}

void ReprojectionTuner::update_overlays() {
  const auto& p = state_.params();
  std::vector<PreviewPane::Overlay> overlays;
  for (const auto& poly : p.masks) {
    QPolygonF q;
    for (const auto& pt : poly) q << QPointF(pt.x, pt.y);
    overlays.push_back({q, QColor(220, 40, 40), true, false});
  }
  if (!editing_mask_.empty()) {
    QPolygonF q;
    for (const auto& pt : editing_mask_) q << QPointF(pt.x, pt.y);
    overlays.push_back({q, QColor(255, 160, 0), false, true});
  }
  // Picked lines on the fisheye too (source pixels), so the user sees what the fit will use: the selected one
  // thick and white, those the last fit left out red, the one taking clicks yellow. Markers on clicked lines
  // (proposed ones have a point every few pixels).
  const auto& picked = state_.lines();
  const auto colour_of = [&](std::size_t i) {
    if (static_cast<int>(i) == selected_) return QColor(255, 255, 255);
    if (std::find(left_out_.begin(), left_out_.end(), picked[i]) != left_out_.end()) return QColor(255, 60, 60);
    return i + 1 == picked.size() && !new_line_pending_ ? QColor(255, 200, 0) : QColor(0, 220, 255);
  };
  for (std::size_t i = 0; i < picked.size(); ++i) {
    QPolygonF q;
    for (const auto& pt : picked[i]) q << QPointF(pt.x, pt.y);
    const bool sel = static_cast<int>(i) == selected_;
    overlays.push_back({q, colour_of(i), false, picked[i].size() < 25 || sel, sel ? 4.0 : 2.0});
  }
  fisheye_pane_->set_overlays(overlays);
  // The lens's image circle (FOV/2) and, after auto-calibration, the detected one.
  std::vector<PreviewPane::Circle> circles;
  double theta = p.lens.fov_deg * kPi / 360;
  if (p.lens.type == vision::LensType::Orthographic) theta = std::min(theta, kPi / 2);
  if (const auto r = p.lens.radius(theta); r && std::isfinite(*r)) {
    const cv::Point2d c = p.lens.centre();
    circles.push_back({QPointF(c.x, c.y), *r, QColor(0, 170, 255)});
  }
  if (circle_) circles.push_back({QPointF(circle_->centre.x, circle_->centre.y), circle_->radius, QColor(60, 220, 60)});
  fisheye_pane_->set_circles(circles);
  // The picked lines as the current lens maps them into the view: straight when the lens is right.
  // Only the stretches inside the view (proposals span the whole fisheye; the view shows a part of it).
  std::vector<PreviewPane::Overlay> lines;
  const QRectF inside(-2.5, -2.5, p.view.width + 4, p.view.height + 4);
  for (std::size_t i = 0; i < picked.size(); ++i) {
    const bool sel = static_cast<int>(i) == selected_;
    const auto flush = [&](QPolygonF& q) {
      if (!q.isEmpty()) lines.push_back({q, colour_of(i), false, picked[i].size() < 25 || sel, sel ? 4.0 : 2.0});
      q.clear();
    };
    QPolygonF q;
    for (const auto& s : picked[i]) {
      const auto o = vision::view_pixel_of(p.lens, p.view, s);
      if (o && inside.contains(QPointF(o->x, o->y)))
        q << QPointF(o->x, o->y);
      else
        flush(q);
    }
    flush(q);
  }
  output_pane_->set_overlays(lines);
}

void ReprojectionTuner::request_preview() {
  ++requested_;
  if (fisheye_.empty()) return;
  if (running_) {
    pending_ = true;  // only the newest request runs next; the ones in between are dropped
    return;
  }
  start_job();
}

void ReprojectionTuner::start_job() {
  pending_ = false;
  running_ = true;
  const quint64 generation = requested_;
  const vision::TunerParams p = state_.params();
  const cv::Mat src = fisheye_;
  // One job at a time, so the job may reuse the map and image buffers: fresh 10 MB buffers per change cost more
  // than the map maths (fast_map.h).
  const auto buffers = buffers_;
  watcher_->setFuture(QtConcurrent::run([generation, p, src, buffers] {
    Result r;
    r.generation = generation;
    QElapsedTimer t;
    t.start();
    try {
      vision::build_reprojection_map_coarse(p.lens, p.view, buffers->map, kCoarseStep);
      cv::remap(src, buffers->image, buffers->map, cv::noArray(), cv::INTER_LINEAR, cv::BORDER_CONSTANT,
                cv::Scalar(64, 64, 64));
      if (!p.masks.empty()) {
        // Masked source pixels (the robot's own body) are blanked in the view, as vision::reproject does.
        cv::Mat masked;
        cv::remap(vision::mask_image(p.masks, src.size()), masked, buffers->map, cv::noArray(), cv::INTER_NEAREST);
        buffers->image.setTo(cv::Scalar(64, 64, 64), masked);
      }
      r.image = to_qimage(buffers->image);
    } catch (const std::exception& e) {
      r.error = QString::fromStdString(e.what());
    }
    r.ms = static_cast<double>(t.nsecsElapsed()) / 1e6;
    return r;
  }));
}

void ReprojectionTuner::job_finished() {
  running_ = false;
  const Result r = watcher_->result();
  shown_ = r.generation;
  if (r.error.isEmpty()) {
    output_pane_->set_image(r.image);
    output_pane_->set_caption(tr("%1×%2 px rectilinear, %3° FOV · map (coarse grid, step %4 px) + remap %5 ms")
                                  .arg(r.image.width())
                                  .arg(r.image.height())
                                  .arg(state_.params().view.fov_deg, 0, 'f', 1)
                                  .arg(kCoarseStep)
                                  .arg(r.ms, 0, 'f', 1));
    // A Detect circle warning stays until the next detection: the preview it caused must not wipe it.
    status_->setText(circle_warning_.isEmpty()
                         ? QString()
                         : "<span style='color:#b00020'>" + circle_warning_.toHtmlEscaped() + "</span>");
  } else {
    status_->setText(tr("Invalid parameters: %1").arg(r.error));
  }
  if (pending_) start_job();
  emit preview_updated();
}

void ReprojectionTuner::apply_lens(const vision::Lens& lens, const std::string& what) {
  state_.end_merge();
  change(what, [&lens](auto& p) { p.lens = lens; });
  state_.end_merge();
}

std::optional<vision::ImageCircle> ReprojectionTuner::auto_calibrate() {
  if (fisheye_.empty()) return std::nullopt;
  circle_ = vision::detect_image_circle(fisheye_);
  if (!circle_) {
    update_overlays();
    return std::nullopt;
  }
  state_.end_merge();
  change("auto-calibrate", [this](auto& p) { p.lens = vision::propose_lens(p.lens, *circle_, circle_fov_->value()); });
  state_.end_merge();
  update_overlays();
  QString text = tr("Image circle: centre (%1, %2) px, radius %3 px, fit RMS %4 px over %5 edge points")
                     .arg(circle_->centre.x, 0, 'f', 1)
                     .arg(circle_->centre.y, 0, 'f', 1)
                     .arg(circle_->radius, 0, 'f', 1)
                     .arg(circle_->rms_px, 0, 'f', 2)
                     .arg(circle_->edge_points);
  // Issue #32.6: a recorded lens is evidence too; a proposal far from it says so, with both values.
  circle_warning_.clear();
  if (reference_ && reference_->r_pp > 0) {
    const double proposed = state_.params().lens.r_pp, recorded = reference_->r_pp;
    const double off = std::abs(proposed - recorded) / recorded;
    if (off > kCircleTolerance)
      circle_warning_ =
          tr("⚠ Detect circle proposes r_pp = %1 rad/px, the lens %2 has %3 rad/px (%4 % apart). The visible disc "
             "may span less than the lens FOV (%5°): enter the angle it spans under “Circle spans” and detect again, "
             "or Ctrl+Z to keep the recorded lens.")
              .arg(proposed, 0, 'f', 7)
              .arg(reference_source_)
              .arg(recorded, 0, 'f', 7)
              .arg(off * 100, 0, 'f', 1)
              .arg(state_.params().lens.fov_deg, 0, 'g', 4);
  }
  // Issue #43.8: a checkerboard lens's own field-of-view circle against the rim this frame shows, with both numbers.
  if (reference_ && reference_->calibration.method == vision::LensCalibration::Method::Checkerboard)
    if (const auto rim = vision::compare_with_rim(*reference_, *circle_); rim && rim->disagrees)
      circle_warning_ += (circle_warning_.isEmpty() ? QString() : QStringLiteral(" ")) +
                         tr("⚠ The calibrated lens %1: %2.").arg(reference_source_, QString::fromStdString(rim->text));
  status_->setText(circle_warning_.isEmpty()
                       ? text
                       : text + "<br><span style='color:#b00020'>" + circle_warning_.toHtmlEscaped() + "</span>");
  return circle_;
}

void ReprojectionTuner::set_reference_lens(const std::optional<vision::Lens>& lens, const QString& source) {
  reference_ = lens;
  reference_source_ = source;
  circle_warning_.clear();
}

QString ReprojectionTuner::status_text() const { return status_->text(); }

bool ReprojectionTuner::add_line_point(QPointF p) {
  const auto& s = state_.params();
  const auto src = vision::source_of(s.lens, s.view, p.x(), p.y());
  if (!src) return false;
  add_source_point(*src);
  return true;
}

void ReprojectionTuner::add_source_point(const cv::Point2d& source_px) {
  auto lines = state_.lines();
  if (lines.empty() || new_line_pending_) lines.emplace_back();
  new_line_pending_ = false;
  lines.back().push_back(source_px);
  set_lines(std::move(lines), "line point");
}

void ReprojectionTuner::set_lines(std::vector<vision::PickedLine> lines, const std::string& what) {
  state_.end_merge();  // every line edit is its own step
  const bool changed = state_.set_lines(lines, what);
  state_.end_merge();
  if (changed) state_changed();
}

void ReprojectionTuner::lines_changed() {
  update_overlays();
  line_label_->setText(line_residual_text());
  line_fit_label_->setText(lines_summary_text());
  update_lines_list();
}

void ReprojectionTuner::update_lines_list() {
  const auto& lines = state_.lines();
  const auto& lens = state_.params().lens;
  syncing_ = true;
  while (lines_list_->count() > static_cast<int>(lines.size())) delete lines_list_->takeItem(lines_list_->count() - 1);
  for (std::size_t i = 0; i < lines.size(); ++i) {
    double length = 0;
    for (std::size_t k = 1; k < lines[i].size(); ++k) length += cv::norm(lines[i][k] - lines[i][k - 1]);
    QString text = tr("%1: %2 points, %3 px").arg(i + 1).arg(lines[i].size()).arg(length, 0, 'f', 0);
    if (lines[i].size() >= 3) {
      try {
        text += tr(", RMS %1 px").arg(vision::line_straightness(lens, {lines[i]}).rms_px, 0, 'f', 2);
      } catch (const std::exception&) {
        text += tr(", no ray under this lens");
      }
    }
    if (std::find(left_out_.begin(), left_out_.end(), lines[i]) != left_out_.end())
      text += tr(" (left out by the fit)");
    if (static_cast<int>(i) < lines_list_->count())
      lines_list_->item(static_cast<int>(i))->setText(text);
    else
      lines_list_->addItem(text);
  }
  lines_list_->setCurrentRow(selected_);
  syncing_ = false;
  delete_line_button_->setEnabled(selected_ >= 0);
}

int ReprojectionTuner::line_near(const std::vector<QPolygonF>& curves, QPointF p, double tol) const {
  int best = -1;
  double best_d = tol;
  for (std::size_t i = 0; i < curves.size(); ++i)
    for (int k = 0; k < curves[i].size(); ++k) {
      // Distance to the segment from point k to k + 1 (or to the point alone at the end).
      const QPointF a = curves[i][k], b = k + 1 < curves[i].size() ? curves[i][k + 1] : a;
      const QPointF d = b - a;
      const double l2 = QPointF::dotProduct(d, d);
      const double t = l2 > 0 ? std::clamp(QPointF::dotProduct(p - a, d) / l2, 0.0, 1.0) : 0.0;
      const QPointF c = a + t * d - p;
      const double dist = std::hypot(c.x(), c.y());
      if (dist < best_d) best_d = dist, best = static_cast<int>(i);
    }
  return best;
}

void ReprojectionTuner::select_line(int index) {
  if (index < -1 || index >= static_cast<int>(state_.lines().size())) index = -1;
  selected_ = index;
  update_overlays();
  update_lines_list();
}

bool ReprojectionTuner::delete_selected_line() {
  if (selected_ < 0 || selected_ >= static_cast<int>(state_.lines().size())) return false;
  auto lines = state_.lines();
  lines.erase(lines.begin() + selected_);
  const int next = std::min(selected_, static_cast<int>(lines.size()) - 1);
  selected_ = -1;
  set_lines(std::move(lines), "delete line");
  select_line(next);
  status_->setText(tr("Line deleted (Ctrl+Z brings it back)."));
  return true;
}

int ReprojectionTuner::propose_lines() {
  if (fisheye_.empty()) {
    status_->setText(tr("No fisheye frame to propose lines in."));
    return 0;
  }
  const auto& lens = state_.params().lens;
  vision::LineProposals proposals;
  QElapsedTimer t;
  t.start();
  try {
    QGuiApplication::setOverrideCursor(Qt::WaitCursor);
    proposals = vision::propose_lines(fisheye_, lens);
    QGuiApplication::restoreOverrideCursor();
  } catch (const std::exception& e) {
    QGuiApplication::restoreOverrideCursor();
    status_->setText(tr("Propose lines: %1").arg(QString::fromStdString(e.what())));
    return 0;
  }
  const auto found = vision::proposal_points(proposals);
  const auto fresh = vision::lines_not_in(found, state_.lines());
  auto lines = state_.lines();
  lines.insert(lines.end(), fresh.begin(), fresh.end());
  new_line_pending_ = true;  // clicks after this start a line of their own
  set_lines(std::move(lines), "propose lines");
  status_->setText(tr("Proposed %1 line(s) in %2 ms (%3 already picked; %4 edges rejected as bent, %5 as short "
                      "or rough). Delete any that is not straight in the world; Ctrl+Z takes them all back.")
                       .arg(fresh.size())
                       .arg(static_cast<double>(t.nsecsElapsed()) / 1e6, 0, 'f', 0)
                       .arg(found.size() - fresh.size())
                       .arg(proposals.rejected_bent)
                       .arg(proposals.rejected_short));
  return static_cast<int>(fresh.size());
}

QString ReprojectionTuner::lines_summary_text() const {
  int usable = 0;
  for (const auto& l : state_.lines()) usable += l.size() >= 3;
  if (usable == 0) return tr("Line fit: pick 3 or more lines (3+ points each), then fit");
  try {
    const auto s = vision::line_straightness(state_.params().lens, state_.lines());
    return tr("Line fit: %1 line(s), %2 points; straightness RMS %3 px, max %4 px with this lens%5")
        .arg(s.lines)
        .arg(s.points)
        .arg(s.rms_px, 0, 'f', 2)
        .arg(s.max_px, 0, 'f', 2)
        .arg(usable < 3 ? tr(" (3 lines needed to fit)") : QString());
  } catch (const std::exception& e) {
    return tr("Line fit: %1").arg(QString::fromStdString(e.what()));
  }
}

void ReprojectionTuner::new_line() {
  if (state_.lines().empty()) return;  // the first click starts one anyway
  new_line_pending_ = true;
  update_overlays();
  line_label_->setText(line_residual_text());
}

void ReprojectionTuner::clear_line_points() {
  new_line_pending_ = false;
  selected_ = -1;
  set_lines({}, "clear lines");
}

void ReprojectionTuner::set_picked_lines(std::vector<vision::PickedLine> lines) {
  new_line_pending_ = false;
  selected_ = -1;
  set_lines(std::move(lines), "load lines");
}

vision::LineFitResult ReprojectionTuner::fit_lens_to_lines() {
  vision::LineFitOptions options;
  options.fixed[1] = options.fixed[2] = !fit_centre_->isChecked();
  options.reject_lines = reject_lines_->isChecked() ? 3 : 0;
  const auto& lines = state_.lines();
  const vision::LineFitResult fit = vision::fit_lens_to_lines(state_.params().lens, lines, options);
  left_out_.clear();
  for (const int i : fit.rejected_lines) left_out_.push_back(lines[static_cast<std::size_t>(i)]);
  state_.end_merge();
  change("line fit", [&fit](auto& p) { p.lens = fit.lens; });
  state_.end_merge();
  const auto& lens = state_.params().lens;
  line_fit_text_ = tr("Line fit over %1 lines, %2 points: straightness RMS %3 px before → %4 px after (max %5 → %6 "
                      "px); Kannala-Brandt k = (%7, %8, %9, %10), image circle rim r = %11 px held (Detect circle "
                      "measures it).%12 Ctrl+Z undoes it.")
                       .arg(fit.after.lines)
                       .arg(fit.after.points)
                       .arg(fit.before.rms_px, 0, 'f', 2)
                       .arg(fit.after.rms_px, 0, 'f', 2)
                       .arg(fit.before.max_px, 0, 'f', 2)
                       .arg(fit.after.max_px, 0, 'f', 2)
                       .arg(fit.lens.k[0], 0, 'g', 3)
                       .arg(fit.lens.k[1], 0, 'g', 3)
                       .arg(fit.lens.k[2], 0, 'g', 3)
                       .arg(fit.lens.k[3], 0, 'g', 3)
                       .arg(lens.radius(lens.fov_deg * kPi / 360).value_or(0), 0, 'f', 1)
                       .arg(fit.rejected_lines.empty()
                                ? QString()
                                : tr(" %1 line(s) left out as outliers (red).").arg(fit.rejected_lines.size()));
  line_fit_label_->setText(line_fit_text_);
  lines_changed();
  line_label_->setText(line_residual_text());
  return fit;
}

QString ReprojectionTuner::line_residual_text() const {
  // The current line as the current lens maps it into the view.
  std::vector<cv::Point2d> pts;
  const auto& s = state_.params();
  if (!state_.lines().empty() && !new_line_pending_)
    for (const auto& src : state_.lines().back())
      if (const auto o = vision::view_pixel_of(s.lens, s.view, src)) pts.push_back(*o);
  if (pts.size() < 3) return tr("Line residual: click %1 more point(s)").arg(3 - static_cast<int>(pts.size()));
  try {
    const auto r = vision::line_residual(pts);
    return tr("Line residual: RMS %1 px, max %2 px (n = %3)")
        .arg(r.rms_px, 0, 'f', 2)
        .arg(r.max_px, 0, 'f', 2)
        .arg(r.points);
  } catch (const std::exception& e) {
    return tr("Line residual: %1").arg(QString::fromStdString(e.what()));
  }
}

void ReprojectionTuner::set_mask_editing(bool on) {
  if (mask_button_->isChecked() != on) mask_button_->setChecked(on);  // re-enters through toggled
  if (mask_editing_ == on) return;
  mask_editing_ = on;
  if (!on) finish_mask();
}

void ReprojectionTuner::add_mask_point(QPointF p) {
  editing_mask_.emplace_back(static_cast<float>(p.x()), static_cast<float>(p.y()));
  update_overlays();
}

void ReprojectionTuner::finish_mask() {
  if (editing_mask_.size() >= 3) {
    const auto poly = editing_mask_;
    state_.end_merge();
    change("mask", [poly](auto& p) { p.masks.push_back(poly); });
    state_.end_merge();
  }
  editing_mask_.clear();
  update_overlays();
}

void ReprojectionTuner::clear_masks() {
  editing_mask_.clear();
  state_.end_merge();
  change("clear masks", [](auto& p) { p.masks.clear(); });
  update_overlays();
}

void ReprojectionTuner::save_json(const QString& path) const {
  vision::save_tuner_json(state_.params(), path.toStdString());
}

void ReprojectionTuner::load_json(const QString& path) {
  const vision::TunerParams p = vision::load_tuner_json(path.toStdString());
  state_.end_merge();
  if (state_.set(p, "load")) state_changed();  // undoable, like any other change
  state_.end_merge();
}

void ReprojectionTuner::export_lut(const QString& path) const {
  const auto& p = state_.params();
  vision::export_lut(vision::build_reprojection_map(p.lens, p.view), p, path.toStdString());
}

}  // namespace bs::ui
