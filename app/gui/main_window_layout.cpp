// SPDX-License-Identifier: GPL-3.0-or-later
// The window's size, docks and splits: fitted to the screen on first start and by View > Reset layout, remembered
// between sessions (QSettings), and a size saved on a larger screen fitted to this one.
#include <QDockWidget>
#include <QGuiApplication>
#include <QScreen>
#include <QSettings>
#include <QSplitter>

#include "common/screen_fit.h"
#include "main_window.h"
#include "platform/platform_view.h"

namespace bs::ui {

QSize MainWindow::first_start_size() const {
  // Before the window is shown it has no screen of its own: the primary one is where it will open.
  const QScreen* screen = this->screen() ? this->screen() : QGuiApplication::primaryScreen();
  return bs::ui::first_start_size(screen ? screen->availableGeometry() : QRect());
}

void MainWindow::restore_layout() {
  QSettings s;
  s.beginGroup(QStringLiteral("main-window"));
  // A size saved on a larger screen is fitted to this one (restoreGeometry keeps a too-large size as it was).
  if (const QByteArray g = s.value("geometry").toByteArray(); !g.isEmpty() && restoreGeometry(g)) clamp_to_screen();
  if (const QByteArray st = s.value("state").toByteArray(); !st.isEmpty()) restoreState(st);
  if (const QByteArray sp = s.value("flops-split").toByteArray(); !sp.isEmpty()) flops_split_->restoreState(sp);
  // Only where the person moved it: until then the tab fits its split to what it shows (platform_view_split.cpp).
  platforms_->restore_split(s.value("platforms-split").toByteArray());
  show_damage();  // the banner follows the workspace, never a remembered layout
}

void MainWindow::clamp_to_screen() {
  // A size saved on a larger screen (1600x1000) must not open off a smaller one (1280x800). Not under the offscreen
  // platform, whose 800x600 "screen" is no user's (tests there size windows themselves).
  if (QGuiApplication::platformName() == QLatin1String("offscreen")) return;
  const QScreen* screen = this->screen() ? this->screen() : QGuiApplication::primaryScreen();
  if (!screen) return;
  const QRect g = geometry(), f = frameGeometry();
  const QMargins frame(g.left() - f.left(), g.top() - f.top(), f.right() - g.right(), f.bottom() - g.bottom());
  const QRect fitted = fit_to_screen(g, frame, screen->availableGeometry(), minimumSizeHint());
  if (fitted != geometry()) setGeometry(fitted);
}

void MainWindow::save_layout() const {
  QSettings s;
  s.beginGroup(QStringLiteral("main-window"));
  s.setValue("geometry", saveGeometry());
  s.setValue("state", saveState());
  s.setValue("flops-split", flops_split_->saveState());
  if (const QByteArray split = platforms_->split_state(); !split.isEmpty())
    s.setValue("platforms-split", split);
  else
    s.remove("platforms-split");
}

void MainWindow::reset_layout() {
  restoreState(default_state_);
  flops_split_->restoreState(default_split_);
  platforms_->reset_split();
  for (QDockWidget* dock : findChildren<QDockWidget*>()) dock->show();
  resize(first_start_size());  // the screen the window is on now
  QSettings().remove(QStringLiteral("main-window"));
}

}  // namespace bs::ui
