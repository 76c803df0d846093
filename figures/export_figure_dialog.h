// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Asks how to export a figure: journal size preset (LNCS, IEEE single/double column) or custom mm, font and line
// sizes in pt, PNG dpi and the formats. Remembers the last choice (QSettings).
#include <QDialog>

#include "paper_figures.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLineEdit;

namespace bs::ui {

class ExportFigureDialog : public QDialog {
  Q_OBJECT
 public:
  // `target` names what is written: a file stem ("flops" -> flops.pdf, flops.png) or a folder (paper figures).
  enum class Target { FileStem, Folder };
  ExportFigureDialog(Target target, const QString& suggested, QWidget* parent = nullptr);

  FigureOptions options() const;
  QString destination() const;  // file stem without extension, or folder
  void set_destination(const QString& path);
  void set_preset(const QString& id);  // "lncs", "lncs-half", "ieee", "ieee-double", "custom"

 private:
  void preset_changed();
  void save_settings() const;
  Target target_;
  QComboBox* preset_;
  QDoubleSpinBox *width_, *height_, *font_, *line_;
  QComboBox* dpi_;
  QCheckBox *pdf_, *svg_, *png_;
  QLineEdit* path_;
};

}  // namespace bs::ui
