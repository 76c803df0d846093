// SPDX-License-Identifier: GPL-3.0-or-later
#include "power/battery_view.h"

#include "common/plot_legend.h"
#include "power/left_out_logs.h"

#include <qcustomplot.h>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QInputDialog>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>
#include <cmath>
#include <stdexcept>

#include "device_palette.h"
#include "store/workspace.h"

namespace bs::ui {
namespace {

constexpr double kNominalCellV = 3.7;  // a LiPo cell's nominal voltage: the cell count follows from the pack's
// The Battery tab's fields as last edited, kept in the workspace so that they survive imports, runs and reopening.
constexpr const char* kCurrentSetupKey = "battery-tab/current";

QDoubleSpinBox* spin(QWidget* parent, double lo, double hi, int decimals, double step, const QString& suffix) {
  auto* s = new QDoubleSpinBox(parent);
  s->setRange(lo, hi);
  s->setDecimals(decimals);
  s->setSingleStep(step);
  s->setSuffix(suffix);
  s->setKeyboardTracking(false);  // recompute when a typed number is complete, not on every digit
  return s;
}

QString minutes(double seconds) { return QString::number(seconds / 60, 'f', 2); }

}  // namespace

BatteryView::BatteryView(QWidget* parent)
    : QWidget(parent),
      preset_(new QComboBox(this)),
      volts_(spin(this, 3.7, 100, 1, 3.7, tr(" V"))),
      capacity_(spin(this, 50, 100000, 0, 50, tr(" mAh"))),
      dod_(spin(this, 1, 100, 0, 5, tr(" %"))),
      extra_(spin(this, 0, 5000, 1, 5, tr(" W"))),
      resistance_(spin(this, 0, 10000, 1, 5, tr(" mΩ"))),
      model_(new QComboBox(this)),
      mission_(new QLineEdit(this)),
      pack_label_(new QLabel(this)),
      error_(new QLabel(this)),
      save_(new QPushButton(tr("Save preset…"), this)),
      delete_(new QPushButton(tr("Delete preset"), this)),
      table_(new QTableWidget(this)),
      plot_(new QCustomPlot(this)) {
  volts_->setToolTip(tr("Nominal pack voltage; the series cell count is voltage / 3.7 V (the paper: 14.8 V, 4S)"));
  dod_->setToolTip(tr("Usable depth of discharge: the share of the capacity the pack may give (LiPo: 80 % is kind)"));
  extra_->setToolTip(tr("A load in parallel with the computer, such as the servos (the paper's robot: up to 225 W)"));
  resistance_->setToolTip(tr("Whole-pack DC internal resistance (LiPo model only)"));
  model_->addItem(tr("Constant power (the paper)"));
  model_->addItem(tr("LiPo curve + internal resistance"));
  model_->setToolTip(
      tr("Constant power: t = V × capacity × depth of discharge / P. LiPo: open-circuit voltage vs state "
         "of charge, internal resistance and a cut-off voltage, the load drawing constant power."));
  mission_->setPlaceholderText(tr("none: constant load; e.g. idle:60:12,walk:30:140,kick:5:225"));
  mission_->setToolTip(
      tr("Mission phases name:seconds:watts, comma separated, repeated until the pack is empty; the "
         "watts come on top of the computer's mean power and the extra load"));
  error_->setStyleSheet(QStringLiteral("color: #b00020"));
  error_->setWordWrap(true);
  pack_label_->setWordWrap(true);

  auto* form = new QFormLayout;
  form->addRow(tr("Preset"), preset_);
  form->addRow(tr("Nominal voltage"), volts_);
  form->addRow(tr("Capacity"), capacity_);
  form->addRow(tr("Usable depth of discharge"), dod_);
  form->addRow(tr("Extra parallel load"), extra_);
  form->addRow(tr("Model"), model_);
  form->addRow(tr("Internal resistance"), resistance_);
  form->addRow(tr("Mission profile"), mission_);
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(save_);
  buttons->addWidget(delete_);
  buttons->addStretch(1);
  auto* box = new QGroupBox(tr("Battery and load"), this);
  auto* box_layout = new QVBoxLayout(box);
  box_layout->addLayout(form);
  box_layout->addWidget(pack_label_);
  box_layout->addLayout(buttons);
  box_layout->addWidget(error_);
  box_layout->addStretch(1);
  box->setMaximumWidth(380);  // the table beside it keeps its runtimes and "Ends by" in view at 1280x800

  table_->setColumnCount(6);
  // Two-line headers: the runtime columns stay in view beside the settings on a 1280 px window (issue #32.7).
  table_->setHorizontalHeaderLabels({tr("Platform"), tr("Computer\nmean power (W)"), tr("Total\nmean load (W)"),
                                     tr("Runtime (min)"), tr("Runtime (h)"), tr("Ends by")});
  table_->verticalHeader()->hide();
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  // "Ends by" is a sentence: it takes the width left and wraps there, so the runtimes and it stay in view at
  // 1280x800 beside the settings (a column as wide as its sentence ran off the table).
  table_->horizontalHeader()->setSectionResizeMode(5, QHeaderView::Stretch);
  table_->setWordWrap(true);
  table_->verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);

