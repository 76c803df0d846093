// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A QTableWidget made ready for a core table (an ExportTable: the headroom phases, the inference runs): emptied,
// with the table's columns and their headings and room for its rows. The cells stay the view's to fill: each view
// aligns, colours and explains them its own way.
#include "util/table_export.h"

class QTableWidget;

namespace bs::ui {

void shape_table(QTableWidget* table, const ExportTable& t);

}  // namespace bs::ui
