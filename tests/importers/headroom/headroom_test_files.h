// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Where the headroom importer tests find their files: the project's own fixtures (tests/data/headroom, SOURCES
// there) and the third-party real outputs in the shared public-data folder (new/headroom, SOURCES.md there), which
// a checkout may lack: a test of a real file skips, naming the folder, when it is absent.
#include <QTest>

#include <algorithm>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "../../support/importer_parse.h"
#include "../../support/text_lines.h"
#include "common/format_importer.h"
#include "headroom/thread_latency.h"
#include "workspace/registry.h"

namespace bs::test {

inline const std::string kHeadroomFixtures = BENCHSCOPE_TEST_DATA_DIR "/headroom/";
inline const std::string kHeadroomReal = BENCHSCOPE_PUBLIC_DATA_DIR "/new/headroom/";

inline const headroom::ThreadLatency& only_thread(const ImportBatch& b, std::size_t index = 0) {
  return b.headroom.at(0).phases.at(0).threads.at(index);
}

inline bool has_warning(const ImportBatch& b, const std::string& text) { return any_line_contains(b.warnings, text); }

// A note of the first measurement's first phase containing `text`.
inline bool has_note(const ImportBatch& b, const std::string& text) {
  return any_line_contains(b.headroom.at(0).phases.at(0).notes, text);
}

// The first measurement's provenance setting `key`, "" when absent.
inline std::string setting(const ImportBatch& b, const std::string& key) {
  for (const auto& [k, v] : b.headroom.at(0).provenance.settings)
    if (k == key) return v;
  return {};
}

// Each file of `folder` (a name and the format id it must get) is sniffed as that format when imported, as the
// import dialog would open it: a test lists its files, the one loop checks them.
inline void each_is_sniffed_as(const std::string& folder,
                               const std::vector<std::pair<std::string, std::string>>& name_and_format) {
  const CancelToken cancel;
  for (const auto& [name, id] : name_and_format) QCOMPARE(import_file(folder + name, cancel).format, id);
}

}  // namespace bs::test

// Skips the current test when the real file is not there (a checkout without ../shared/public-data).
#define REQUIRE_REAL_FILE(name)                                                    \
  do {                                                                             \
    if (!std::filesystem::exists(bs::test::kHeadroomReal + (name)))                \
      QSKIP("needs the third-party file new/headroom/" name                        \
            " under BENCHSCOPE_PUBLIC_DATA_DIR (" BENCHSCOPE_PUBLIC_DATA_DIR ")"); \
  } while (false)
