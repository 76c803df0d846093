// SPDX-License-Identifier: GPL-3.0-or-later
// Replays a fuzz corpus through the same entry point as the libFuzzer target, in the ordinary (and the sanitizer)
// build: every regression input found by scripts/fuzz, and the seed corpus, must keep being rejected cleanly.
// Usage: replay_<id> [--third-party-absent=FOLDER]... DIR_OR_FILE...   Exit 0 when every input was handled; a
// finding aborts. --third-party-absent names a folder of third-party seeds (tests/fuzz/targets.txt, public:) that
// is not there: the inputs that are there are replayed all the same, and then the exit code is 77, CTest's
// "skipped", so that a replay without its real-file seeds is never reported as a full pass.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <string_view>
#include <vector>

#include "fuzz_importer.h"

namespace fs = std::filesystem;

int main(int argc, char** argv) {
  constexpr std::string_view kAbsent = "--third-party-absent=";
  std::vector<fs::path> files;
  std::string absent;
  for (int i = 1; i < argc; ++i) {
    if (const std::string_view a = argv[i]; a.starts_with(kAbsent)) {
      absent += (absent.empty() ? "" : ", ") + std::string(a.substr(kAbsent.size()));
      continue;
    }
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
  if (!absent.empty()) {
    std::printf("replay %s: SKIPPED the third-party seeds: needs %s (BENCHSCOPE_PUBLIC_DATA_DIR)\n",
                bs::fuzz::importer_id(), absent.c_str());
    return 77;
  }
  return 0;
}
