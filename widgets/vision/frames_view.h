// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The Frames tab: the workspace's frames (label, size, pattern, bit depth, synthetic or captured, kept by
// reference or copied) on the left, the selected one in the frame triptych on the right.
#include <QWidget>
#include <vector>

#include "store/workspace.h"

class QListWidget;

namespace bs::ui {

class FrameTriptych;

class FramesView : public QWidget {
  Q_OBJECT
 public:
  explicit FramesView(QWidget* parent = nullptr);

  // Lists the frames of `ws` (nullptr: none) and shows the first. The workspace must outlive the next call.
  void set_workspace(const Workspace* ws);
  FrameTriptych* triptych() const { return triptych_; }
  QListWidget* list() const { return list_; }
  int frame_count() const { return static_cast<int>(frames_.size()); }
  void select(int index);
  // The frame shown (its workspace id), 0 when none; selecting by id returns false for an unknown id.
  std::int64_t current_frame_id() const;
  bool select_frame_id(std::int64_t id);
  const StoredFrame* current_frame() const;

 signals:
  void frame_selected(std::int64_t frame_id);

 public:
  // File > Export Figure 3: asks for a PNG or PDF path and writes the triptych as the paper's figure.
  void export_figure_dialog();
  bool export_figure(const QString& path, QString* error);

 private:
  void show_frame(int index);

  const Workspace* ws_ = nullptr;
  std::vector<StoredFrame> frames_;
  QListWidget* list_;
  FrameTriptych* triptych_;
};

}  // namespace bs::ui
