// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The paper's sample data (sample_data/paper-2018) through the importers, as the GUI gets it from a workspace.
#include <algorithm>
#include <filesystem>
#include <vector>

#include "importer.h"

namespace bs::test {

inline void load_paper_sample(std::vector<FlopsRun>& runs, std::vector<PowerTrace>& traces) {
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::recursive_directory_iterator(BENCHSCOPE_SOURCE_DIR "/sample_data/paper-2018")) {
    const auto ext = e.path().extension();
    if (e.is_regular_file() && (ext == ".json" || ext == ".csv")) files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());  // directory order is not defined; the import order is
  for (const auto& f : files) {
    auto b = import_file(f.string(), CancelToken{});
    runs.insert(runs.end(), b.runs.begin(), b.runs.end());
    traces.insert(traces.end(), b.power_traces.begin(), b.power_traces.end());
  }
}

}  // namespace bs::test
