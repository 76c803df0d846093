// SPDX-License-Identifier: GPL-3.0-or-later
// The Frames and Lens tabs together: the Lens tab tunes on the workspace's capture, and the lens it tunes drives
// the Frames tab's reprojection, so a user sees the paper's Figure 3 change as they move a slider.
#include <QDirIterator>
#include <QFileInfo>
#include <QItemSelectionModel>
#include <QMessageBox>
#include <QStatusBar>
#include <nlohmann/json.hpp>

#include "frames/frame_store.h"
#include "main_window.h"
#include "store/lens_store.h"
#include "vision/frame_triptych.h"
#include "vision/frames/frame_image.h"
#include "vision/frames_view.h"
#include "vision/lens_tab.h"
#include "vision/raw_geometry_dialog.h"
#include "vision/reproject/triptych.h"
#include "vision/reprojection_tuner.h"
#include "vision/workspace_lens.h"

namespace bs::ui {

void MainWindow::connect_lens_and_frames() {
  // The Frames tab shows the tuner's lens only while both show the same frame; the banner names it.
  connect(lens_->tuner(), &ReprojectionTuner::lens_changed, this,
          [this](const vision::Lens& lens, const vision::View& view) {
            if (lens_->frame_id() > 0 && lens_->frame_id() == frames_->current_frame_id())
              frames_->triptych()->set_lens(lens, view, lens_->lens_source());
          });
  // A frame selected anywhere (Frames tab, workspace tree) is the one the Lens tab tunes.
  connect(frames_, &FramesView::frame_selected, this, [this](std::int64_t id) { tune_frame(id); });
  connect(tree_->selectionModel(), &QItemSelectionModel::currentChanged, this, [this](const QModelIndex& index) {
    const TreeItemRef ref = tree_->ref_at(index);
    if (ref.kind == TreeItemRef::Kind::Frame) frames_->select_frame_id(ref.id);
  });
  connect(lens_, &LensTab::save_requested, this, &MainWindow::save_tuned_lens);
}

void MainWindow::feed_lens_tab() {
  // The Frames tab's frame (it told tune_frame already when it showed it; this covers a Frames tab that kept its
  // frame). Without frames the tab keeps its synthetic fisheye of the paper's lens.
  if (!workspace_ || frames_->frame_count() == 0) return;
  tune_frame(frames_->current_frame_id());
}

void MainWindow::tune_frame(std::int64_t frame_id) {
  if (!workspace_ || frame_id <= 0) return;
  // A lens being tuned on this frame and not saved yet is not thrown away by a reload.
  if (lens_->frame_id() == frame_id && lens_->has_unsaved_lens()) return;
  for (const StoredFrame& stored : workspace_->frames()) {
    if (stored.id != frame_id) continue;
    const vision::ResolvedLens lens = vision::resolve_frame_lens(workspace_.get(), stored);
    if (lens_->tunes(frame_id, lens)) return;  // a reload that changed nothing here keeps the tuner's history
    try {
      const Frame frame = load_frame(*workspace_, stored);
      const cv::Mat raw = vision::frame_to_mat(frame);
      const cv::Mat rgb = vision::demosaic_frame(raw, frame, vision::DemosaicMethod::Bilinear);
      lens_->set_frame(stored.id, QString::fromStdString(frame.label),
                       vision::window_to_8bit(rgb, 0, vision::full_scale(frame)), lens);
    } catch (const std::exception& e) {
      statusBar()->showMessage(tr("Lens tab: cannot read the frame: %1").arg(QString::fromUtf8(e.what())), 10000);
    }
    return;
  }
}

void MainWindow::save_tuned_lens(bool for_camera) {
  if (!workspace_ || lens_->frame_id() <= 0) return;
  Workspace* ws = workspace_.get();
  const vision::TunerParams& p = lens_->tuner()->params();
  SavedLens lens;
  lens.frame_id = for_camera ? 0 : lens_->frame_id();
  lens.camera = for_camera ? lens_->camera() : std::string();
  lens.lens_json = vision::lens_to_json(p.lens, p.view).dump();
  lens.obtained = vision::describe(p.lens.calibration);
  const std::optional<SavedLens> before = find_lens(*ws, lens.frame_id, lens.camera);
  std::function<void()> redo = [ws, lens] { save_lens(*ws, lens); };
  std::function<void()> undo = [ws, lens, before] {
    if (before)
      save_lens(*ws, *before);
    else
      remove_lens(*ws, lens.frame_id, lens.camera);
  };
  if (!try_edit(redo)) return;
  lens_->mark_saved(for_camera ? vision::ResolvedLens::Source::SavedForCamera
                               : vision::ResolvedLens::Source::SavedForFrame);
  const QString what = for_camera ? tr("save lens for camera %1").arg(QString::fromStdString(lens.camera))
                                  : tr("save lens for frame “%1”").arg(lens_->frame_label());
  push_edit(what, std::move(redo), std::move(undo));
}

bool MainWindow::has_unsaved_changes() const { return (lens_ && lens_->has_unsaved_lens()) || untitled_work_at_risk(); }

bool MainWindow::settle_unsaved_changes() {
  if (!has_unsaved_changes()) return true;
  // Save, Discard or Cancel, asked by a box (or by the test's prompt when one is set), for either thing unsaved.
  const auto ask = [this](const QString& title, const QString& text) {
    return unsaved_prompt_ ? unsaved_prompt_(text)
                           : QMessageBox::question(this, title, text,
                                                   QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel,
                                                   QMessageBox::Save);
  };
  if (untitled_work_at_risk()) {
    // An untitled workspace lives in a temporary folder that goes with it: what the user imported, measured or
    // edited there is lost unless saved under a name now.
    const QString text =
        tr("The untitled workspace holds your imports, runs or edits and is deleted when it closes. "
           "Save it as a workspace file?");
    const int answer = ask(tr("Unsaved workspace"), text);
    if (answer == QMessageBox::Cancel) return false;
    if (answer == QMessageBox::Save) {
      if (lens_ && lens_->has_unsaved_lens()) save_tuned_lens(false);  // into the workspace before it is copied
      save_as();
      return !untitled_dir_;  // the file dialog cancelled: nothing is lost, nothing closes
    }
    work_since_open_ = false;  // discarded, the tuned lens with it: asked once
    return true;
  }
  const QString text = tr("The lens tuned for frame “%1” is not saved in the workspace. Save it for this frame?")
                           .arg(lens_->frame_label());
  const int answer = ask(tr("Unsaved lens"), text);
  if (answer == QMessageBox::Cancel) return false;
  if (answer == QMessageBox::Save) save_tuned_lens(false);
  return true;
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
