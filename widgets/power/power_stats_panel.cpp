// SPDX-License-Identifier: GPL-3.0-or-later
#include "power/power_stats_panel.h"

#include <QApplication>
#include <QClipboard>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

#include "analysis/power/range_table.h"

namespace bs::ui {

PowerStatsPanel::PowerStatsPanel(const QString& placeholder, bool can_save_phase, QWidget* parent)
    : QWidget(parent),
      caption_(new QLabel(placeholder, this)),
      table_(new QTableWidget(this)),
      copy_(new QPushButton(tr("Copy as table"), this)),
      placeholder_(placeholder) {
  caption_->setWordWrap(true);
  copy_->setToolTip(
      tr("Copy these rows to the clipboard as tab-separated text with units in the headers "
         "(pastes into a spreadsheet)"));
  copy_->setEnabled(false);
  connect(copy_, &QPushButton::clicked, this, [this] { QApplication::clipboard()->setText(tsv()); });
  table_->verticalHeader()->hide();
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  auto* top = new QHBoxLayout;
  top->addWidget(caption_, 1);
  if (can_save_phase) {
    save_ = new QPushButton(tr("Save as phase…"), this);
    save_->setToolTip(
        tr("Store the selection A–B as a named phase of the log it was drawn on (or another log it covers), in "
           "the workspace: it is then shaded, listed under Phases and printed by benchscope-cli power --phases"));
    save_->setEnabled(false);
    connect(save_, &QPushButton::clicked, this, &PowerStatsPanel::save_phase_requested);
    top->addWidget(save_);
  }
  top->addWidget(copy_);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 2, 0, 0);
  layout->addLayout(top);
  layout->addWidget(table_, 1);
}

void PowerStatsPanel::set_table(const QString& caption, const std::vector<std::string>& headers,
                                const std::vector<std::vector<std::string>>& rows, const std::vector<QString>& tips) {
  caption_->setText(caption);
  headers_ = headers;
  rows_ = rows;
  table_->setColumnCount(static_cast<int>(headers.size()));
  QStringList labels;
  for (const std::string& h : headers) labels << QString::fromStdString(h);
  table_->setHorizontalHeaderLabels(labels);
  table_->setRowCount(static_cast<int>(rows.size()));
  for (int r = 0; r < static_cast<int>(rows.size()); ++r)
    for (int c = 0; c < static_cast<int>(rows[static_cast<std::size_t>(r)].size()); ++c) {
      QTableWidgetItem* item = table_->item(r, c);  // reused while the mouse drags: no reallocation per move
      if (!item) {
        item = new QTableWidgetItem;
        table_->setItem(r, c, item);
      }
      item->setText(QString::fromStdString(rows[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)]));
      item->setTextAlignment(c == 0 ? Qt::AlignLeft | Qt::AlignVCenter : Qt::AlignRight | Qt::AlignVCenter);
      if (static_cast<std::size_t>(r) < tips.size()) item->setToolTip(tips[static_cast<std::size_t>(r)]);
    }
  copy_->setEnabled(!rows.empty());
  if (save_) save_->setEnabled(!rows.empty());
}

void PowerStatsPanel::clear_table() {
  caption_->setText(placeholder_);
  headers_.clear();
  rows_.clear();
  table_->setRowCount(0);
  copy_->setEnabled(false);
  if (save_) save_->setEnabled(false);
}

QString PowerStatsPanel::tsv() const { return QString::fromStdString(to_tsv(headers_, rows_)); }

}  // namespace bs::ui
