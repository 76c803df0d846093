// SPDX-License-Identifier: GPL-3.0-or-later
#include "workspace/import_warnings_dialog.h"

#include <QApplication>
#include <QClipboard>
#include <QDialogButtonBox>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>

#include "workspace/import_controller.h"

namespace bs::ui {

ImportWarningsDialog::ImportWarningsDialog(QWidget* parent)
    : QDialog(parent), headline_(new QLabel(this)), list_(new QListWidget(this)) {
  setWindowTitle(tr("Import warnings"));
  setModal(false);
  headline_->setWordWrap(true);
  list_->setWordWrap(true);
  list_->setAlternatingRowColors(true);
  list_->setSelectionMode(QAbstractItemView::ExtendedSelection);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
  QPushButton* copy = buttons->addButton(tr("Copy"), QDialogButtonBox::ActionRole);
  connect(copy, &QPushButton::clicked, this, [this] { QApplication::clipboard()->setText(text()); });
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::close);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(headline_);
  layout->addWidget(list_, 1);
  layout->addWidget(buttons);
  resize(820, 360);
}

void ImportWarningsDialog::set_report(const ImportReport& report) {
  const ImportMessage m = import_message(report);
  headline_->setText(m.headline);
  list_->clear();
  const auto add = [this](const QString& prefix, const QString& line) {
    auto* item = new QListWidgetItem(prefix + line, list_);
    item->setToolTip(line);
  };
  for (const QString& w : report.warnings) add(tr("warning: "), w);
  for (const QString& s : report.skipped) add(tr("skipped "), s);
}

QString ImportWarningsDialog::text() const {
  QStringList lines{headline_->text()};
  for (int i = 0; i < list_->count(); ++i) lines << list_->item(i)->text();
  return lines.join('\n');
}

}  // namespace bs::ui
