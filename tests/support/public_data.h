// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Third-party files (real logs and results other people published) are never committed to the project: they live in
// one shared folder, BENCHSCOPE_PUBLIC_DATA_DIR (the CMake cache variable, default <source>/../shared/public-data),
// at the path they would have had in the project (tests/data/power/real/..., resources/library/sources/...).
// docs/third-party-data.md says how to add one. A test names a third-party file like this:
//
//   void real_tegrastats_log() {
//     BENCHSCOPE_REQUIRE_PUBLIC_DATA("tests/data/power/real");  // skips, naming the folder, when it is absent
//     const std::string f = bs::test::public_data("tests/data/power/real/tegrastats-nano-jetpack4.log");
//     ...
//
// and ends with its QTEST_MAIN line as any test; tests/support/test_program_main.cpp makes a run that skipped for lack
// of such data reported by CTest as skipped, never as passed. Only an absent FOLDER skips: a folder that is there but
// lacks the file a test names fails the test, as any missing fixture does.
#include <QDir>
#include <QFileInfo>
#include <QString>
#include <QTest>

#include <cstdio>
#include <set>
#include <string>
#include <string_view>

#ifndef BENCHSCOPE_PUBLIC_DATA_DIR
#error "BENCHSCOPE_PUBLIC_DATA_DIR is given to every test by benchscope_add_test (tests/CMakeLists.txt)"
#endif

namespace bs::test {

// The third-party folder this test was configured with (absolute).
inline constexpr const char* kPublicDataDir = BENCHSCOPE_PUBLIC_DATA_DIR;

// The absolute path of a third-party file or folder, from its project path ("tests/data/power/real/x.log").
inline std::string public_data(std::string_view relative) {
  return std::string(kPublicDataDir) + "/" + std::string(relative);
}

// The third-party folders this run needed and did not find (each named once): what the skip reports.
inline std::set<std::string>& public_data_skips() {
  static std::set<std::string> skips;
  return skips;
}

// Whether the folder is there; records it among the skips when it is not.
inline bool public_data_present(std::string_view folder) {
  if (QFileInfo(QString::fromStdString(public_data(folder))).isDir()) return true;
  public_data_skips().insert(std::string(folder));
  return false;
}

inline QString public_data_skip_message(std::string_view folder) {
  return QStringLiteral("needs third-party data: %1 (BENCHSCOPE_PUBLIC_DATA_DIR=%2; see docs/third-party-data.md)")
      .arg(QString::fromUtf8(folder.data(), static_cast<qsizetype>(folder.size())),
           QDir::toNativeSeparators(QString::fromUtf8(kPublicDataDir)));
}

inline constexpr int kSkipReturnCode = 77;  // SKIP_RETURN_CODE of every test (tests/CMakeLists.txt)

// The exit code of a run whose QTest::qExec returned `failed` (the number of failed functions, or an error): a run
// in which nothing failed but a function skipped because its third-party folder is absent exits with 77 (CTest's
// skip, so the suite shows the test as skipped, not passed). A failure always wins, and is never read as 77.
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

// Skips the current test function (all of them, in initTestCase) when the third-party folder is absent. A statement
// in a test slot, before the first use of the folder's files.
#define BENCHSCOPE_REQUIRE_PUBLIC_DATA(folder)                                                                 \
  do {                                                                                                         \
    if (!bs::test::public_data_present(folder)) QSKIP(qPrintable(bs::test::public_data_skip_message(folder))); \
  } while (false)
