// SPDX-License-Identifier: GPL-3.0-or-later
#include "power/save_phase_dialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>

namespace bs::ui {

SavePhaseDialog::SavePhaseDialog(const std::vector<QString>& logs, std::size_t preferred, QWidget* parent)
    : QDialog(parent), name_(new QLineEdit(tr("selection"), this)), log_(new QComboBox(this)), count_(logs.size()) {
  setWindowTitle(tr("Save selection as phase"));
  name_->selectAll();
  for (std::size_t i = 0; i < logs.size(); ++i) log_->addItem(logs[i], static_cast<int>(i));
  if (logs.size() > 1) log_->addItem(tr("every log it covers (%1)").arg(logs.size()), -1);
  log_->setCurrentIndex(preferred < logs.size() ? static_cast<int>(preferred) : 0);
  log_->setToolTip(tr("The log the phase belongs to: the one the selection was drawn on is offered first"));
  auto* form = new QFormLayout;
  auto* name_label = new QLabel(tr("&Phase name:"), this);
  name_label->setBuddy(name_);
  auto* log_label = new QLabel(tr("&Log:"), this);
  log_label->setBuddy(log_);
  form->addRow(name_label, name_);
  form->addRow(log_label, log_);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  connect(name_, &QLineEdit::textChanged, this,
          [buttons](const QString& t) { buttons->button(QDialogButtonBox::Ok)->setEnabled(!t.trimmed().isEmpty()); });
  form->addRow(buttons);
  setLayout(form);
  name_->setFocus();
}

QString SavePhaseDialog::name() const { return name_->text().trimmed(); }

std::vector<std::size_t> SavePhaseDialog::chosen() const {
  const int data = log_->currentData().toInt();
  if (data >= 0) return {static_cast<std::size_t>(data)};
  std::vector<std::size_t> all;
  for (std::size_t i = 0; i < count_; ++i) all.push_back(i);
  return all;
}

}  // namespace bs::ui
