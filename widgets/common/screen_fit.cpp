// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/screen_fit.h"

#include <algorithm>

namespace bs::ui {

QRect fit_to_screen(const QRect& window, const QMargins& frame, const QRect& available, const QSize& minimum) {
  if (available.contains(window.marginsAdded(frame))) return window;
  const QSize room = available.marginsRemoved(frame).size();
  const QSize size = window.size().boundedTo(room).expandedTo(minimum.boundedTo(room));
  // The frame inside the available area; where it cannot fit, its top-left corner (the title bar) stays on screen.
  QRect outer(window.topLeft() - QPoint(frame.left(), frame.top()), size.grownBy(frame));
  outer.moveLeft(
      std::clamp(outer.left(), available.left(), std::max(available.left(), available.right() + 1 - outer.width())));
  outer.moveTop(
      std::clamp(outer.top(), available.top(), std::max(available.top(), available.bottom() + 1 - outer.height())));
  return outer.marginsRemoved(frame);
}

QSize first_start_size(const QRect& available, const QSize& preferred) {
  if (available.isEmpty()) return preferred;
  return preferred.boundedTo(QSize(available.width() * 9 / 10, available.height() * 9 / 10));
}

}  // namespace bs::ui
