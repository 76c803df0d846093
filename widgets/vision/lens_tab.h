// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The main window's "Lens" tab: the reprojection tuner beside the 3D lens view, fed with one fisheye frame.
// The 3D view (VTK, OpenGL) is created when the tab is first shown and only where the platform can host an
// OpenGL widget (not under QT_QPA_PLATFORM=offscreen, where a placeholder says why).
#include <QWidget>
#include <cstdint>
#include <string>

#include <opencv2/core.hpp>

#include "vision/workspace_lens.h"

class QAction;
class QLabel;
class QSplitter;

namespace bs::ui {

class CheckerboardDialog;
class ReprojectionTuner;
class LensView3D;

class LensTab : public QWidget {
  Q_OBJECT
 public:
  explicit LensTab(QWidget* parent = nullptr);
  // The frame to tune on (8-bit BGR, e.g. a demosaiced capture); an empty image gets a synthetic fisheye of the
  // paper's lens (vision::render_fisheye), rendered here. Without a call, the first show renders that synthetic
  // frame in the background.
  void set_fisheye(const cv::Mat& bgr, const QString& caption);
  // Tunes a workspace frame (issue #32.1): `bgr` is its demosaiced image, `lens` the lens it has now (saved,
  // recorded or the paper's), which becomes the tuner's baseline. The header says which frame and which lens.
  void set_frame(std::int64_t frame_id, const QString& label, const cv::Mat& bgr, const vision::ResolvedLens& lens);
  // Forgets the workspace frame (another workspace opened): back to the synthetic fisheye of the paper's lens.
  void clear_frame();
  std::int64_t frame_id() const { return frame_id_; }  // 0: not a workspace frame (synthetic, or none)
  const QString& frame_label() const { return frame_label_; }
  const std::string& camera() const { return lens_.camera; }
  // The tuner's lens differs from the one the frame has in the workspace (it would be lost on quit).
  bool has_unsaved_lens() const;
  // Tunes frame `id` with `lens` as its baseline already (a reload need not start it again).
  bool tunes(std::int64_t id, const vision::ResolvedLens& lens) const;
  // After the window saved the tuner's lens: it becomes the frame's lens (the header says where it is saved).
  void mark_saved(vision::ResolvedLens::Source where);
  QString header_text() const;                            // plain text of the header, for tests
  const QString& lens_source() const { return source_; }  // "saved for this frame", "tuned …, not saved", …
  QAction* save_frame_action() const { return save_frame_; }
  QAction* save_camera_action() const { return save_camera_; }
  ReprojectionTuner* tuner() const { return tuner_; }
  LensView3D* view_3d() const { return view3d_; }  // null until the tab has been shown on a GL-capable platform
  LensView3D* ensure_view_3d();
  // "Calibrate from checkerboard…": the dialog, opened non-modally; its Apply sets the tuner's lens (one undo step).
  CheckerboardDialog* open_checkerboard_dialog();

 signals:
  // "Save lens for this frame / camera": the window stores the tuner's lens in the workspace (one undo step).
  void save_requested(bool for_camera);
  // The lens in the tuner or its saved state changed: `source` names it for the views that reprojects with it.
  void lens_source_changed(const QString& source);

 protected:
  void showEvent(QShowEvent* event) override;

 private:
  void apply_fisheye(const cv::Mat& bgr, const QString& caption);
  void update_header();
  std::string params_json() const;
  ReprojectionTuner* tuner_;
  bool rendering_ = false;
  LensView3D* view3d_ = nullptr;
  QSplitter* split_;
  QWidget* placeholder_;
  QLabel* header_;
  QAction* save_frame_;
  QAction* save_camera_;
  std::int64_t frame_id_ = 0;
  QString frame_label_;
  vision::ResolvedLens lens_;  // the frame's lens in the workspace (the baseline)
  QString source_;
  std::string baseline_json_;  // lens_ as tuner JSON: what "unsaved" compares against
};

// A synthetic fisheye frame of the paper's lens (1280x1024, 195 degrees) showing the test chart.
cv::Mat synthetic_fisheye();

}  // namespace bs::ui
