// SPDX-License-Identifier: GPL-3.0-or-later
// The Platforms tab's split (issue #50.5): the summary, the comparison, the inference table and the candidates one
// over the other. At 1280x800 with the candidates' figure and note in one layout, the comparison kept its header and
// at most one row; the split opens fitted to what each part holds and the person moves it from there.
#include <QEvent>
#include <QHeaderView>
#include <QLabel>
#include <QLayout>
#include <QScrollArea>
#include <QScrollBar>
#include <QSplitter>
#include <QTableWidget>
#include <algorithm>

#include "platform/candidates_panel.h"
#include "platform/inference_table.h"
#include "platform/platform_view.h"

namespace bs::ui {
namespace {

// The height a table needs for its header and its first `rows` rows (all: -1), scroll bar and frame included.
int rows_height(const QTableWidget* t, int rows = -1) {
  const QHeaderView* header = t->horizontalHeader();
  int h = std::max(header->sizeHint().height(), header->minimumHeight()) + 2 * t->frameWidth();
  if (t->horizontalScrollBar()->isVisible()) h += t->horizontalScrollBar()->sizeHint().height();
  const int n = rows < 0 ? t->rowCount() : std::min(rows, t->rowCount());
  for (int r = 0; r < n; ++r) h += t->rowHeight(r);
  return h;
}

// The least height `w` needs at `width` with its wrapped texts whole: each item of its layout at its minimum, a
// word-wrapped label at the height its text needs at that width.
int least_height_for_width(const QWidget* w, int width) {
  const QLayout* layout = w->layout();
  if (!layout) return w->minimumSizeHint().height();
  const QMargins m = layout->contentsMargins();
  const int inner = width - m.left() - m.right();
  int h = m.top() + m.bottom(), items = 0;
  for (int i = 0; i < layout->count(); ++i) {
    QLayoutItem* item = layout->itemAt(i);
    if (item->isEmpty()) continue;
    const auto* label = qobject_cast<const QLabel*>(item->widget());
    h += label && label->wordWrap() ? item->heightForWidth(inner) : item->minimumSize().height();
    ++items;
  }
  return h + std::max(0, items - 1) * layout->spacing();
}

}  // namespace

QByteArray PlatformView::split_state() const { return auto_split_ ? QByteArray() : split_->saveState(); }

void PlatformView::restore_split(const QByteArray& state) {
  if (!state.isEmpty() && split_->restoreState(state)) auto_split_ = false;
}

void PlatformView::reset_split() {
  auto_split_ = true;
  fit_split();
}

bool PlatformView::eventFilter(QObject* watched, QEvent* event) {
  // Before the splitter spreads a new height, or takes in a part's new minimum (the candidates' note grows with
  // them): the fitted sizes.
  if (watched == split_ && (event->type() == QEvent::Resize || event->type() == QEvent::LayoutRequest)) fit_split();
  return QWidget::eventFilter(watched, event);
}

// The summary whole, the comparison's rows whole, the inference rows (at most three), the candidates the rest, their
// note whole. Where that is more than the height, the summary gives up lines first (it scrolls), then the inference
// rows beyond the first, then the candidates down to their minimum (their figure's legend; their note wraps into
// fewer lines), and only then the comparison its rows beyond the first two: the comparison is what the tab is for.
void PlatformView::fit_split() {
  if (!auto_split_ || split_->height() <= 0) return;
  const bool inference = !inference_->isHidden();
  const int total = split_->height() - split_->handleWidth() * (inference ? 3 : 2);
  const int width = split_->width();
  int summary = summary_->heightForWidth(summary_box_->viewport()->width()) + 2;
  int table = rows_height(table_);
  // The inference table's title over its rows: what the widget needs beyond its table's minimum.
  const int title = inference_->minimumSizeHint().height() - inference_->table()->minimumSizeHint().height();
  int rows = inference ? title + std::min(rows_height(inference_->table()), rows_height(inference_->table(), 3)) : 0;
  int candidates = std::max(least_height_for_width(candidates_, width), candidates_->minimumSizeHint().height());
  int deficit = summary + table + rows + candidates - total;
  const auto give = [&deficit](int& pane, int floor) {
    const int taken = std::clamp(deficit, 0, std::max(0, pane - floor));
    pane -= taken;
    deficit -= taken;
  };
  give(summary, summary_box_->minimumHeight());
  give(rows, inference ? title + rows_height(inference_->table(), 1) : 0);
  give(candidates, candidates_->minimumSizeHint().height());
  give(table, rows_height(table_, 2));
  // What is left over goes to the comparison and the candidates (the panes that stretch).
  split_->setSizes({summary, table, rows, std::max(0, total - summary - table - rows)});
}

}  // namespace bs::ui