  plot_->xAxis->setLabel(tr("Time (min)"));
  plot_->yAxis->setLabel(tr("State of charge (%)"));
  // Short enough for a figure at an IEEE column's height; the legend says "pack voltage, LiPo model".
  plot_->yAxis2->setLabel(tr("Pack voltage (V)"));
  plot_->yAxis2->setVisible(true);
  plot_->legend->setVisible(true);
  plot_->legend->setFont(QFont(font().family(), 8));
  // Under the plot: the state-of-charge and voltage curves run corner to corner, any inset legend hides some (and
  // at 1280x800 it hid most, issue #32.7). One entry per line: the entries are long and stay whole.
  put_legend_below(plot_, 1);

  left_out_ = new QLabel(this);
  left_out_->setWordWrap(true);
  left_out_->setStyleSheet(QStringLiteral("color: #8a5a00"));
  left_out_->hide();
  auto* table_box = new QWidget(this);
  auto* table_layout = new QVBoxLayout(table_box);
  table_layout->setContentsMargins(0, 0, 0, 0);
  table_layout->addWidget(table_, 1);
  table_layout->addWidget(left_out_);
  auto* split = new QSplitter(Qt::Vertical, this);
  split->addWidget(table_box);
  split->addWidget(plot_);
  split->setStretchFactor(0, 1);
  split->setStretchFactor(1, 3);
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(4, 4, 4, 4);
  layout->addWidget(box);
  layout->addWidget(split, 1);

  connect(preset_, &QComboBox::currentIndexChanged, this, [this](int i) {
    if (i < 0 || i >= static_cast<int>(presets_.size())) return;
    show_setup(presets_[static_cast<std::size_t>(i)]);
    recompute();
  });
  for (QDoubleSpinBox* s : {volts_, capacity_, dod_, extra_, resistance_})
    connect(s, &QDoubleSpinBox::valueChanged, this, &BatteryView::recompute);
  connect(model_, &QComboBox::currentIndexChanged, this, &BatteryView::recompute);
  connect(mission_, &QLineEdit::editingFinished, this, &BatteryView::recompute);
  connect(save_, &QPushButton::clicked, this, &BatteryView::ask_save);
  connect(delete_, &QPushButton::clicked, this, &BatteryView::delete_preset);
  reload_presets(QStringLiteral("paper-4s-3850"));
}

void BatteryView::set_workspace(Workspace* workspace) {
  const QString selected = preset_->currentIndex() >= 0 ? QString::fromStdString(base_.pack.name) : QString();
  if (workspace == workspace_) {
    reload_presets(selected, /*keep_fields=*/true);  // the user's edits stay
    return;
  }
  workspace_ = workspace;
  remembered_.clear();
  // Showing the preset list must not overwrite what the workspace remembers before it is read back.
  restoring_ = true;
  reload_presets(selected);
  restore_saved_setup();
  restoring_ = false;
}

