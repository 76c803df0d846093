// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/table_shape.h"

#include <QStringList>
#include <QTableWidget>

namespace bs::ui {

void shape_table(QTableWidget* table, const ExportTable& t) {
  table->clear();
  table->setColumnCount(static_cast<int>(t.header.size()));
  table->setRowCount(static_cast<int>(t.rows.size()));
  QStringList header;
  for (const std::string& h : t.header) header << QString::fromStdString(h);
  table->setHorizontalHeaderLabels(header);
}

}  // namespace bs::ui
