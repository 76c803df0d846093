// SPDX-License-Identifier: GPL-3.0-or-later
#include "platform/inference_table.h"

#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>
#include <cmath>
#include <limits>

#include "analysis/platform/inference_table.h"
#include "common/numeric_item.h"
#include "common/table_shape.h"

namespace bs::ui {
namespace {

QString provenance_tip(const DnnRun& r) {
  QString tip =
      QObject::tr("%1, %2 on %3\nmodel hash %4\n%5 FLOPs per forward pass (OpenCV's count: %6)\n%7\n%8, %9")
          .arg(QString::fromStdString(r.model), QString::fromStdString(r.backend), QString::fromStdString(r.device),
               QString::fromStdString(r.model_hash))
          .arg(static_cast<double>(r.flops), 0, 'g', 4)
          .arg(static_cast<double>(r.opencv_flops), 0, 'g', 4)
          .arg(QString::fromStdString(r.provenance.note), QString::fromUtf8(to_string(r.provenance.origin).data()),
               QString::fromStdString(r.provenance.host + " " + r.provenance.date));
  if (r.mean_power_w) tip += QObject::tr("\nmean power during the timed passes: %1 W").arg(*r.mean_power_w, 0, 'f', 2);
  if (r.architecture_only)
    tip = QObject::tr(
              "Built-in architecture with random weights: this row times the network's cost; it detects "
              "nothing.\n\n") +
          tip;
  return tip;
}

}  // namespace

InferenceTable::InferenceTable(QWidget* parent) : QWidget(parent) {
  title_ = new QLabel(tr("<b>Detection network inference</b> (bench dnn; per image, warm-up excluded)"), this);
  table_ = new QTableWidget(this);
  table_->setObjectName(QStringLiteral("inference_table"));
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->verticalHeader()->setVisible(false);
  table_->horizontalHeader()->setDefaultAlignment(Qt::Alignment(Qt::AlignCenter) | Qt::Alignment(Qt::TextWordWrap));
  table_->setWordWrap(true);
  table_->horizontalHeader()->setStretchLastSection(true);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(title_);
  layout->addWidget(table_, 1);
  setVisible(false);
}

void InferenceTable::set_runs(std::vector<DnnRun> runs) {
  runs_ = std::move(runs);
  const ExportTable t = inference_table(runs_);
  table_->setSortingEnabled(false);
  shape_table(table_, t);
  const int columns = static_cast<int>(InferenceColumn::Count);
  // The best value per numeric column (only marked when there is something to compare).
  std::vector<double> best(static_cast<std::size_t>(columns), std::numeric_limits<double>::quiet_NaN());
  for (const DnnRun& r : runs_)
    for (int c = 0; c < columns; ++c) {
      const auto col = static_cast<InferenceColumn>(c);
      const double v = inference_value(r, col);
      const int better = inference_better(col);
      double& b = best[static_cast<std::size_t>(c)];
      if (better != 0 && !std::isnan(v) && (std::isnan(b) || (better > 0 ? v > b : v < b))) b = v;
    }
  for (int i = 0; i < static_cast<int>(t.rows.size()); ++i) {
    const DnnRun& r = runs_[static_cast<std::size_t>(i)];
    const QString tip = provenance_tip(r);
    for (int c = 0; c < static_cast<int>(t.header.size()); ++c) {
      auto* item =
          new NumericItem(QString::fromStdString(t.rows[static_cast<std::size_t>(i)][static_cast<std::size_t>(c)]));
      item->setToolTip(tip);
      if (c < columns) {
        const auto col = static_cast<InferenceColumn>(c);
        const double v = inference_value(r, col);
        if (!std::isnan(v)) {
          item->setData(kSortRole, v);
          item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
          if (runs_.size() > 1 && v == best[static_cast<std::size_t>(c)]) {
            QFont f = item->font();
            f.setBold(true);
            item->setFont(f);
            item->setBackground(QColor(0xd9, 0xf2, 0xd9));
          }
        }
      }
      if (r.architecture_only && c == static_cast<int>(InferenceColumn::Network)) {
        QFont f = item->font();
        f.setItalic(true);
        item->setFont(f);
      }
      table_->setItem(i, c, item);
    }
  }
  table_->setSortingEnabled(true);
  table_->resizeColumnsToContents();
  table_->resizeRowsToContents();
  setVisible(!runs_.empty());
}

}  // namespace bs::ui
