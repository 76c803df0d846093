// SPDX-License-Identifier: GPL-3.0-or-later
#include "power/power_overlay.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QTableWidget>
#include <QVBoxLayout>

#include "analysis/power/trace_align.h"

namespace bs::ui {

PowerOverlayPanel::PowerOverlayPanel(QWidget* parent)
    : QWidget(parent),
      table_(new QTableWidget(this)),
      phase_box_(new QComboBox(this)),
      align_(new QPushButton(tr("Align"), this)),
      reset_(new QPushButton(tr("Reset offsets"), this)) {
  table_->setColumnCount(3);
  table_->setHorizontalHeaderLabels({tr("Show"), tr("Trace"), tr("Offset (s)")});
  table_->verticalHeader()->hide();
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  table_->horizontalHeader()->setStretchLastSection(true);
  phase_box_->setToolTip(
      tr("A phase or marker the traces share (PTDaemon marks, BenchScope's runs, saved "
         "selections): Align shifts every trace that has it so that it starts at 0 s"));
  phase_box_->setMinimumContentsLength(16);
  align_->setToolTip(tr("Shift the traces so that the chosen phase starts at 0 s on each of them"));
  reset_->setToolTip(tr("Every trace back at its own start (offset 0 s)"));
  connect(align_, &QPushButton::clicked, this, [this] { align_at(phase_box_->currentText().toStdString()); });
  connect(reset_, &QPushButton::clicked, this, [this] {
    for (std::size_t i = 0; i < offsets_.size(); ++i) offsets_[i] = 0;
    fill_table();
    emit changed();
  });
  auto* row = new QHBoxLayout;
  row->addWidget(new QLabel(tr("Align at phase:"), this));
  row->addWidget(phase_box_);
  row->addWidget(align_);
  row->addWidget(reset_);
  row->addStretch(1);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 2, 0, 0);
  layout->addLayout(row);
  layout->addWidget(table_, 1);
}

void PowerOverlayPanel::set_traces(const std::vector<QString>& names, std::vector<std::vector<TracePhase>> phases) {
  phases_ = std::move(phases);
  offsets_.assign(names.size(), 0.0);
  visible_.assign(names.size(), true);
  table_->setRowCount(static_cast<int>(names.size()));
  for (int r = 0; r < static_cast<int>(names.size()); ++r) {
    auto* show = new QCheckBox(table_);
    show->setChecked(true);
    show->setToolTip(tr("Draw this trace and include it in the statistics tables"));
    connect(show, &QCheckBox::toggled, this, [this, r](bool on) { set_visible(static_cast<std::size_t>(r), on); });
    table_->setCellWidget(r, 0, show);
    auto* name = new QTableWidgetItem(names[static_cast<std::size_t>(r)]);
    name->setFlags(name->flags() & ~Qt::ItemIsEditable);
    table_->setItem(r, 1, name);
    auto* spin = new QDoubleSpinBox(table_);
    spin->setRange(-1e9, 1e9);
    spin->setDecimals(3);
    spin->setSuffix(tr(" s"));
    spin->setToolTip(tr("Seconds added to this trace's time on the shared axis (negative: earlier)"));
    connect(spin, &QDoubleSpinBox::valueChanged, this,
            [this, r](double v) { set_offset(static_cast<std::size_t>(r), v); });
    table_->setCellWidget(r, 2, spin);
  }
  set_phases(std::move(phases_));
}

void PowerOverlayPanel::set_phases(std::vector<std::vector<TracePhase>> phases) {
  phases_ = std::move(phases);
  const QString current = phase_box_->currentText();
  const QSignalBlocker block(phase_box_);
  phase_box_->clear();
  // Names two traces share come first; with one trace, its own phases.
  std::vector<std::string> names_shared = shared_phase_names(phases_, phases_.size() > 1 ? 2 : 1);
  for (const std::string& n : names_shared) phase_box_->addItem(QString::fromStdString(n));
  if (phase_box_->findText(current) >= 0) phase_box_->setCurrentText(current);
  align_->setEnabled(phase_box_->count() > 0);
}

void PowerOverlayPanel::fill_table() {
  for (int r = 0; r < table_->rowCount() && r < static_cast<int>(offsets_.size()); ++r) {
    if (auto* spin = qobject_cast<QDoubleSpinBox*>(table_->cellWidget(r, 2))) {
      const QSignalBlocker block(spin);
      spin->setValue(offsets_[static_cast<std::size_t>(r)]);
    }
    if (auto* show = qobject_cast<QCheckBox*>(table_->cellWidget(r, 0))) {
      const QSignalBlocker block(show);
      show->setChecked(visible_[static_cast<std::size_t>(r)]);
    }
  }
}

void PowerOverlayPanel::set_offset(std::size_t trace, double seconds) {
  if (trace >= offsets_.size()) return;
  offsets_[trace] = seconds;
  fill_table();
  emit changed();
}

void PowerOverlayPanel::set_visible(std::size_t trace, bool on) {
  if (trace >= visible_.size()) return;
  visible_[trace] = on;
  fill_table();
  emit changed();
}

int PowerOverlayPanel::align_at(const std::string& name) {
  int aligned = 0;
  const std::vector<std::optional<double>> offsets = align_at_phase(phases_, name);
  for (std::size_t i = 0; i < offsets.size() && i < offsets_.size(); ++i)
    if (offsets[i]) offsets_[i] = *offsets[i], ++aligned;
  {
    const QSignalBlocker block(phase_box_);
    phase_box_->setCurrentText(QString::fromStdString(name));  // shows what the offsets were aligned at
  }
  fill_table();
  emit changed();
  return aligned;
}

}  // namespace bs::ui
