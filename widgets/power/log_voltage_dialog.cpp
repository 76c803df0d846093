// SPDX-License-Identifier: GPL-3.0-or-later
#include "power/log_voltage_dialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QRadioButton>
#include <QVBoxLayout>

namespace bs::ui {

LogVoltageDialog::LogVoltageDialog(const QString& log_label, const LogVoltageChoice& current,
                                   std::vector<VoltageChannelOption> channels, QWidget* parent)
    : QDialog(parent),
      none_(new QRadioButton(tr("None: the log's own channels only"), this)),
      typed_(new QRadioButton(tr("Supply voltage (constant):"), this)),
      borrowed_(new QRadioButton(tr("Voltage channel of another log:"), this)),
      volts_(new QDoubleSpinBox(this)),
      channel_(new QComboBox(this)),
      channels_(std::move(channels)) {
  setWindowTitle(tr("Supply voltage of %1").arg(log_label));
  auto* intro = new QLabel(tr("Power = current × voltage. A log with current only needs the voltage it was "
                              "supplied at: typed, or from another log recorded at the same time (lined up by "
                              "the logs' start times)."),
                           this);
  intro->setWordWrap(true);
  volts_->setRange(0.1, 1000);
  volts_->setDecimals(3);
  volts_->setSuffix(tr(" V"));
  volts_->setValue(current.supply_v.value_or(16.0));  // the paper's supply, as a starting point
  for (const VoltageChannelOption& o : channels_) channel_->addItem(o.text);
  borrowed_->setEnabled(!channels_.empty());
  if (channels_.empty()) channel_->addItem(tr("no other log has a voltage channel"));
  auto* form = new QFormLayout;
  form->addRow(none_);
  form->addRow(typed_, volts_);
  form->addRow(borrowed_, channel_);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(intro);
  layout->addLayout(form);
  layout->addWidget(buttons);
  const auto sync = [this] {
    volts_->setEnabled(typed_->isChecked());
    channel_->setEnabled(borrowed_->isChecked());
  };
  for (QRadioButton* b : {none_, typed_, borrowed_}) connect(b, &QRadioButton::toggled, this, sync);
  if (!(current.source && choose_channel(*current.source))) (current.supply_v ? typed_ : none_)->setChecked(true);
  sync();
}

void LogVoltageDialog::choose_none() { none_->setChecked(true); }

void LogVoltageDialog::choose_volts(double volts) {
  typed_->setChecked(true);
  volts_->setValue(volts);
}

bool LogVoltageDialog::choose_channel(const VoltageSource& source) {
  for (std::size_t i = 0; i < channels_.size(); ++i)
    if (channels_[i].source == source) {
      borrowed_->setChecked(true);
      channel_->setCurrentIndex(static_cast<int>(i));
      return true;
    }
  return false;
}

LogVoltageChoice LogVoltageDialog::choice() const {
  LogVoltageChoice c;
  if (typed_->isChecked()) c.supply_v = volts_->value();
  const int i = channel_->currentIndex();
  if (borrowed_->isChecked() && i >= 0 && i < static_cast<int>(channels_.size()))
    c.source = channels_[static_cast<std::size_t>(i)].source;
  return c;
}

}  // namespace bs::ui
