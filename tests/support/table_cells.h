// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Finding a cell of a view's table the way a person reads it, by the column's header and the row's first cell,
// so a test does not depend on where a column happens to stand. -1 when there is none: the test's next check (an
// item() of -1 is null) fails on it.
#include <QString>
#include <QTableWidget>

namespace bs::test {

// The column whose header reads `header`.
inline int column(const QTableWidget* t, const QString& header) {
  for (int c = 0; c < t->columnCount(); ++c)
    if (t->horizontalHeaderItem(c) && t->horizontalHeaderItem(c)->text() == header) return c;
  return -1;
}

// The first column whose header starts with `start` (headers that carry their unit, "Peak GFLOPS/W (run)").
inline int column_starting(const QTableWidget* t, const QString& start) {
  for (int c = 0; c < t->columnCount(); ++c)
    if (t->horizontalHeaderItem(c) && t->horizontalHeaderItem(c)->text().startsWith(start)) return c;
  return -1;
}

// The row whose first cell reads `first` (a platform's name).
inline int row_of(const QTableWidget* t, const QString& first) {
  for (int r = 0; r < t->rowCount(); ++r)
    if (t->item(r, 0) && t->item(r, 0)->text() == first) return r;
  return -1;
}

}  // namespace bs::test
