// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/lens_tab.h"

#include <QFutureWatcher>
#include <QGuiApplication>
#include <QLabel>
#include <QSplitter>
#include <QTextDocument>
#include <QToolBar>
#include <QVBoxLayout>
#include <QtConcurrent>
#include <nlohmann/json.hpp>

#include "vision/checkerboard_dialog.h"
#include "vision/frames/synthetic.h"
#include "vision/lens_view_3d.h"
#include "vision/reprojection_tuner.h"

namespace bs::ui {

cv::Mat synthetic_fisheye() { return vision::render_fisheye(vision::Lens::paper()); }

LensTab::LensTab(QWidget* parent)
    : QWidget(parent), tuner_(new ReprojectionTuner), split_(new QSplitter), header_(new QLabel) {
  placeholder_ = new QLabel(tr("The 3D lens view needs an OpenGL display (it is not available on the '%1' platform).")
                                .arg(QGuiApplication::platformName()));
  static_cast<QLabel*>(placeholder_)->setWordWrap(true);
  static_cast<QLabel*>(placeholder_)->setAlignment(Qt::AlignCenter);
  tuner_->tool_bar()->addSeparator();
  tuner_->tool_bar()
      ->addAction(tr("Calibrate from checkerboard…"), this, [this] { open_checkerboard_dialog(); })
      ->setToolTip(tr("Fit the lens to photos of a printed checkerboard (OpenCV's fisheye calibration)"));
  tuner_->tool_bar()->addSeparator();
  save_frame_ =
      tuner_->tool_bar()->addAction(tr("Save lens for this frame"), this, [this] { emit save_requested(false); });
  save_frame_->setToolTip(tr("Keep this lens in the workspace for the frame being tuned (Edit > Undo takes it back)"));
  save_camera_ = tuner_->tool_bar()->addAction(tr("Save for camera"), this, [this] { emit save_requested(true); });
  save_camera_->setToolTip(
      tr("Keep this lens in the workspace for every frame of this camera (same size and mosaic) that has no lens "
         "of its own"));
  save_frame_->setEnabled(false);
  save_camera_->setEnabled(false);
  header_->setWordWrap(true);
  header_->setTextFormat(Qt::RichText);
  connect(tuner_, &ReprojectionTuner::lens_changed, this, [this] { update_header(); });
  split_->addWidget(tuner_);
  split_->addWidget(placeholder_);
  split_->setStretchFactor(0, 3);
  split_->setStretchFactor(1, 2);
  auto* lay = new QVBoxLayout(this);
  lay->setContentsMargins(0, 0, 0, 0);
  lay->addWidget(header_);
  lay->addWidget(split_, 1);
  update_header();
}

void LensTab::set_frame(std::int64_t frame_id, const QString& label, const cv::Mat& bgr,
                        const vision::ResolvedLens& lens) {
  frame_id_ = 0;  // while the image changes, no view takes the tuner's half-set lens for this frame's
  apply_fisheye(bgr, label);
  frame_id_ = frame_id;
  frame_label_ = label;
  lens_ = lens;
  // The baseline first: the views told of the new lens below name it as the frame's, not as an unsaved tuning.
  baseline_json_ = vision::lens_to_json(lens.lens, lens.view).dump();
  vision::TunerParams p = tuner_->params();
  p.lens = lens.lens;
  p.view = lens.view;
  tuner_->set_params(p);  // the frame's lens is the baseline Reset returns to
  // Detect circle compares with the lens the frame has, unless that is only the paper's default.
  tuner_->set_reference_lens(
      lens.source == vision::ResolvedLens::Source::Paper ? std::nullopt : std::optional<vision::Lens>(lens.lens),
      QString::fromStdString(vision::describe_lens_source(lens)));
  if (view3d_) view3d_->set_lens(tuner_->params().lens, tuner_->params().view);
  update_header();
}

void LensTab::clear_frame() {
  if (frame_id_ == 0) return;
  frame_id_ = 0;
  frame_label_.clear();
  lens_ = {};
  baseline_json_.clear();
  tuner_->set_reference_lens(std::nullopt, {});
  tuner_->set_params(vision::TunerParams{});
  set_fisheye({}, {});
  update_header();
}

std::string LensTab::params_json() const {
  return vision::lens_to_json(tuner_->params().lens, tuner_->params().view).dump();
}

bool LensTab::tunes(std::int64_t id, const vision::ResolvedLens& lens) const {
  return frame_id_ == id && lens_.source == lens.source &&
         baseline_json_ == vision::lens_to_json(lens.lens, lens.view).dump();
}

bool LensTab::has_unsaved_lens() const { return frame_id_ > 0 && params_json() != baseline_json_; }

void LensTab::mark_saved(vision::ResolvedLens::Source where) {
  lens_.lens = tuner_->params().lens;
  lens_.view = tuner_->params().view;
  lens_.source = where;
  baseline_json_ = params_json();
  tuner_->set_reference_lens(lens_.lens, QString::fromStdString(vision::describe_lens_source(lens_)));
  update_header();
}

void LensTab::update_header() {
  const bool frame = frame_id_ > 0;
  save_frame_->setEnabled(frame);
  save_camera_->setEnabled(frame);
  QString source;
  if (!frame) {
    source = tr("not a workspace frame: nothing is saved");
    header_->setText(tr("Tuning <b>%1</b> — %2. Select a frame (Frames tab or workspace tree) to tune its lens.")
                         .arg(tuner_->fisheye().empty() ? tr("nothing yet") : tr("a synthetic fisheye"), source));
  } else {
    const bool unsaved = has_unsaved_lens();
    source = unsaved ? tr("tuned in the Lens tab, not saved (was: %1)")
                           .arg(QString::fromStdString(vision::describe_lens_source(lens_)))
                     : QString::fromStdString(vision::describe_lens_source(lens_));
    header_->setText(tr("Tuning frame <b>%1</b> (camera %2) — lens: %3%4")
                         .arg(frame_label_.toHtmlEscaped(), QString::fromStdString(lens_.camera).toHtmlEscaped(),
                              source.toHtmlEscaped(),
                              unsaved ? tr(" — <span style='color:#b00'>● unsaved: Save lens for this frame or "
                                           "camera keeps it</span>")
                                      : QString()));
  }
  source_ = source;
  emit lens_source_changed(source);
}

QString LensTab::header_text() const {
  QTextDocument doc;
  doc.setHtml(header_->text());
  return doc.toPlainText();
}

namespace {

QString synthetic_caption() {
  return QObject::tr(
      "synthetic fisheye: the paper's lens (195°, 1280×1024) seeing the test chart (no frames in "
      "the workspace)");
}

}  // namespace

void LensTab::set_fisheye(const cv::Mat& bgr, const QString& caption) {
  if (bgr.empty())
    apply_fisheye(synthetic_fisheye(), synthetic_caption());
  else
    apply_fisheye(bgr, caption);
}

void LensTab::apply_fisheye(const cv::Mat& bgr, const QString& caption) {
  tuner_->set_fisheye(bgr, caption);
  if (view3d_) {
    view3d_->set_fisheye(tuner_->fisheye());
    view3d_->set_lens(tuner_->params().lens, tuner_->params().view);
  }
}

LensView3D* LensTab::ensure_view_3d() {
  if (view3d_) return view3d_;
  if (QGuiApplication::platformName() == "offscreen" || QGuiApplication::platformName() == "minimal") return nullptr;
  view3d_ = new LensView3D;
  split_->replaceWidget(1, view3d_);
  split_->setSizes({width() * 3 / 5, width() * 2 / 5});
  placeholder_->deleteLater();
  placeholder_ = nullptr;
  view3d_->set_fisheye(tuner_->fisheye());
  view3d_->set_lens(tuner_->params().lens, tuner_->params().view);
  connect(tuner_, &ReprojectionTuner::lens_changed, view3d_, &LensView3D::set_lens);
  return view3d_;
}

CheckerboardDialog* LensTab::open_checkerboard_dialog() {
  auto* dialog = new CheckerboardDialog(tuner_->params(), this);
  dialog->setAttribute(Qt::WA_DeleteOnClose);
  connect(dialog, &CheckerboardDialog::apply_requested, this,
          [this](const vision::Lens& lens) { tuner_->apply_lens(lens, "checkerboard calibration"); });
  dialog->show();
  return dialog;
}

void LensTab::showEvent(QShowEvent* event) {
  QWidget::showEvent(event);
  ensure_view_3d();
  if (tuner_->fisheye().empty() && !rendering_) {
    // Nothing to tune on yet: render the synthetic frame off the GUI thread (about a second on this machine).
    rendering_ = true;
    auto* watcher = new QFutureWatcher<cv::Mat>(this);
    connect(watcher, &QFutureWatcher<cv::Mat>::finished, this, [this, watcher] {
      rendering_ = false;
      if (tuner_->fisheye().empty()) apply_fisheye(watcher->result(), synthetic_caption());
      watcher->deleteLater();
    });
    watcher->setFuture(QtConcurrent::run(synthetic_fisheye));
  }
}

}  // namespace bs::ui
