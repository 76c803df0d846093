// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Fitting a window to the screen it opens on (issue #32.7): a size saved at 1600x1000 restored on a 1280x800 screen
// opened partly off it, out of reach of the mouse.
#include <QMargins>
#include <QRect>
#include <QSize>

namespace bs::ui {

// The window's new geometry (client area, as QWidget::geometry): no larger than `available` less the frame
// (`frame`: title bar and borders around the client area), no smaller than `minimum` where the screen allows, and
// moved so that its frame lies inside `available`. `window` itself when it fits already.
QRect fit_to_screen(const QRect& window, const QMargins& frame, const QRect& available, const QSize& minimum);

// The window's size on first start and after View > Reset layout (issue #50.5): `preferred` where it fits in 90 % of
// the screen's available area (the rest is for the frame and the desktop's panels), else that 90 % in the direction
// that does not fit. 1400x900 opened larger than a 1280x800 screen.
QSize first_start_size(const QRect& available, const QSize& preferred = QSize(1400, 900));

}  // namespace bs::ui
