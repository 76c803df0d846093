// SPDX-License-Identifier: GPL-3.0-or-later
// A window size saved on a 1600x1000 screen, restored on a 1280x800 one, is fitted to it (issue #32.7).
#include <QTest>

#include "common/screen_fit.h"

using bs::ui::fit_to_screen;

class TestScreenFit : public QObject {
  Q_OBJECT
 private slots:
  void a_larger_saved_size_is_fitted_and_moved_on_screen() {
    const QRect screen(0, 0, 1280, 800);
    const QMargins frame(2, 30, 2, 2);  // a title bar and thin borders
    // Saved at 1600x1000 on the larger screen, at (100, 80): too large and partly off this one.
    const QRect fitted = fit_to_screen(QRect(100, 80, 1600, 1000), frame, screen, QSize(900, 600));
    QCOMPARE(fitted.size(), QSize(1276, 768));
    QVERIFY(screen.contains(fitted.marginsAdded(frame)));
    QCOMPARE(fitted.topLeft(), QPoint(2, 30));
    // A window that fits is left alone.
    const QRect fits(50, 60, 1000, 700);
    QCOMPARE(fit_to_screen(fits, frame, screen, QSize(900, 600)), fits);
    // One that fits in size but hangs off the right edge is moved back, not shrunk.
    const QRect moved = fit_to_screen(QRect(600, 100, 1000, 600), frame, screen, QSize(900, 600));
    QCOMPARE(moved.size(), QSize(1000, 600));
    QVERIFY(screen.contains(moved.marginsAdded(frame)));
    // The minimum wins over a saved size below it (its frame off the top-left here), never over the screen.
    QCOMPARE(fit_to_screen(QRect(0, 10, 400, 300), frame, screen, QSize(900, 600)).size(), QSize(900, 600));
    QCOMPARE(fit_to_screen(QRect(0, 0, 2000, 2000), frame, screen, QSize(1500, 900)).size(), QSize(1276, 768));
  }

  // First start (issue #50.5): 1400x900 where it fits in 90 % of the screen, else 90 % of the screen.
  void the_first_size_fits_the_screen() {
    QCOMPARE(bs::ui::first_start_size(QRect(0, 0, 1600, 1000)), QSize(1400, 900));
    QCOMPARE(bs::ui::first_start_size(QRect(0, 0, 1280, 800)), QSize(1152, 720));
    QCOMPARE(bs::ui::first_start_size(QRect(0, 30, 1920, 850)), QSize(1400, 765));  // a panel takes 30 px
    QCOMPARE(bs::ui::first_start_size(QRect()), QSize(1400, 900));                  // no screen known
  }
};

QTEST_APPLESS_MAIN(TestScreenFit)
#include "test_screen_fit.moc"
