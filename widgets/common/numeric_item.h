// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A table cell that sorts by the number stored under kSortRole instead of its text ("170 ms" after "6.21 ms"), with
// cells whose number is unknown (NaN: shown as "–") last in either sort order; cells without a number sort by their
// text. The Platforms, Pipeline and inference tables share it.
#include <QHeaderView>
#include <QTableWidget>
#include <QTableWidgetItem>
#include <QVariant>
#include <cmath>

namespace bs::ui {

inline constexpr int kSortRole = Qt::UserRole + 1;

class NumericItem : public QTableWidgetItem {
 public:
  using QTableWidgetItem::QTableWidgetItem;
  bool operator<(const QTableWidgetItem& other) const override {
    const QVariant a = data(kSortRole), b = other.data(kSortRole);
    if (!a.isValid() || !b.isValid()) return QTableWidgetItem::operator<(other);
    const double x = a.toDouble(), y = b.toDouble();
    if (std::isnan(x) != std::isnan(y)) {
      const QTableWidget* view = tableWidget();
      const bool ascending = !view || view->horizontalHeader()->sortIndicatorOrder() == Qt::AscendingOrder;
      return std::isnan(x) ? !ascending : ascending;
    }
    return x < y;
  }
};

}  // namespace bs::ui
