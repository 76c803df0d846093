// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/wrapping_tool_bar.h"

#include <QActionEvent>
#include <QFrame>
#include <QTimer>
#include <QToolBar>
#include <QToolButton>
#include <algorithm>

namespace bs::ui {

FlowLayout::FlowLayout(QWidget* parent, int spacing) : QLayout(parent), spacing_(spacing) {
  setContentsMargins(2, 2, 2, 2);
}

FlowLayout::~FlowLayout() {
  while (QLayoutItem* item = takeAt(0)) delete item;
}

void FlowLayout::addItem(QLayoutItem* item) { items_.append(item); }

QLayoutItem* FlowLayout::itemAt(int index) const { return items_.value(index); }

QLayoutItem* FlowLayout::takeAt(int index) {
  return index >= 0 && index < items_.size() ? items_.takeAt(index) : nullptr;
}

QSize FlowLayout::minimumSize() const {
  QSize size;
  for (const QLayoutItem* item : items_) size = size.expandedTo(item->minimumSize());
  const QMargins m = contentsMargins();
  return size + QSize(m.left() + m.right(), m.top() + m.bottom());
}

void FlowLayout::setGeometry(const QRect& rect) {
  QLayout::setGeometry(rect);
  arrange(rect, true);
}

int FlowLayout::arrange(const QRect& rect, bool apply) const {
  const QMargins m = contentsMargins();
  const QRect area = rect.adjusted(m.left(), m.top(), -m.right(), -m.bottom());
  int x = area.x(), y = area.y(), row_height = 0;
  for (QLayoutItem* item : items_) {
    if (item->isEmpty()) continue;
    const QSize hint = item->sizeHint();
    if (x + hint.width() > area.right() + 1 && row_height > 0) {  // wrap: this one starts the next row
      x = area.x();
      y += row_height + spacing_;
      row_height = 0;
    }
    if (apply) item->setGeometry(QRect(QPoint(x, y), hint));
    x += hint.width() + spacing_;
    row_height = std::max(row_height, hint.height());
  }
  return y + row_height - rect.y() + m.bottom();
}

WrappingToolBar::WrappingToolBar(QToolBar* bar, QWidget* parent)
    : QWidget(parent), bar_(bar), flow_(new FlowLayout(this)) {
  bar_->hide();
  bar_->installEventFilter(this);
  QSizePolicy policy(QSizePolicy::Preferred, QSizePolicy::Preferred);
  policy.setHeightForWidth(true);
  setSizePolicy(policy);
  rebuild();
}

bool WrappingToolBar::eventFilter(QObject* watched, QEvent* event) {
  if (watched == bar_ && (event->type() == QEvent::ActionAdded || event->type() == QEvent::ActionRemoved))
    QTimer::singleShot(0, this, &WrappingToolBar::rebuild);            // after the bar has taken the action in
  if (watched == bar_ && event->type() == QEvent::Show) bar_->hide();  // the rows show its actions, not the bar
  return QWidget::eventFilter(watched, event);
}

void WrappingToolBar::rebuild() {
  while (QLayoutItem* item = flow_->takeAt(0)) {
    delete item->widget();
    delete item;
  }
  for (QAction* a : bar_->actions()) {
    if (a->isSeparator()) {
      auto* line = new QFrame(this);
      line->setFrameShape(QFrame::VLine);
      line->setFrameShadow(QFrame::Sunken);
      line->setFixedHeight(20);
      flow_->addWidget(line);
      continue;
    }
    auto* button = new QToolButton(this);
    button->setDefaultAction(a);  // triggers, enables, checks and tooltips follow the action
    button->setToolButtonStyle(Qt::ToolButtonTextOnly);
    button->setAutoRaise(true);
    flow_->addWidget(button);
  }
  updateGeometry();
}

int WrappingToolBar::button_count() const { return static_cast<int>(findChildren<QToolButton*>().size()); }

}  // namespace bs::ui