void BatteryView::restore_saved_setup() {
  if (!workspace_) return;
  for (const auto& [key, json] : workspace_->settings(kCurrentSetupKey)) {
    if (key != kCurrentSetupKey) continue;
    try {
      const BatterySetup saved = battery_setup_from_json(json);
      const QString name = QString::fromStdString(saved.pack.name);
      for (std::size_t i = 0; i < presets_.size(); ++i)
        if (QString::fromStdString(presets_[i].pack.name) == name) {
          const QSignalBlocker block(preset_);
          preset_->setCurrentIndex(static_cast<int>(i));
          base_ = presets_[i];
        }
      show_fields(saved);
      remembered_ = json;
      recompute();
    } catch (const std::invalid_argument& e) {
      error_->setText(
          tr("The battery setup saved in this workspace was not restored: %1").arg(QString::fromUtf8(e.what())));
    }
  }
}

bool BatteryView::remember_setup() {
  if (!workspace_ || restoring_) return false;
  const std::string json = battery_setup_to_json(setup());
  if (json == remembered_) return false;
  try {
    workspace_->set_setting(kCurrentSetupKey, json);
    remembered_ = json;
    return true;
  } catch (const std::exception& e) {  // a read-only or vanished workspace file: the edit still applies here
    error_->setText(tr("The battery setup could not be saved in the workspace: %1").arg(QString::fromUtf8(e.what())));
    return false;
  }
}

bool BatteryView::modified() const {
  BatterySetup preset = base_;
  BatterySetup now = setup();
  preset.from_workspace = now.from_workspace = false;
  return battery_setup_to_json(preset) != battery_setup_to_json(now);
}

void BatteryView::mark_modified() {
  const int i = preset_->currentIndex();
  if (i < 0 || i >= static_cast<int>(preset_texts_.size())) return;
  const QSignalBlocker block(preset_);
  const QString text = preset_texts_[static_cast<std::size_t>(i)];
  preset_->setItemText(i, modified() ? tr("%1 — modified").arg(text) : text);
  for (int k = 0; k < static_cast<int>(preset_texts_.size()); ++k)
    if (k != i) preset_->setItemText(k, preset_texts_[static_cast<std::size_t>(k)]);
}

void BatteryView::set_data(std::vector<PowerTrace> traces, std::vector<std::pair<std::string, int>> colors) {
  set_data(share_traces(std::move(traces)), std::move(colors));
}

void BatteryView::set_data(SharedTraces traces, std::vector<std::pair<std::string, int>> colors) {
  traces_ = std::move(traces);
  colors_ = std::move(colors);
  recompute();
}

void BatteryView::reload_presets(const QString& select, bool keep_fields) {
  std::vector<std::string> errors;
  const BatterySetup edited = setup();
  presets_ = all_battery_setups(workspace_, &errors);
  const QSignalBlocker block(preset_);
  preset_->clear();
  preset_texts_.clear();
  int index = 0;
  for (std::size_t i = 0; i < presets_.size(); ++i) {
    const BatteryPack& p = presets_[i].pack;
    QString text = QStringLiteral("%1 (%2 V, %3 mAh)")
                       .arg(QString::fromStdString(p.name))
                       .arg(p.nominal_v(), 0, 'f', 1)
                       .arg(p.capacity_ah * 1000, 0, 'f', 0);
    if (presets_[i].from_workspace) text += tr(", workspace");
    preset_->addItem(text);
    preset_texts_.push_back(text);
    preset_->setItemData(static_cast<int>(i), QString::fromStdString(p.description), Qt::ToolTipRole);
    if (QString::fromStdString(p.name) == select) index = static_cast<int>(i);
  }
  delete_->setEnabled(workspace_ != nullptr);
  save_->setEnabled(workspace_ != nullptr);
  preset_->setCurrentIndex(index);
  if (keep_fields) {
    base_ = presets_.at(static_cast<std::size_t>(index));
    show_fields(edited);
  } else {
    show_setup(presets_.at(static_cast<std::size_t>(index)));
  }
  recompute();
  if (!errors.empty()) error_->setText(QString::fromStdString(errors.front()));
}

