// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A file's bytes as text, for tests that hand a fixture to a text parser; an unreadable file throws (a test that
// parsed "" instead would check the wrong refusal).
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

namespace bs::test {

inline std::string file_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace bs::test
