// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/raw_geometry_dialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QLabel>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>

namespace bs::ui {
namespace {

constexpr const char* kKey = "raw-geometry/last";  // "WxH:PATTERN:BITS:le|be", as --raw-geometry takes it

QString to_text(const RawFrameOptions& o) {
  return QStringLiteral("%1x%2:%3:%4:%5")
      .arg(o.width)
      .arg(o.height)
      .arg(o.pattern.empty() ? QStringLiteral("grey") : QString::fromStdString(o.pattern))
      .arg(o.bit_depth)
      .arg(o.big_endian ? "be" : "le");
}

}  // namespace

std::optional<RawFrameOptions> RawGeometryDialog::remembered() {
  const QString text = QSettings().value(kKey).toString();
  if (text.isEmpty()) return std::nullopt;
  try {
    return parse_raw_geometry(text.toStdString());
  } catch (const std::invalid_argument&) {
    return std::nullopt;  // a damaged setting is forgotten, not an error
  }
}

RawGeometryDialog::RawGeometryDialog(const QString& raw_path, QWidget* parent)
    : QDialog(parent), file_size_(QFileInfo(raw_path).size()) {
  setWindowTitle(tr("Raw frame geometry"));
  setMinimumWidth(420);
  auto* form = new QFormLayout(this);
  auto* intro =
      new QLabel(tr("<b>%1</b> has no JSON sidecar (%2), so its geometry is not recorded. "
                    "Give it once; it is remembered for the next capture.")
                     .arg(QFileInfo(raw_path).fileName(),
                          QFileInfo(QString::fromStdString(raw_sidecar_path(raw_path.toStdString()))).fileName()));
  intro->setWordWrap(true);
  form->addRow(intro);
  width_ = new QSpinBox;
  height_ = new QSpinBox;
  for (QSpinBox* s : {width_, height_}) {
    s->setRange(1, 65535);
    s->setSuffix(tr(" px"));
  }
  width_->setToolTip(tr("Samples per row"));
  height_->setToolTip(tr("Rows"));
  pattern_ = new QComboBox;
  for (const char* p : {"BGGR", "RGGB", "GRBG", "GBRG"}) pattern_->addItem(p, p);
  pattern_->addItem(tr("grey (no mosaic)"), "");
  pattern_->setToolTip(tr("Colour of the top-left 2x2 block; the paper's camera is BGGR"));
  bits_ = new QComboBox;
  for (const int b : {8, 10, 12, 14, 16}) bits_->addItem(tr("%1-bit").arg(b), b);
  bits_->setToolTip(tr("Bits per sample; above 8, each sample is a 16-bit word with the value in its low bits"));
  endian_ = new QComboBox;
  endian_->addItem(tr("little endian"), false);
  endian_->addItem(tr("big endian"), true);
  endian_->setToolTip(tr("Byte order of 16-bit words"));
  form->addRow(tr("&Width"), width_);
  form->addRow(tr("&Height"), height_);
  form->addRow(tr("&Pattern"), pattern_);
  form->addRow(tr("&Bits"), bits_);
  form->addRow(tr("Byte &order"), endian_);
  check_ = new QLabel;
  check_->setWordWrap(true);
  form->addRow(check_);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
  ok_ = buttons->button(QDialogButtonBox::Ok);
  ok_->setText(tr("&Import"));
  form->addRow(buttons);
  connect(buttons, &QDialogButtonBox::accepted, this, [this] {
    QSettings().setValue(kKey, to_text(options()));
    accept();
  });
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  for (QSpinBox* s : {width_, height_}) connect(s, &QSpinBox::valueChanged, this, &RawGeometryDialog::update_check);
  for (QComboBox* c : {pattern_, bits_, endian_})
    connect(c, &QComboBox::currentIndexChanged, this, &RawGeometryDialog::update_check);

  RawFrameOptions initial;
  initial.width = 1280;  // the paper's camera
  initial.height = 1024;
  set_options(remembered().value_or(initial));
}

void RawGeometryDialog::set_options(const RawFrameOptions& o) {
  width_->setValue(o.width);
  height_->setValue(o.height);
  pattern_->setCurrentIndex(std::max(0, pattern_->findData(QString::fromStdString(o.pattern))));
  bits_->setCurrentIndex(std::max(0, bits_->findData(o.bit_depth)));
  endian_->setCurrentIndex(o.big_endian ? 1 : 0);
  update_check();
}

RawFrameOptions RawGeometryDialog::options() const {
  RawFrameOptions o;
  o.width = width_->value();
  o.height = height_->value();
  o.pattern = pattern_->currentData().toString().toStdString();
  o.bit_depth = bits_->currentData().toInt();
  o.big_endian = endian_->currentData().toBool();
  return o;
}

bool RawGeometryDialog::matches_file() const {
  const RawFrameOptions o = options();
  return static_cast<qint64>(o.width) * o.height * (o.bit_depth > 8 ? 2 : 1) == file_size_;
}

void RawGeometryDialog::update_check() {
  endian_->setEnabled(bits_->currentData().toInt() > 8);
  const RawFrameOptions o = options();
  const qint64 expected = static_cast<qint64>(o.width) * o.height * (o.bit_depth > 8 ? 2 : 1);
  const bool ok = expected == file_size_;
  check_->setText(ok ? tr("The file's %1 bytes match this geometry.").arg(file_size_)
                     : tr("<span style='color:#b00'>This geometry needs %1 bytes; the file has %2.</span>")
                           .arg(expected)
                           .arg(file_size_));
  if (ok_) ok_->setEnabled(ok);
}

}  // namespace bs::ui
