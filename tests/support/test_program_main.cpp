// SPDX-License-Identifier: GPL-3.0-or-later
// The main of a subject room's test program (tests/CMakeLists.txt): `tests_core_store test_workspace [Qt Test
// arguments]` runs the test registered as "test_workspace" (tests/support/test_registration.h), with argv[0] set to
// the test's name so that its application name, and so its QSettings file, is its own as when every test was a
// program of its own (two tests of one program may run at the same time under ctest -j). Every test's settings
// belong to the organisation "BenchScopeTest", set here once: never a person's BenchScope settings.
#include <cstdio>
#include <cstring>
#include <map>
#include <string>
#include <vector>

#include <QCoreApplication>

#include "test_registration.h"

namespace {
std::map<std::string, bs::test::TestMain>& registry() {
  static std::map<std::string, bs::test::TestMain> tests;
  return tests;
}
}  // namespace

bool bs::test::register_test(const char* file, TestMain main) {
  std::string name = file;
  if (const auto slash = name.find_last_of('/'); slash != std::string::npos) name.erase(0, slash + 1);
  if (const auto dot = name.find_last_of('.'); dot != std::string::npos) name.erase(dot);
  if (!registry().emplace(name, main).second) {
    std::fprintf(stderr, "test program: two tests named %s\n", name.c_str());
    std::abort();
  }
  return true;
}

int main(int argc, char** argv) {
  const auto found = argc >= 2 ? registry().find(argv[1]) : registry().end();
  if (found == registry().end()) {
    std::fprintf(stderr, "usage: %s TEST [Qt Test arguments]\n%s:", argc ? argv[0] : "tests",
                 argc >= 2 ? "no such test here; the tests are" : "the tests are");
    for (const auto& [name, main] : registry()) std::fprintf(stderr, " %s", name.c_str());
    std::fprintf(stderr, "\n");
    return 2;
  }
  // argv[0] becomes the program's folder + the test's name; the test's own arguments follow.
  std::string self = argv[0];
  const auto slash = self.find_last_of('/');
  self = (slash == std::string::npos ? std::string() : self.substr(0, slash + 1)) + found->first;
  std::vector<char*> args{self.data()};
  for (int i = 2; i < argc; ++i) args.push_back(argv[i]);
  args.push_back(nullptr);
  QCoreApplication::setOrganizationName(QStringLiteral("BenchScopeTest"));
  return found->second(static_cast<int>(args.size()) - 1, args.data());
}
