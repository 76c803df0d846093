// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The main window's "Lens" tab: the reprojection tuner beside the 3D lens view, fed with one fisheye frame.
// The 3D view (VTK, OpenGL) is created when the tab is first shown and only where the platform can host an
// OpenGL widget (not under QT_QPA_PLATFORM=offscreen, where a placeholder says why).
#include <QWidget>

#include <opencv2/core.hpp>

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
  ReprojectionTuner* tuner() const { return tuner_; }
  LensView3D* view_3d() const { return view3d_; }  // null until the tab has been shown on a GL-capable platform
  LensView3D* ensure_view_3d();
  // "Calibrate from checkerboard…": the dialog, opened non-modally; its Apply sets the tuner's lens (one undo step).
  CheckerboardDialog* open_checkerboard_dialog();

 protected:
  void showEvent(QShowEvent* event) override;

 private:
  void apply_fisheye(const cv::Mat& bgr, const QString& caption);
  ReprojectionTuner* tuner_;
  bool rendering_ = false;
  LensView3D* view3d_ = nullptr;
  QSplitter* split_;
  QWidget* placeholder_;
};

// A synthetic fisheye frame of the paper's lens (1280x1024, 195 degrees) showing the test chart.
cv::Mat synthetic_fisheye();

}  // namespace bs::ui
