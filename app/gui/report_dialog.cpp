// SPDX-License-Identifier: GPL-3.0-or-later
#include "report_dialog.h"

#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

#include "common/reading_label.h"

namespace bs::ui {

ReportDialog::ReportDialog(const QString& default_path, const QStringList& decision, QWidget* parent)
    : QDialog(parent), path_(new QLineEdit(default_path, this)), decision_(reading_label(this)) {
  setWindowTitle(tr("Export report"));
  path_->setObjectName(QStringLiteral("reportPath"));
  path_->setToolTip(tr("A .pdf file (A4, printed) or a .html file (one self-contained page with the figures)"));
  auto* browse = new QPushButton(tr("Browse…"), this);
  connect(browse, &QPushButton::clicked, this, [this] {
    const QString p =
        QFileDialog::getSaveFileName(this, tr("Report file"), path(), tr("PDF report (*.pdf);;HTML report (*.html)"));
    if (!p.isEmpty()) path_->setText(p);
  });
  auto* file_row = new QHBoxLayout;
  file_row->addWidget(path_, 1);
  file_row->addWidget(browse);
  auto* form = new QFormLayout;
  auto* file_label = new QLabel(tr("&File:"), this);
  file_label->setBuddy(path_);
  form->addRow(file_label, file_row);

  decision_->setObjectName(QStringLiteral("reportDecision"));
  decision_->setTextFormat(Qt::RichText);
  decision_->setText(decision.join("<br>"));
  auto* box = new QGroupBox(tr("Page 1 states this decision (set in the Platforms tab, kept in the workspace)"), this);
  auto* box_layout = new QVBoxLayout(box);
  box_layout->addWidget(decision_);
  auto* change = new QPushButton(tr("Change in the Platforms tab"), box);
  change->setToolTip(tr("Close this dialog and go to the Platforms tab, where the constraints are set"));
  connect(change, &QPushButton::clicked, this, [this] {
    change_ = true;
    reject();
  });
  box_layout->addWidget(change, 0, Qt::AlignLeft);

  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Cancel, this);
  export_ = buttons->addButton(tr("Export"), QDialogButtonBox::AcceptRole);
  export_->setDefault(true);
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  connect(path_, &QLineEdit::textChanged, this,
          [this](const QString& t) { export_->setEnabled(!t.trimmed().isEmpty()); });

  auto* layout = new QVBoxLayout(this);
  layout->addLayout(form);
  layout->addWidget(box, 1);
  layout->addWidget(buttons);
  setMinimumWidth(560);
}

QString ReportDialog::path() const {
  QString p = path_->text().trimmed();
  if (!p.endsWith(QStringLiteral(".pdf"), Qt::CaseInsensitive) &&
      !p.endsWith(QStringLiteral(".html"), Qt::CaseInsensitive) &&
      !p.endsWith(QStringLiteral(".htm"), Qt::CaseInsensitive))
    p += QStringLiteral(".html");
  return p;
}

bool ReportDialog::pdf() const { return path().endsWith(QStringLiteral(".pdf"), Qt::CaseInsensitive); }

}  // namespace bs::ui
