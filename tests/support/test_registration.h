// SPDX-License-Identifier: GPL-3.0-or-later
// Included first into every test source (the room program's precompiled header, or -include): each test keeps
// its QTEST_MAIN / QTEST_GUILESS_MAIN / QTEST_APPLESS_MAIN line, and this file makes that line register the test's
// main under the test's file name (test_workspace.cpp -> "test_workspace") instead of defining `main`, so that the
// tests of a subject room link into one program (tests/CMakeLists.txt, issue #42). tests/support/
// test_program_main.cpp runs the one named on the command line, in its own process as before.
#pragma once

#include <QtTest/qtest.h>

#include "public_data.h"  // the exit code of a run that skipped for want of third-party files

namespace bs::test {
using TestMain = int (*)(int argc, char** argv);
// Registers `main` as the test named after the file (its base name without the extension). Returns true.
bool register_test(const char* file, TestMain main);
}  // namespace bs::test

// Qt's own definition (qtest.h) with `int main(...)` replaced by a function of the translation unit's anonymous
// namespace and its registration; the application object, initMain() and the source path are Qt's. The exit code
// is 77 (skipped) when nothing failed but third-party files were absent (public_data.h).
#undef QTEST_MAIN_WRAPPER
#define QTEST_MAIN_WRAPPER(TestObject, ...)                                                                          \
  namespace {                                                                                                        \
  int benchscope_test_main(int argc, char* argv[]) {                                                                 \
    TESTLIB_SELFCOVERAGE_START(#TestObject)                                                                          \
    QT_PREPEND_NAMESPACE(QTest::Internal::callInitMain)<TestObject>();                                               \
    __VA_ARGS__                                                                                                      \
    TestObject tc;                                                                                                   \
    QTEST_SET_MAIN_SOURCE_PATH                                                                                       \
    return bs::test::test_exit_code(QTest::qExec(&tc, argc, argv));                                                  \
  }                                                                                                                  \
  [[maybe_unused]] const bool benchscope_test_registered = bs::test::register_test(__FILE__, &benchscope_test_main); \
  }

// A test with a main of its own (e.g. one that must set up before the QApplication exists) names it here.
#define BENCHSCOPE_TEST_CUSTOM_MAIN(function)                                                            \
  namespace {                                                                                            \
  [[maybe_unused]] const bool benchscope_test_registered = bs::test::register_test(__FILE__, &function); \
  }
