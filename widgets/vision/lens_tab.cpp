// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/lens_tab.h"

#include <QFutureWatcher>
#include <QGuiApplication>
#include <QLabel>
#include <QSplitter>
#include <QToolBar>
#include <QVBoxLayout>
#include <QtConcurrent>

#include "vision/checkerboard_dialog.h"
#include "vision/frames/synthetic.h"
#include "vision/lens_view_3d.h"
#include "vision/reprojection_tuner.h"

namespace bs::ui {

cv::Mat synthetic_fisheye() { return vision::render_fisheye(vision::Lens::paper()); }

LensTab::LensTab(QWidget* parent) : QWidget(parent), tuner_(new ReprojectionTuner), split_(new QSplitter) {
  placeholder_ = new QLabel(tr("The 3D lens view needs an OpenGL display (it is not available on the '%1' platform).")
                                .arg(QGuiApplication::platformName()));
  static_cast<QLabel*>(placeholder_)->setWordWrap(true);
  static_cast<QLabel*>(placeholder_)->setAlignment(Qt::AlignCenter);
  tuner_->tool_bar()->addSeparator();
  tuner_->tool_bar()
      ->addAction(tr("Calibrate from checkerboard…"), this, [this] { open_checkerboard_dialog(); })
      ->setToolTip(tr("Fit the lens to photos of a printed checkerboard (OpenCV's fisheye calibration)"));
  split_->addWidget(tuner_);
  split_->addWidget(placeholder_);
  split_->setStretchFactor(0, 3);
  split_->setStretchFactor(1, 2);
  auto* lay = new QVBoxLayout(this);
  lay->setContentsMargins(0, 0, 0, 0);
  lay->addWidget(split_);
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
