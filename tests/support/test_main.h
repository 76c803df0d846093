// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// main() of a Qt Test suite that reads third-party files (tests/support/public_data.h): QTEST_MAIN,
// QTEST_GUILESS_MAIN and QTEST_APPLESS_MAIN, except for the exit code. A run in which nothing failed but a test
// function skipped because its third-party folder is absent exits with 77, which benchscope_add_test
// (tests/CMakeLists.txt) gives CTest as SKIP_RETURN_CODE: the suite then shows the test as skipped, not passed.
// A failure always wins: any failed function exits non-zero and never 77, whatever else was skipped.
#include <QtTest/qtest.h>

#include <cstdio>

#include "public_data.h"

namespace bs::test {

inline constexpr int kSkipReturnCode = 77;  // SKIP_RETURN_CODE of every test (tests/CMakeLists.txt)

// The exit code of a run whose QTest::qExec returned `failed` (the number of failed functions, or an error).
inline int test_exit_code(int failed) {
  if (failed != 0) return failed == kSkipReturnCode ? 1 : failed;
  if (public_data_skips().empty()) return 0;
  std::string folders;
  for (const std::string& f : public_data_skips()) folders += (folders.empty() ? "" : ", ") + f;
  std::fprintf(stderr, "SKIPPED: nothing failed, but the run needed third-party data it did not find: %s (%s)\n",
               folders.c_str(), kPublicDataDir);
  return kSkipReturnCode;
}

}  // namespace bs::test

// QTEST_MAIN_WRAPPER (qtest.h) with the exit code above.
#define BENCHSCOPE_TEST_MAIN_WRAPPER(TestObject, ...)                  \
  int main(int argc, char* argv[]) {                                   \
    QT_PREPEND_NAMESPACE(QTest::Internal::callInitMain)<TestObject>(); \
    __VA_ARGS__                                                        \
    TestObject tc;                                                     \
    QTEST_SET_MAIN_SOURCE_PATH                                         \
    return bs::test::test_exit_code(QTest::qExec(&tc, argc, argv));    \
  }

// QTEST_MAIN: a QApplication (QGuiApplication, QCoreApplication) as the test links Qt Widgets (Gui, neither).
#define BENCHSCOPE_TEST_MAIN(TestObject) BENCHSCOPE_TEST_MAIN_WRAPPER(TestObject, QTEST_MAIN_SETUP())
// QTEST_GUILESS_MAIN: a QCoreApplication.
#define BENCHSCOPE_TEST_GUILESS_MAIN(TestObject) \
  BENCHSCOPE_TEST_MAIN_WRAPPER(TestObject, QTEST_QAPP_SETUP(QCoreApplication))
// QTEST_APPLESS_MAIN: no application object.
#define BENCHSCOPE_TEST_APPLESS_MAIN(TestObject) BENCHSCOPE_TEST_MAIN_WRAPPER(TestObject)
