// SPDX-License-Identifier: GPL-3.0-or-later
#include <QTest>

#include "device_palette.h"

class TestDevicePalette : public QObject {
  Q_OBJECT
 private slots:
  void stable_and_distinct() {
    QSet<QRgb> seen;
    for (int i = 0; i < 15; ++i) {
      QCOMPARE(bs::ui::device_color(i), bs::ui::device_color(i));
      seen.insert(bs::ui::device_color(i).rgb());
    }
    QCOMPARE(seen.size(), 15);
    QCOMPARE(bs::ui::device_color(15), bs::ui::device_color(0));  // wraps, never out of range
    QCOMPARE(bs::ui::device_color(-1), bs::ui::device_color(14));
  }
  void line_styles_by_dims() {
    QCOMPARE(bs::ui::dims_pen_style(1), Qt::DotLine);
    QCOMPARE(bs::ui::dims_pen_style(2), Qt::DashLine);
    QCOMPARE(bs::ui::dims_pen_style(4), Qt::SolidLine);
    QVERIFY(bs::ui::backend_marker_shape("CUDA") != bs::ui::backend_marker_shape("OpenCL"));
  }
};

QTEST_MAIN(TestDevicePalette)
#include "test_device_palette.moc"
