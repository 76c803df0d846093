// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// `benchscope-cli check`: everything that can be wrong with a workspace file, each finding on its own, without
// writing to the file. SQLite's own integrity and foreign-key checks, every value against the import rules (the
// reader's, store/row_map.h), sample chunks contiguous and complete, every sample finite, and each cached summary
// equal to the one its samples give. docs/workspace-check.md describes what is checked and what the user sees.
#include <string>
#include <vector>

#include "util/cancel.h"

namespace bs {

struct CheckFinding {
  std::string item;    // "sqlite", "workspace", "run #4 (NUC / NUC GPU, OpenCL rotation2d)", ...
  std::string reason;  // what is wrong, with the stored value and the rule
};

struct CheckReport {
  bool opened = false;     // false: the file could not be read as a workspace at all (the findings say why)
  int schema_version = 0;  // as stored in the file (0 when unknown)
  std::vector<CheckFinding> findings;
};

// Checks the workspace at `path`, read-only. Polls `cancel` between traces.
CheckReport check_workspace(const std::string& path, const CancelToken* cancel = nullptr);

}  // namespace bs
