// SPDX-License-Identifier: GPL-3.0-or-later
#include "remote/robot_queue_dialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace bs::ui {

RobotQueueDialog::RobotQueueDialog(const std::vector<remote::Robot>& robots, const QString& backend, QWidget* parent)
    : QDialog(parent), table_(new QTableWidget(this)), backend_(new QComboBox(this)) {
  setWindowTitle(tr("Run on several robots"));
  table_->setObjectName("robotQueue");
  table_->setColumnCount(3);
  table_->setHorizontalHeaderLabels({tr("Robot"), tr("Platform"), tr("Last contact")});
  table_->verticalHeader()->hide();
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  table_->horizontalHeader()->setStretchLastSection(true);
  table_->setRowCount(static_cast<int>(robots.size()));
  for (std::size_t i = 0; i < robots.size(); ++i) {
    const remote::Robot& r = robots[i];
    const int row = static_cast<int>(i);
    auto* name = new QTableWidgetItem(QString::fromStdString(r.name));
    name->setFlags(Qt::ItemIsUserCheckable | Qt::ItemIsEnabled);
    name->setCheckState(r.last_ok ? Qt::Checked : Qt::Unchecked);
    table_->setItem(row, 0, name);
    const std::string platform = !r.platform.empty() ? r.platform : !r.hostname.empty() ? r.hostname : r.name;
    auto* plat = new QTableWidgetItem(QString::fromStdString(platform));
    plat->setToolTip(tr("The platform this robot's results are stored under; edit to rename"));
    table_->setItem(row, 1, plat);
    auto* contact = new QTableWidgetItem(r.last_contact.empty() ? tr("never")
                                                                : QString::fromStdString(r.last_contact) +
                                                                      (r.last_ok ? QString() : tr(" (failed)")));
    contact->setFlags(Qt::ItemIsEnabled);
    table_->setItem(row, 2, contact);
  }
  for (const char* id : {"cpu", "cpu-scalar", "opencl", "cuda"})
    backend_->addItem(QString::fromLatin1(id), QString::fromLatin1(id));
  if (!backend.isEmpty() && backend_->findData(backend) < 0) backend_->addItem(backend, backend);
  backend_->setCurrentIndex(std::max(0, backend_->findData(backend.isEmpty() ? QStringLiteral("cpu") : backend)));
  backend_->setToolTip(
      tr("cpu: the CPU SIMD backend; opencl, cuda: the first device of each. A robot without it "
         "reports so and the others run on"));
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  buttons->button(QDialogButtonBox::Ok)->setText(tr("Run on the checked robots"));
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(new QLabel(tr("The sweep of the Kernel Runner runs on each checked robot, one after another; "
                                  "each robot's results appear in the FLOPS, Efficiency and Platforms tabs as they "
                                  "arrive."),
                               this));
  layout->addWidget(table_, 1);
  auto* form = new QFormLayout;
  form->addRow(tr("Backend"), backend_);
  layout->addLayout(form);
  layout->addWidget(buttons);
  resize(560, 320);
}

std::vector<std::pair<QString, QString>> RobotQueueDialog::chosen() const {
  std::vector<std::pair<QString, QString>> list;
  for (int r = 0; r < table_->rowCount(); ++r)
    if (table_->item(r, 0)->checkState() == Qt::Checked) {
      const QString platform = table_->item(r, 1)->text().trimmed();
      list.emplace_back(table_->item(r, 0)->text(), platform.isEmpty() ? table_->item(r, 0)->text() : platform);
    }
  return list;
}

QString RobotQueueDialog::backend() const { return backend_->currentData().toString(); }

}  // namespace bs::ui
