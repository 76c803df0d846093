// SPDX-License-Identifier: GPL-3.0-or-later
// Replays a fuzz corpus through the same entry point as the libFuzzer target, in the ordinary (and the sanitizer)
// build: every regression input found by scripts/fuzz, and the seed corpus, must keep being rejected cleanly.
// Usage: replay_<id> DIR_OR_FILE...   Exit 0 when every input was handled; a finding aborts.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include "fuzz_importer.h"

namespace fs = std::filesystem;

int main(int argc, char** argv) {
  std::vector<fs::path> files;
  for (int i = 1; i < argc; ++i) {
    const fs::path p = argv[i];
    if (fs::is_directory(p)) {
      for (const auto& e : fs::recursive_directory_iterator(p))
        if (e.is_regular_file()) files.push_back(e.path());
    } else if (fs::is_regular_file(p)) {
      files.push_back(p);
    }
  }
  std::sort(files.begin(), files.end());
  if (files.empty()) {
    std::fprintf(stderr, "replay %s: no inputs found\n", bs::fuzz::importer_id());
    return 1;
  }
  for (const auto& f : files) {
    std::ifstream in(f, std::ios::binary);
    const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    bs::fuzz::run_one(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
  }
  std::printf("replay %s: %zu inputs handled\n", bs::fuzz::importer_id(), files.size());
  return 0;
}
