// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Asks how to export a figure: journal size preset (LNCS, IEEE single/double column) or custom mm, font and line
// sizes in pt, PNG dpi and the formats. Remembers the last choice (QSettings).
#include <QDialog>
#include <QImage>
#include <functional>

#include "paper_figures.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QTimer;

namespace bs::ui {

class ExportFigureDialog : public QDialog {
  Q_OBJECT
 public:
  // `target` names what is written: a file stem ("flops" -> flops.pdf, flops.png) or a folder (paper figures).
  enum class Target { FileStem, Folder };
  ExportFigureDialog(Target target, const QString& suggested, QWidget* parent = nullptr);

  FigureOptions options() const;
  // Folder target (paper figures) only: paper data only, or everything ticked in the workspace.
  FigureDataChoice data_choice() const;
  QString destination() const;  // file stem without extension, or folder
  void set_destination(const QString& path);
  void set_preset(const QString& id);  // "lncs", "lncs-half", "ieee", "ieee-double", "custom"
  // Shows beside the fields what will be written, rendered by `render` at the options as they are (again shortly
  // after each change). Without it the dialog has no preview (the paper figures: several files).
  void set_preview(std::function<QImage(const FigureOptions&)> render);
  QLabel* preview_label() const { return preview_; }

 private:
  void preset_changed();
  void save_settings() const;
  Target target_;
  QComboBox* preset_;
  QDoubleSpinBox *width_, *height_, *font_, *line_;
  QComboBox* dpi_;
  QCheckBox *pdf_, *svg_, *png_;
  QLineEdit* path_;
  QComboBox* data_ = nullptr;
  QLabel* preview_ = nullptr;
  QTimer* preview_timer_ = nullptr;
  std::function<QImage(const FigureOptions&)> render_;
  void update_preview();
};

}  // namespace bs::ui
