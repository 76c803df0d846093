// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Asks the geometry of a raw Bayer file that has no JSON sidecar: width, height, Bayer pattern, bits per sample and
// byte order. The file's size is checked live against the geometry (OK only when they agree), and the last answer
// is remembered (QSettings) for the next capture from the same camera.
#include <QDialog>

#include "frames/frame_raw.h"

class QComboBox;
class QLabel;
class QSpinBox;

namespace bs::ui {

class RawGeometryDialog : public QDialog {
  Q_OBJECT
 public:
  RawGeometryDialog(const QString& raw_path, QWidget* parent = nullptr);
  RawFrameOptions options() const;
  void set_options(const RawFrameOptions& o);
  bool matches_file() const;  // width x height x bytes per sample == the file's size

  // Remembered answer from the last accepted dialog, if any.
  static std::optional<RawFrameOptions> remembered();

 private:
  void update_check();
  qint64 file_size_;
  QSpinBox *width_, *height_;
  QComboBox *pattern_, *bits_, *endian_;
  QLabel* check_;
  QPushButton* ok_ = nullptr;
};

}  // namespace bs::ui