void BatteryView::show_setup(const BatterySetup& s) {
  base_ = s;
  show_fields(s);
}

void BatteryView::show_fields(const BatterySetup& s) {
  const QSignalBlocker b1(volts_), b2(capacity_), b3(dod_), b4(extra_), b5(resistance_), b6(model_), b7(mission_);
  volts_->setValue(s.pack.nominal_v());
  capacity_->setValue(s.pack.capacity_ah * 1000);
  dod_->setValue(s.depth_of_discharge * 100);
  extra_->setValue(s.extra_load_w);
  resistance_->setValue(s.pack.internal_resistance_ohm * 1000);
  model_->setCurrentIndex(s.model == BatteryModel::Lipo ? 1 : 0);
  mission_->setText(QString::fromStdString(s.mission));
}

BatterySetup BatteryView::setup() const {
  BatterySetup s = base_;
  s.pack.cells_series = std::max(1, static_cast<int>(std::lround(volts_->value() / kNominalCellV)));
  // Keep the preset's own cell voltage when the voltage was not edited (exact 14.8 V, not 14.8 / 4 rounded).
  if (std::abs(volts_->value() - base_.pack.nominal_v()) > 0.05 || s.pack.cells_series != base_.pack.cells_series)
    s.pack.nominal_cell_v = volts_->value() / s.pack.cells_series;
  s.pack.capacity_ah = capacity_->value() / 1000;
  s.pack.internal_resistance_ohm = resistance_->value() / 1000;
  s.depth_of_discharge = dod_->value() / 100;
  s.extra_load_w = extra_->value();
  s.model = model_->currentIndex() == 1 ? BatteryModel::Lipo : BatteryModel::ConstantPower;
  s.mission = mission_->text().trimmed().toStdString();
  return s;
}

bool BatteryView::select_preset(const QString& name) {
  for (std::size_t i = 0; i < presets_.size(); ++i)
    if (QString::fromStdString(presets_[i].pack.name) == name) {
      preset_->setCurrentIndex(static_cast<int>(i));
      show_setup(presets_[i]);
      recompute();
      return true;
    }
  return false;
}

QString BatteryView::error_text() const { return error_->text(); }
QString BatteryView::left_out_text() const { return left_out_->text(); }

void BatteryView::recompute() {
  const BatterySetup s = setup();
  pack_label_->setText(tr("%1S × %2 V per cell = %3 V nominal, %4 Wh; cut-off %5 V per cell (LiPo model)")
                           .arg(s.pack.cells_series)
                           .arg(s.pack.nominal_cell_v, 0, 'f', 2)
                           .arg(s.pack.nominal_v(), 0, 'f', 1)
                           .arg(s.pack.nominal_wh(), 0, 'f', 1)
                           .arg(s.pack.cutoff_cell_v, 0, 'f', 2));
  resistance_->setEnabled(s.model == BatteryModel::Lipo);
  DischargeOptions options;
  options.model = s.model;
  options.depth_of_discharge = s.depth_of_discharge;
  try {
    rows_ = platform_battery(traces_->traces, s.pack, options, s.extra_load_w, s.mission);
    error_->clear();
  } catch (const std::invalid_argument& e) {
    rows_.clear();
    error_->setText(QString::fromUtf8(e.what()));
  }
  fill_table();
  fill_plot();
  const QString left_out = left_out_logs_text(traces_->traces);
  left_out_->setText(left_out);
  left_out_->setVisible(!left_out.isEmpty());
  mark_modified();
  const bool edited = remember_setup();
  emit setup_changed();
  if (edited) emit setup_edited();
}

