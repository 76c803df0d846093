// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The paper's Figure 3 as a live view: (a) the raw Bayer mosaic as grey, (b) demosaiced, (c) reprojected to a
// rectilinear view, side by side. Zoom (wheel) and pan (drag) move all three panes together; the pixel inspector
// shows, for the point under the cursor in any pane, the raw sample, the demosaiced colour, and the fisheye and
// output coordinates (output -> fisheye through core's source_of, fisheye -> output through output_of), with a
// cross-hair at the linked point in the other panes. 16-bit captures are shown through a window/level.
// Demosaicing and reprojection run off the GUI thread (QtConcurrent); the newest request wins.
#include <QFutureWatcher>
#include <QWidget>
#include <array>
#include <memory>
#include <optional>

#include <opencv2/core.hpp>

#include "model/frame.h"
#include "util/cancel.h"
#include "vision/demosaic/bayer.h"
#include "vision/lens/lens.h"
#include "vision/reproject/triptych.h"
#include "vision/workspace_lens.h"

class QCheckBox;
class QComboBox;
class QLabel;
class QPushButton;
class QSpinBox;

namespace bs::ui {

class ImagePane;

// What the inspector reports for one cursor position.
struct PixelInspection {
  std::optional<cv::Point> fisheye;                        // source pixel (column, row) in the capture
  std::optional<cv::Point> output;                         // pixel (column, row) in the reprojected view
  std::optional<cv::Point2d> fisheye_exact, output_exact;  // before rounding to a pixel
  int raw = -1;                                            // the recorded sample at `fisheye`, in counts
  char channel = '?';                    // which colour the sensor measures there: 'R', 'G', 'B', or 'Y' (grey)
  std::optional<cv::Vec3i> fisheye_rgb;  // demosaiced colour at `fisheye` (R, G, B), counts
  std::optional<cv::Vec3i> output_rgb;   // reprojected colour at `output` (R, G, B), counts
};

class FrameTriptych : public QWidget {
  Q_OBJECT
 public:
  explicit FrameTriptych(QWidget* parent = nullptr);
  ~FrameTriptych() override;

  // Shows `frame` (pixels included) with the lens recorded with it (sidecar), else the paper's lens.
  void set_frame(const Frame& frame);
  // Shows `frame` with a lens resolved elsewhere (a lens saved in the workspace); the banner names its source.
  void set_frame(const Frame& frame, const vision::ResolvedLens& lens);
  void clear(const QString& message);
  // Drives the reprojection from outside (the reprojection tuner): the lens must have the frame's size.
  void set_lens(const vision::Lens& lens, const vision::View& view);
  // The same, naming where the lens comes from in the banner ("tuned in the Lens tab, not saved").
  void set_lens(const vision::Lens& lens, const vision::View& view, const QString& source);
  QString banner_text() const;  // what the banner says (plain text), for tests
  void set_demosaic_method(vision::DemosaicMethod method);
  void set_window(int low, int high);  // display window in counts (16-bit captures: e.g. 0..4095)
  void set_overlays_visible(bool on);
  void set_view(double zoom, QPointF centre);  // all panes

  const vision::Lens& lens() const { return lens_; }
  const vision::View& view() const { return view_; }
  vision::DemosaicMethod demosaic_method() const { return method_; }
  bool has_frame() const { return !raw_.empty(); }
  const Frame& frame() const { return frame_; }
  const vision::TriptychImages& images() const { return images_; }  // at full depth, as last rendered
  ImagePane* pane(int index) const { return panes_.at(static_cast<std::size_t>(index)); }
  QString inspector_text() const;
  // Waits (processing events) until no render is running or pending; false on timeout. For tests and export.
  bool wait_until_rendered(int timeout_ms);

  // The inspector's answer for an image point in pane 0/1 (fisheye coordinates) or 2 (output coordinates).
  PixelInspection inspect(int pane, QPointF image_point) const;

  // Inspects as if the cursor were at `image_point` of pane `pane`: updates the inspector text, the linked
  // cross-hairs and emits cursor_moved (what a mouse move does).
  void inspect_at(int pane, QPointF image_point) { show_inspection(pane, image_point); }

  // The captions of Figure 3's panels, (a) (b) (c) included.
  std::array<QString, 3> captions() const;
  // The three panels as shown (8-bit, window/level applied).
  std::array<QImage, 3> panel_images() const;

 signals:
  void cursor_moved(QPointF fisheye_px, QPointF output_px);  // (-1, -1) where the point has no counterpart
  void rendered();
  void render_failed(const QString& reason);

 private:
  struct Job;
  void request_render(bool demosaic_again);
  void start_job();
  void job_finished();
  void update_display();
  void update_overlays();
  void update_titles();
  void update_banner();
  void show_inspection(int pane, QPointF image_point);
  void sync_from(int pane, double zoom, QPointF centre);

  Frame frame_;  // without pixels (kept in raw_)
  cv::Mat raw_;
  vision::Lens lens_;
  vision::View view_;
  QString lens_source_;  // where lens_ comes from, for the banner
  vision::DemosaicMethod method_ = vision::DemosaicMethod::Bilinear;
  vision::TriptychImages images_;
  int window_low_ = 0, window_high_ = 255;
  bool overlays_ = true;

  std::array<ImagePane*, 3> panes_{};
  QComboBox* method_box_;
  QSpinBox* low_box_;
  QSpinBox* high_box_;
  QPushButton* full_range_;
  QCheckBox* overlay_box_;
  QLabel* banner_;
  QLabel* inspector_;

  QFutureWatcher<std::shared_ptr<Job>>* watcher_;
  std::shared_ptr<Job> running_;
  bool pending_ = false, pending_demosaic_ = false;
  std::uint64_t generation_ = 0;
};

}  // namespace bs::ui
