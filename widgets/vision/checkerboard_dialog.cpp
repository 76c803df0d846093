// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/checkerboard_dialog.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>
#include <QtConcurrent>

#include "common/file_command.h"
#include "common/reading_label.h"

namespace bs::ui {
namespace {

enum Column { kImage, kCorners, kRms, kAngle, kStatus, kColumns };

QTableWidgetItem* item(const QString& text, Qt::Alignment align = Qt::AlignLeft | Qt::AlignVCenter) {
  auto* it = new QTableWidgetItem(text);
  it->setTextAlignment(align);
  it->setFlags(it->flags() & ~Qt::ItemIsEditable);
  return it;
}

}  // namespace

CheckerboardDialog::CheckerboardDialog(const vision::TunerParams& base, QWidget* parent)
    : QDialog(parent), base_(base), watcher_(new QFutureWatcher<Outcome>(this)) {
  setWindowTitle(tr("Calibrate from checkerboard"));
  add_ = new QPushButton(tr("Add images…"));
  remove_ = new QPushButton(tr("Remove"));
  clear_ = new QPushButton(tr("Clear"));
  auto* files = new QHBoxLayout;
  files->addWidget(add_);
  files->addWidget(remove_);
  files->addWidget(clear_);
  files->addStretch(1);

  cols_ = new QSpinBox;
  rows_ = new QSpinBox;
  for (QSpinBox* s : {cols_, rows_}) s->setRange(3, 100);
  cols_->setValue(10);
  rows_->setValue(7);
  square_ = new QDoubleSpinBox;
  square_->setRange(0.1, 10000);
  square_->setDecimals(2);
  square_->setValue(30);
  square_->setSuffix(tr(" mm"));
  model_ = new QComboBox;
  model_->addItem(tr("Kannala-Brandt (k1…k4)"), static_cast<int>(vision::CalibrationModel::KannalaBrandt));
  model_->addItem(tr("Equidistant (k = 0)"), static_cast<int>(vision::CalibrationModel::Equidistant));
  fov_ = new QDoubleSpinBox;
  fov_->setRange(1, 360);
  fov_->setDecimals(1);
  fov_->setSuffix(tr("°"));
  fov_->setValue(base.lens.fov_deg);
  fov_->setToolTip(
      tr("A checkerboard does not measure where the image circle ends: the lens keeps this field of view"));
  auto* board_row = new QHBoxLayout;
  board_row->addWidget(cols_);
  board_row->addWidget(new QLabel(tr("×")));
  board_row->addWidget(rows_);
  board_row->addWidget(new QLabel(tr("squares (OpenCV's inner corners are one fewer each way)")));
  board_row->addStretch(1);
  for (QWidget* w : std::initializer_list<QWidget*>{square_, model_, fov_}) w->setMaximumWidth(260);
  auto* form = new QFormLayout;
  form->addRow(tr("Board:"), board_row);
  form->addRow(tr("Square size:"), square_);
  form->addRow(tr("Model:"), model_);
  form->addRow(tr("Lens FOV:"), fov_);

  calibrate_ = new QPushButton(tr("Calibrate"));
  calibrate_->setDefault(true);
  cancel_button_ = new QPushButton(tr("Cancel"));
  progress_ = new QProgressBar;
  progress_->setRange(0, 1000);
  progress_->setValue(0);
  progress_->setTextVisible(false);
  step_ = new QLabel;
  auto* run_row = new QHBoxLayout;
  run_row->addWidget(calibrate_);
  run_row->addWidget(progress_, 1);
  run_row->addWidget(cancel_button_);

  table_ = new QTableWidget(0, kColumns);
  table_->setHorizontalHeaderLabels({tr("Image"), tr("Corners"), tr("RMS (px)"), tr("Max angle (°)"), tr("Status")});
  table_->horizontalHeader()->setSectionResizeMode(kStatus, QHeaderView::Stretch);
  table_->verticalHeader()->setVisible(false);
  table_->verticalHeader()->setDefaultSectionSize(table_->fontMetrics().height() + 8);
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  table_->setWordWrap(false);
  summary_ = reading_label(nullptr, tr("Add photos of the board from many angles, filling the whole field of view."));

  apply_ = new QPushButton(tr("Apply"));
  apply_->setToolTip(tr("Use the calibrated lens in the Lens tab (one undo step there)"));
  save_ = new QPushButton(tr("Save…"));
  auto* close = new QPushButton(tr("Close"));
  auto* buttons = new QHBoxLayout;
  buttons->addStretch(1);
  buttons->addWidget(apply_);
  buttons->addWidget(save_);
  buttons->addWidget(close);

  auto* lay = new QVBoxLayout(this);
  lay->addLayout(files);
  lay->addLayout(form);
  lay->addLayout(run_row);
  lay->addWidget(step_);
  lay->addWidget(table_, 1);
  lay->addWidget(summary_);
  lay->addLayout(buttons);
  resize(860, 640);

  connect(add_, &QPushButton::clicked, this, [this] {
    const QStringList more = QFileDialog::getOpenFileNames(this, tr("Checkerboard photos"), {},
                                                           tr("Images (*.png *.jpg *.jpeg *.tif *.tiff *.bmp *.pgm)"));
    if (!more.isEmpty()) set_images(paths_ + more);
  });
  connect(remove_, &QPushButton::clicked, this, [this] {
    QStringList keep;
    for (int i = 0; i < paths_.size(); ++i)
      if (!table_->item(i, kImage)->isSelected()) keep << paths_[i];
    set_images(keep);
  });
  connect(clear_, &QPushButton::clicked, this, [this] { set_images({}); });
  connect(calibrate_, &QPushButton::clicked, this, &CheckerboardDialog::start);
  connect(cancel_button_, &QPushButton::clicked, this, &CheckerboardDialog::cancel);
  connect(apply_, &QPushButton::clicked, this, [this] {
    if (result_) emit apply_requested(result_->lens);
  });
  connect(save_, &QPushButton::clicked, this, [this] {
    run_file_command(this, {FileCommand::Save, tr("Save lens"), "lens.json", tr("Lens JSON (*.json)")},
                     [this](const QString& path) { save(path); });
  });
  connect(close, &QPushButton::clicked, this, &QDialog::reject);
  connect(watcher_, &QFutureWatcher<Outcome>::finished, this, &CheckerboardDialog::run_finished);
  update_buttons();
}

CheckerboardDialog::~CheckerboardDialog() {
  if (cancel_) cancel_->cancel();
  watcher_->waitForFinished();
}

void CheckerboardDialog::set_images(const QStringList& paths) {
  if (running()) return;
  paths_ = paths;
  paths_.removeDuplicates();
  result_.reset();
  error_.clear();
  fill_table();
  summary_->setText(paths_.isEmpty()
                        ? tr("Add photos of the board from many angles, filling the whole field of view.")
                        : tr("%n image(s), not calibrated yet.", nullptr, static_cast<int>(paths_.size())));
  update_buttons();
}

void CheckerboardDialog::set_board(int cols, int rows, double square_mm) {
  cols_->setValue(cols);
  rows_->setValue(rows);
  square_->setValue(square_mm);
}

void CheckerboardDialog::set_model(vision::CalibrationModel model) {
  model_->setCurrentIndex(model_->findData(static_cast<int>(model)));
}

void CheckerboardDialog::set_fov(double deg) { fov_->setValue(deg); }

void CheckerboardDialog::start() {
  if (running() || paths_.isEmpty()) return;
  std::vector<vision::CalibrationImage> images;
  for (const QString& p : paths_) images.push_back({QFileInfo(p).fileName().toStdString(), p.toStdString(), {}});
  vision::Checkerboard board;
  board.cols = cols_->value();
  board.rows = rows_->value();
  board.square_mm = square_->value();
  const auto model = static_cast<vision::CalibrationModel>(model_->currentData().toInt());
  vision::Lens base = base_.lens;
  base.fov_deg = fov_->value();
  result_.reset();
  error_.clear();
  cancel_ = std::make_shared<CancelToken>();
  progress_->setValue(0);
  step_->setText(tr("Finding corners…"));
  summary_->setText(tr("Calibrating…"));
  auto cancel = cancel_;
  auto report = [this](double fraction, std::string_view step) {
    const QString text = QString::fromUtf8(step.data(), static_cast<qsizetype>(step.size()));
    QMetaObject::invokeMethod(
        this,
        [this, fraction, text] {
          progress_->setValue(static_cast<int>(fraction * 1000));
          step_->setText(text);
        },
        Qt::QueuedConnection);
  };
  watcher_->setFuture(QtConcurrent::run([images, board, model, base, cancel, report] {
    Outcome o;
    try {
      o.result = vision::calibrate_checkerboard(images, board, model, base, cancel.get(), report);
    } catch (const Cancelled&) {
      o.cancelled = true;
    } catch (const std::exception& e) {
      o.error = QString::fromStdString(e.what());
    }
    return o;
  }));
  update_buttons();
}

void CheckerboardDialog::cancel() {
  if (cancel_ && running()) {
    cancel_->cancel();
    step_->setText(tr("Cancelling…"));
  }
}

void CheckerboardDialog::run_finished() {
  const Outcome o = watcher_->result();
  result_ = o.result;
  error_ = o.cancelled ? tr("Cancelled.") : o.error;
  progress_->setValue(result_ ? 1000 : 0);
  step_->setText(o.cancelled ? tr("Cancelled.") : result_ ? tr("Done.") : tr("Failed."));
  fill_table();
  summary_->setText(summary_text());
  update_buttons();
  emit calibration_finished(result_.has_value());
}

void CheckerboardDialog::fill_table() {
  table_->setRowCount(static_cast<int>(paths_.size()));
  for (int i = 0; i < paths_.size(); ++i) {
    table_->setItem(i, kImage, item(QFileInfo(paths_[i]).fileName()));
    table_->item(i, kImage)->setToolTip(paths_[i]);
    const vision::CalibrationImageResult* r = result_ && i < static_cast<int>(result_->images.size())
                                                  ? &result_->images[static_cast<std::size_t>(i)]
                                                  : nullptr;
    const auto right = Qt::AlignRight | Qt::AlignVCenter;
    table_->setItem(i, kCorners, item(r && !r->corners.empty() ? QString::number(r->corners.size()) : "–", right));
    table_->setItem(i, kRms, item(r && r->rms_px ? QString::number(*r->rms_px, 'f', 3) : "–", right));
    table_->setItem(i, kAngle, item(r && r->used ? QString::number(r->max_theta_deg, 'f', 0) : "–", right));
    QString status = r ? (r->used ? tr("used") : tr("rejected: %1").arg(QString::fromStdString(r->rejected)))
                       : tr("not calibrated yet");
    table_->setItem(i, kStatus, item(status));
    table_->item(i, kStatus)->setToolTip(status);
    if (r && !r->used)
      for (int c = 0; c < kColumns; ++c) table_->item(i, c)->setBackground(QColor(255, 228, 214));
  }
  table_->resizeColumnsToContents();
  table_->horizontalHeader()->setSectionResizeMode(kStatus, QHeaderView::Stretch);
}

QString CheckerboardDialog::summary_text() const {
  if (!result_) return error_.isEmpty() ? QString() : error_.toHtmlEscaped().replace('\n', "<br>");
  const auto& r = *result_;
  const auto& l = r.lens;
  QString s = tr("<b>RMS %1 px</b> over %2 of %3 images (the lens file's own model) — %4 lens:<br>"
                 "focal %5 px (r_pp %6 rad/px), principal point (%7, %8) px, k = %9, %10, %11, %12; FOV %13° "
                 "(not measured by a checkerboard)<br>"
                 "free fit: fx %14 px, fy %15 px (fy/fx %16), RMS %17 px; corners seen up to %18° off the axis")
                  .arg(r.rms_px, 0, 'f', 3)
                  .arg(r.used())
                  .arg(r.images.size())
                  .arg(QString::fromUtf8(vision::to_string(l.type).data()))
                  .arg(1 / l.r_pp, 0, 'f', 2)
                  .arg(l.r_pp, 0, 'g', 6)
                  .arg(l.cx, 0, 'f', 2)
                  .arg(l.cy, 0, 'f', 2)
                  .arg(l.k[0], 0, 'g', 4)
                  .arg(l.k[1], 0, 'g', 4)
                  .arg(l.k[2], 0, 'g', 4)
                  .arg(l.k[3], 0, 'g', 4)
                  .arg(l.fov_deg, 0, 'f', 1)
                  .arg(r.fx, 0, 'f', 2)
                  .arg(r.fy, 0, 'f', 2)
                  .arg(r.fy / r.fx, 0, 'f', 5)
                  .arg(r.free_rms_px, 0, 'f', 3)
                  .arg(r.max_theta_deg, 0, 'f', 0);
  for (const auto& w : r.warnings)
    s += "<br><span style='color:#a05000'>" + tr("Warning: %1").arg(QString::fromStdString(w).toHtmlEscaped()) +
         "</span>";
  return s;
}

void CheckerboardDialog::save(const QString& path) const {
  if (!result_) throw std::runtime_error("no calibration to save yet");
  vision::TunerParams p = base_;
  p.lens = result_->lens;
  vision::save_tuner_json(p, path.toStdString());
}

void CheckerboardDialog::update_buttons() {
  const bool busy = running();
  for (QWidget* w : std::initializer_list<QWidget*>{add_, remove_, clear_, cols_, rows_, square_, model_, fov_})
    w->setEnabled(!busy);
  calibrate_->setEnabled(!busy && !paths_.isEmpty());
  cancel_button_->setEnabled(busy);
  apply_->setEnabled(!busy && result_.has_value());
  save_->setEnabled(!busy && result_.has_value());
}

}  // namespace bs::ui
