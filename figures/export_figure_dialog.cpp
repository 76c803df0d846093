// SPDX-License-Identifier: GPL-3.0-or-later
#include "export_figure_dialog.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QFrame>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPixmap>
#include <QPushButton>
#include <QSettings>
#include <QTimer>

#include "report/figure_template.h"

namespace bs::ui {

ExportFigureDialog::ExportFigureDialog(Target target, const QString& suggested, QWidget* parent)
    : QDialog(parent), target_(target) {
  setWindowTitle(target == Target::Folder ? tr("Reproduce paper figures") : tr("Export figure"));
  // The fields on the left; set_preview() adds the preview on the right.
  auto* outer = new QHBoxLayout(this);
  auto* form = new QFormLayout;
  outer->addLayout(form);
  preset_ = new QComboBox;
  preset_->addItem(tr("LNCS text width (122 mm)"), "lncs");
  preset_->addItem(tr("LNCS half width (58 mm)"), "lncs-half");
  preset_->addItem(tr("IEEE single column (88.9 mm)"), "ieee");
  preset_->addItem(tr("IEEE double column (181 mm)"), "ieee-double");
  preset_->addItem(tr("Custom"), "custom");
  preset_->setToolTip(tr("Figure width of the journal's page layout"));
  form->addRow(tr("&Size"), preset_);
  const auto spin = [](double lo, double hi, double step, int decimals, const QString& suffix, const QString& tip) {
    auto* s = new QDoubleSpinBox;
    s->setRange(lo, hi);
    s->setSingleStep(step);
    s->setDecimals(decimals);
    s->setSuffix(suffix);
    s->setToolTip(tip);
    return s;
  };
  width_ = spin(20, 1000, 1, 1, tr(" mm"), tr("Figure width in millimetres"));
  height_ = spin(0, 1000, 1, 1, tr(" mm"),
                 tr("Figure height in millimetres; automatic: axes 0.62 x width plus the legend below them"));
  height_->setSpecialValueText(tr("automatic"));
  font_ = spin(4, 24, 0.5, 1, tr(" pt"), tr("Font size of labels and legend, as in the paper's body text (8 pt)"));
  line_ = spin(0.1, 5, 0.1, 2, tr(" pt"), tr("Line width of the data series"));
  form->addRow(tr("&Width"), width_);
  form->addRow(tr("&Height"), height_);
  form->addRow(tr("&Font size"), font_);
  form->addRow(tr("&Line width"), line_);
  dpi_ = new QComboBox;
  for (const int d : {150, 300, 600}) dpi_->addItem(tr("%1 dpi").arg(d), d);
  dpi_->setToolTip(tr("Resolution of the PNG; PDF and SVG are vector and keep text as text"));
  form->addRow(tr("PNG &resolution"), dpi_);
  auto* formats = new QHBoxLayout;
  pdf_ = new QCheckBox("PDF");
  svg_ = new QCheckBox("SVG");
  png_ = new QCheckBox("PNG");
  for (QCheckBox* c : {pdf_, svg_, png_}) formats->addWidget(c);
  form->addRow(tr("Formats"), formats);
  auto* where = new QHBoxLayout;
  path_ = new QLineEdit(suggested);
  path_->setToolTip(target == Target::Folder ? tr("Folder for the figures, tables and figures.json")
                                             : tr("File name without extension; one file per format is written"));
  auto* browse = new QPushButton(tr("&Browse…"));
  where->addWidget(path_, 1);
  where->addWidget(browse);
  auto* where_label = new QLabel(target == Target::Folder ? tr("F&older") : tr("F&ile"));
  where_label->setBuddy(path_);  // a row holding a layout gets no buddy by itself, and would show the '&'
  form->addRow(where_label, where);
  if (target == Target::Folder) {
    data_ = new QComboBox;
    data_->setObjectName(QStringLiteral("data"));
    data_->addItem(tr("Paper data only (reconstructed from the paper)"), static_cast<int>(FigureDataChoice::PaperOnly));
    data_->addItem(tr("Everything ticked in the workspace (measured runs too)"),
                   static_cast<int>(FigureDataChoice::All));
    data_->setToolTip(
        tr("What the figures show; figures.json records it, and the summary after the export lists "
           "what each figure contains and what it left out"));
    form->addRow(tr("&Data"), data_);
  }
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
  buttons->button(QDialogButtonBox::Ok)->setText(tr("&Export"));
  form->addRow(buttons);

  connect(browse, &QPushButton::clicked, this, [this] {
    const QString p = target_ == Target::Folder
                          ? QFileDialog::getExistingDirectory(this, tr("Folder for the figures"), path_->text())
                          : QFileDialog::getSaveFileName(this, tr("Export figure"), path_->text());
    if (!p.isEmpty()) set_destination(p);
  });
  connect(preset_, &QComboBox::currentIndexChanged, this, &ExportFigureDialog::preset_changed);
  connect(width_, &QDoubleSpinBox::valueChanged, this, [this] {
    if (const auto w = preset_width_mm(preset_->currentData().toString().toStdString()); w && *w != width_->value())
      preset_->setCurrentIndex(preset_->findData("custom"));
  });
  connect(buttons, &QDialogButtonBox::accepted, this, [this] {
    save_settings();
    accept();
  });
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  const auto validate = [this, buttons] {
    buttons->button(QDialogButtonBox::Ok)
        ->setEnabled((pdf_->isChecked() || svg_->isChecked() || png_->isChecked()) &&
                     !path_->text().trimmed().isEmpty());
  };
  for (QCheckBox* c : {pdf_, svg_, png_}) connect(c, &QCheckBox::toggled, this, validate);
  connect(path_, &QLineEdit::textChanged, this, validate);

  QSettings s;
  s.beginGroup("figure-export");
  font_->setValue(s.value("font_pt", 8.0).toDouble());
  line_->setValue(s.value("line_pt", 1.0).toDouble());
  height_->setValue(s.value("height_mm", 0.0).toDouble());
  dpi_->setCurrentIndex(std::max(0, dpi_->findData(s.value("dpi", 300).toInt())));
  pdf_->setChecked(s.value("pdf", true).toBool());
  svg_->setChecked(s.value("svg", false).toBool());
  png_->setChecked(s.value("png", true).toBool());
  const QString preset = s.value("preset", "lncs").toString();
  width_->setValue(s.value("width_mm", 122.0).toDouble());
  set_preset(preset);
  validate();
}

void ExportFigureDialog::set_preset(const QString& id) {
  const int i = preset_->findData(id);
  preset_->setCurrentIndex(i < 0 ? 0 : i);
  preset_changed();
}

void ExportFigureDialog::preset_changed() {
  if (const auto w = preset_width_mm(preset_->currentData().toString().toStdString())) width_->setValue(*w);
}

void ExportFigureDialog::set_destination(const QString& path) {
  QString p = path;
  for (const char* ext : {".pdf", ".svg", ".png"})
    if (p.endsWith(ext, Qt::CaseInsensitive)) p.chop(4);
  path_->setText(p);
}

QString ExportFigureDialog::destination() const { return path_->text().trimmed(); }

FigureOptions ExportFigureDialog::options() const {
  FigureOptions o;
  o.width_mm = width_->value();
  o.height_mm = height_->value();
  o.font_pt = font_->value();
  o.line_width_pt = line_->value();
  o.dpi = dpi_->currentData().toInt();
  o.formats.clear();
  if (pdf_->isChecked()) o.formats << "pdf";
  if (svg_->isChecked()) o.formats << "svg";
  if (png_->isChecked()) o.formats << "png";
  return o;
}

void ExportFigureDialog::save_settings() const {
  QSettings s;
  s.beginGroup("figure-export");
  s.setValue("preset", preset_->currentData());
  s.setValue("width_mm", width_->value());
  s.setValue("height_mm", height_->value());
  s.setValue("font_pt", font_->value());
  s.setValue("line_pt", line_->value());
  s.setValue("dpi", dpi_->currentData());
  s.setValue("pdf", pdf_->isChecked());
  s.setValue("svg", svg_->isChecked());
  s.setValue("png", png_->isChecked());
}

FigureDataChoice ExportFigureDialog::data_choice() const {
  return data_ ? static_cast<FigureDataChoice>(data_->currentData().toInt()) : FigureDataChoice::All;
}

void ExportFigureDialog::set_preview(std::function<QImage(const FigureOptions&)> render) {
  render_ = std::move(render);
  if (!preview_) {
    preview_ = new QLabel(this);
    preview_->setObjectName(QStringLiteral("preview"));
    preview_->setMinimumSize(420, 300);
    preview_->setAlignment(Qt::AlignCenter);
    preview_->setFrameShape(QFrame::StyledPanel);
    preview_->setToolTip(
        tr("The figure as it will be written: its size, fonts, line widths and legend below the axes"));
    static_cast<QHBoxLayout*>(layout())->addWidget(preview_, 1);
    preview_timer_ = new QTimer(this);
    preview_timer_->setSingleShot(true);
    preview_timer_->setInterval(150);  // typing a width renders once, not per digit
    connect(preview_timer_, &QTimer::timeout, this, &ExportFigureDialog::update_preview);
    for (QDoubleSpinBox* b : {width_, height_, font_, line_})
      connect(b, &QDoubleSpinBox::valueChanged, preview_timer_, qOverload<>(&QTimer::start));
    connect(preset_, &QComboBox::currentIndexChanged, preview_timer_, qOverload<>(&QTimer::start));
  }
  update_preview();
}

void ExportFigureDialog::update_preview() {
  if (!render_ || !preview_) return;
  FigureOptions o = options();
  o.formats = {"png"};
  const QImage image = render_(o);
  if (image.isNull()) {
    preview_->setText(tr("No preview"));
    return;
  }
  preview_->setPixmap(
      QPixmap::fromImage(image.scaled(preview_->size() - QSize(8, 8), Qt::KeepAspectRatio, Qt::SmoothTransformation)));
  preview_->setToolTip(
      tr("%1 × %2 mm as written")
          .arg(o.width_mm, 0, 'f', 1)
          .arg(o.height_mm > 0 ? o.height_mm : image.height() * o.width_mm / std::max(1, image.width()), 0, 'f', 1));
}

}  // namespace bs::ui
