// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A test on a screen of a person's size without an X server: Qt's offscreen platform reads its screens from a JSON
// file named in QT_QPA_PLATFORM, which must be set before the QApplication starts. The tests of a 1280x800 laptop
// screen (issues #43.6, #50.5) use it.
#include <QApplication>
#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QTest>

#include "test_registration.h"

namespace bs::test {

// Runs `run` (the tests: QTest::qExec on a test object) inside a QApplication whose one offscreen screen is
// `width` x `height` at 96 dpi. Returns its exit code, or 2 when the screen's file cannot be written.
template <typename Run>
int on_offscreen_screen(int argc, char** argv, int width, int height, Run run) {
  const QString config = QDir::temp().filePath(
      QStringLiteral("benchscope-%1x%2-%3.json").arg(width).arg(height).arg(QCoreApplication::applicationPid()));
  {
    QFile f(config);
    if (!f.open(QIODevice::WriteOnly)) return 2;
    f.write(QStringLiteral(R"({"screens": [{"name": "small", "x": 0, "y": 0, "width": %1, "height": %2,
                                               "logicalDpi": 96, "logicalBaseDpi": 96, "dpr": 1}]})")
                .arg(width)
                .arg(height)
                .toUtf8());
  }
  qputenv("QT_QPA_PLATFORM", "offscreen:configfile=" + config.toUtf8());
  int rc = 0;
  {
    QApplication app(argc, argv);
    rc = run();
  }
  QFile::remove(config);
  return rc;
}

}  // namespace bs::test

// main() of a test class run on an offscreen screen of W x H (registered under the test's file name).
#define BENCHSCOPE_OFFSCREEN_SCREEN_MAIN(TestClass, W, H)               \
  namespace {                                                           \
  int benchscope_offscreen_main(int argc, char** argv) {                \
    return bs::test::on_offscreen_screen(argc, argv, W, H, [&] {        \
      TestClass test;                                                   \
      return bs::test::test_exit_code(QTest::qExec(&test, argc, argv)); \
    });                                                                 \
  }                                                                     \
  }                                                                     \
  BENCHSCOPE_TEST_CUSTOM_MAIN(benchscope_offscreen_main)
