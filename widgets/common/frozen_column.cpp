// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/frozen_column.h"

#include <algorithm>

#include <QEvent>
#include <QHeaderView>
#include <QScrollBar>
#include <QTableView>

namespace bs::ui {

FrozenFirstColumn::FrozenFirstColumn(QTableView* table)
    : QObject(table), table_(table), frozen_(new QTableView(table)) {
  frozen_->setObjectName(QStringLiteral("frozen-first-column"));
  frozen_->setModel(table->model());
  frozen_->setSelectionModel(table->selectionModel());
  frozen_->setFocusPolicy(Qt::NoFocus);
  frozen_->verticalHeader()->hide();
  frozen_->horizontalHeader()->setSectionResizeMode(QHeaderView::Fixed);
  frozen_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  frozen_->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  frozen_->setVerticalScrollMode(table->verticalScrollMode());
  frozen_->setEditTriggers(table->editTriggers());
  frozen_->setStyleSheet(
      QStringLiteral("QTableView#frozen-first-column { border: none; border-right: 1px solid palette(mid); }"));
  // Sorting from the overlay's header sorts the table (they share the model).
  frozen_->horizontalHeader()->setSectionsClickable(true);
  connect(frozen_->horizontalHeader(), &QHeaderView::sectionClicked, table, [table](int section) {
    const QHeaderView* h = table->horizontalHeader();
    const bool again = h->sortIndicatorSection() == section && h->sortIndicatorOrder() == Qt::AscendingOrder;
    table->sortByColumn(section, again ? Qt::DescendingOrder : Qt::AscendingOrder);
  });
  connect(table->horizontalHeader(), &QHeaderView::sectionResized, this, [this](int section, int, int size) {
    if (section == 0) {
      frozen_->setColumnWidth(0, size);
      update_geometry();
    }
  });
  connect(table->verticalHeader(), &QHeaderView::sectionResized, this,
          [this](int section, int, int size) { frozen_->setRowHeight(section, size); });
  // A double-click on a name in the overlay is a double-click on the table's cell (QTableWidget turns it into
  // cellDoubleClicked).
  connect(frozen_, &QAbstractItemView::doubleClicked, table,
          [table](const QModelIndex& index) { emit table->doubleClicked(index); });
  connect(frozen_->verticalScrollBar(), &QAbstractSlider::valueChanged, table->verticalScrollBar(),
          &QAbstractSlider::setValue);
  connect(table->verticalScrollBar(), &QAbstractSlider::valueChanged, frozen_->verticalScrollBar(),
          &QAbstractSlider::setValue);
  connect(table->model(), &QAbstractItemModel::modelReset, this, &FrozenFirstColumn::sync_columns);
  connect(table->model(), &QAbstractItemModel::columnsInserted, this, &FrozenFirstColumn::sync_columns);
  connect(table->model(), &QAbstractItemModel::layoutChanged, this, &FrozenFirstColumn::sync_columns);
  connect(table->model(), &QAbstractItemModel::rowsInserted, this, &FrozenFirstColumn::sync_columns);
  table->viewport()->stackUnder(frozen_);
  table->installEventFilter(this);
  // The viewport shrinks without the table resizing when a scroll bar appears: follow it too.
  table->viewport()->installEventFilter(this);
  sync_columns();
  frozen_->show();
}

FrozenFirstColumn::~FrozenFirstColumn() {
  table_->removeEventFilter(this);
  table_->viewport()->removeEventFilter(this);
  if (table_->model()) table_->model()->disconnect(this);
  delete frozen_;
}

void FrozenFirstColumn::sync_columns() {
  const int columns = table_->model()->columnCount();
  for (int c = 0; c < columns; ++c) frozen_->setColumnHidden(c, c != 0);
  frozen_->setColumnWidth(0, table_->columnWidth(0));
  frozen_->horizontalHeader()->setMinimumHeight(table_->horizontalHeader()->height());
  frozen_->horizontalHeader()->setFixedHeight(table_->horizontalHeader()->height());
  for (int r = 0; r < table_->model()->rowCount(); ++r) frozen_->setRowHeight(r, table_->rowHeight(r));
  update_geometry();
}

bool FrozenFirstColumn::eventFilter(QObject* watched, QEvent* event) {
  if (watched == table_ &&
      (event->type() == QEvent::Resize || event->type() == QEvent::LayoutRequest || event->type() == QEvent::Show))
    sync_columns();
  else if (watched == table_->viewport() && event->type() == QEvent::Resize)
    update_geometry();
  return QObject::eventFilter(watched, event);
}

void FrozenFirstColumn::update_geometry() {
  const int left = table_->verticalHeader()->isVisible() ? table_->verticalHeader()->width() : 0;
  // Never beyond the table's frame: a table squeezed to less than its header and one row would otherwise have the
  // overlay drawn over whatever lies under it.
  const int frame = table_->frameWidth();
  const int width = std::min(table_->columnWidth(0), table_->width() - left - 2 * frame);
  const int height =
      std::min(table_->viewport()->height() + table_->horizontalHeader()->height(), table_->height() - 2 * frame);
  frozen_->setGeometry(left + frame, frame, std::max(width, 0), std::max(height, 0));
}

}  // namespace bs::ui
