// SPDX-License-Identifier: GPL-3.0-or-later
// make_bad_workspaces BASE.bsw OUT_DIR: writes every case of tests/data/bad-workspaces/manifest.json into OUT_DIR
// (scripts/make-bad-workspaces makes BASE from the paper data and calls this), to open them in BenchScope by hand.
#include <filesystem>
#include <iostream>

#include "bad_workspaces.h"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: make_bad_workspaces BASE.bsw OUT_DIR\n";
    return 2;
  }
  try {
    std::filesystem::create_directories(argv[2]);
    for (const auto& c : bs::test::load_bad_workspaces(BENCHSCOPE_TEST_DATA_DIR))
      std::cout << bs::test::make_bad_workspace(c, argv[1], argv[2]) << "  (" << c.expect << ")\n";
  } catch (const std::exception& e) {
    std::cerr << "make_bad_workspaces: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
