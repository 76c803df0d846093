// SPDX-License-Identifier: GPL-3.0-or-later
// The Frames and Lens tabs together: the Lens tab tunes on the workspace's capture, and the lens it tunes drives
// the Frames tab's reprojection, so a user sees the paper's Figure 3 change as they move a slider.
#include <QDirIterator>
#include <QFileInfo>
#include <QStatusBar>

#include "frames/frame_store.h"
#include "main_window.h"
#include "vision/frame_triptych.h"
#include "vision/frames/frame_image.h"
#include "vision/frames_view.h"
#include "vision/lens_tab.h"
#include "vision/raw_geometry_dialog.h"
#include "vision/reproject/triptych.h"
#include "vision/reprojection_tuner.h"

namespace bs::ui {

void MainWindow::connect_lens_and_frames() {
  connect(lens_->tuner(), &ReprojectionTuner::lens_changed, frames_->triptych(), &FrameTriptych::set_lens);
}

void MainWindow::feed_lens_tab() {
  if (!workspace_) return;
  const auto frames = workspace_->frames();
  if (frames.empty()) return;  // the tab keeps its synthetic fisheye of the paper's lens
  try {
    const Frame frame = load_frame(*workspace_, frames.front());
    const cv::Mat raw = vision::frame_to_mat(frame);
    const cv::Mat rgb = vision::demosaic_frame(raw, frame, vision::DemosaicMethod::Bilinear);
    lens_->set_fisheye(vision::window_to_8bit(rgb, 0, vision::full_scale(frame)), QString::fromStdString(frame.label));
  } catch (const std::exception& e) {
    statusBar()->showMessage(tr("Lens tab: cannot read the frame: %1").arg(QString::fromUtf8(e.what())), 10000);
  }
}

std::optional<RawFrameOptions> MainWindow::ask_raw_geometry(const QStringList& paths) {
  QString first;
  for (const QString& p : paths) {
    if (QFileInfo(p).isDir()) {
      QDirIterator it(p, {"*.raw"}, QDir::Files, QDirIterator::Subdirectories);
      while (first.isEmpty() && it.hasNext()) {
        const QString f = it.next();
        if (raw_without_sidecar(f.toStdString())) first = f;
      }
    } else if (raw_without_sidecar(p.toStdString())) {
      first = p;
    }
    if (!first.isEmpty()) break;
  }
  if (first.isEmpty()) return std::nullopt;
  RawGeometryDialog dialog(first, this);
  if (dialog.exec() != QDialog::Accepted) return std::nullopt;
  return dialog.options();
}

}  // namespace bs::ui