void BatteryView::fill_table() {
  table_->setRowCount(static_cast<int>(rows_.size()));
  for (std::size_t r = 0; r < rows_.size(); ++r) {
    const PlatformBattery& b = rows_[r];
    const auto cell = [&](int col, const QString& text, const QString& tip = {}) {
      auto* item = new QTableWidgetItem(text);
      if (col > 0 && col < 5) item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
      if (!tip.isEmpty()) item->setToolTip(tip);
      table_->setItem(static_cast<int>(r), col, item);
    };
    cell(0, QString::fromStdString(b.platform), tr("power from log %1").arg(QString::fromStdString(b.trace_label)));
    cell(1, QString::number(b.computer_mean_w, 'f', 2));
    cell(2, QString::number(b.mission.mean_load_w(), 'f', 2));
    cell(3, minutes(b.result.runtime_s), QString::fromStdString(b.result.model_label));
    cell(4, QString::number(b.result.runtime_s / 3600, 'f', 2));
    cell(5, QString::fromStdString(b.result.stop_reason), QString::fromStdString(b.result.stop_reason));
  }
}

void BatteryView::fill_plot() {
  plot_->clearGraphs();
  double max_t = 0, min_v = 1e9, max_v = 0;
  for (std::size_t r = 0; r < rows_.size(); ++r) {
    const PlatformBattery& b = rows_[r];
    int color = static_cast<int>(r) + 7;
    for (const auto& [platform, index] : colors_)
      if (platform == b.platform) color = index;
    const QString name = QString::fromStdString(b.platform);
    QVector<double> t, soc, vt, volts;
    for (const DischargePoint& p : b.result.series) t << p.t_s / 60, soc << p.soc * 100;
    for (const DischargePoint& p : b.lipo.series) {
      vt << p.t_s / 60, volts << p.terminal_v;
      min_v = std::min(min_v, p.terminal_v);
      max_v = std::max(max_v, p.terminal_v);
    }
    QCPGraph* g = plot_->addGraph(plot_->xAxis, plot_->yAxis);
    g->setName(tr("%1: state of charge (%2 min)").arg(name, minutes(b.result.runtime_s)));
    g->setPen(QPen(device_color(color), 2));
    g->setData(t, soc, true);
    QCPGraph* v = plot_->addGraph(plot_->xAxis, plot_->yAxis2);
    v->setName(tr("%1: pack voltage, LiPo model (empty at %2 min)").arg(name, minutes(b.lipo.runtime_s)));
    v->setPen(QPen(device_color(color), 1.2, Qt::DashLine));
    v->setData(vt, volts, true);
    if (!t.isEmpty()) max_t = std::max(max_t, t.back());
    if (!vt.isEmpty()) max_t = std::max(max_t, vt.back());
  }
  plot_->xAxis->setRange(0, max_t > 0 ? max_t * 1.02 : 1);
  plot_->yAxis->setRange(0, 105);
  if (max_v > 0) plot_->yAxis2->setRange(std::floor(min_v - 0.5), std::ceil(max_v + 0.5));
  plot_->replot();
}

void BatteryView::ask_save() {
  bool ok = false;
  const QString name = QInputDialog::getText(this, tr("Save battery preset"),
                                             tr("Name (saved in this workspace; an existing name is replaced):"),
                                             QLineEdit::Normal, QString::fromStdString(base_.pack.name), &ok);
  if (ok && !name.trimmed().isEmpty()) save_preset(name.trimmed());
}

bool BatteryView::save_preset(const QString& name) {
  if (!workspace_) {
    error_->setText(tr("No workspace open: presets are saved in the workspace."));
    return false;
  }
  BatterySetup s = setup();
  s.pack.name = name.toStdString();
  try {
    save_battery_setup(*workspace_, s);
  } catch (const std::exception& e) {  // invalid values, or the workspace file (WorkspaceError)
    error_->setText(QString::fromUtf8(e.what()));
    return false;
  }
  reload_presets(name);
  return true;
}

void BatteryView::delete_preset() {
  if (!workspace_ || !base_.from_workspace) {
    error_->setText(tr("Built-in presets cannot be deleted; only presets saved in the workspace."));
    return;
  }
  remove_battery_setup(*workspace_, base_.pack.name);
  reload_presets(QString::fromStdString(base_.pack.name));  // a replaced built-in comes back
}

}  // namespace bs::ui
