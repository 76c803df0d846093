// SPDX-License-Identifier: GPL-3.0-or-later
#include <QTest>
#include <cmath>
#include <map>

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
    // Issue #23.4: no two entries look alike (a measured AMD EPYC run looked like the NUC CPU): every pair is at
    // least 60 apart in RGB. The former palette had Okabe-Ito's sky blue and Tol's cyan, 55.7 apart.
    double closest = 1e9;
    for (int i = 0; i < 15; ++i)
      for (int j = i + 1; j < 15; ++j) {
        const QColor a = bs::ui::device_color(i), b = bs::ui::device_color(j);
        closest = std::min(closest, std::hypot(a.red() - b.red(), a.green() - b.green(), a.blue() - b.blue()));
      }
    QVERIFY2(closest >= 60, qPrintable(QString::number(closest)));
  }
  // Issue #23.4: a platform has one colour in Power, Battery and Platforms, whether or not it has devices.
  void one_colour_per_platform() {
    const auto colors = bs::ui::platform_color_indices({{"NUC", 3}, {"NUC", 1}, {"Jetson", 0}, {"NUC", 5}},
                                                       {"RobotPC", "NUC", "Jetson", "Alpha"});
    const std::map<std::string, int> got(colors.begin(), colors.end());
    QCOMPARE(got.at("NUC"), 1);  // its first device's colour
    QCOMPARE(got.at("Jetson"), 0);
    QCOMPARE(got.at("Alpha"), 2);  // power logs only: free indices in name order
    QCOMPARE(got.at("RobotPC"), 4);
    QCOMPARE(got.size(), std::size_t{4});
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
