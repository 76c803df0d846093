// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A user's name for a FLOPS run ("fan at 100 %", "after BIOS update"), shown after the run's own name in legends,
// tables, exports and the report. Kept in the workspace's settings ("run-label/<run id>", JSON with a fingerprint
// of the run), so no schema change is needed and the labels travel with the data. The fingerprint guards against a
// run id that SQLite hands out again after its run was removed: a new run never inherits an old run's label.
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "store/workspace.h"

namespace bs {

inline constexpr std::size_t kMaxRunLabelChars = 80;

// Sets (or, with an empty label, removes) the label of `run`. Leading and trailing spaces are trimmed. Throws
// std::invalid_argument for a label longer than kMaxRunLabelChars characters or with a control character, and
// WorkspaceError(Constraint) for a run that is not in `ws`.
void set_run_label(Workspace& ws, const StoredRun& run, std::string_view label);
// Run id -> label, for the runs of `runs` that have one and whose fingerprint still matches.
std::map<std::int64_t, std::string> run_labels(const Workspace& ws, const std::vector<StoredRun>& runs);
// The same for every run of the workspace, in ws.runs() order ("" where none).
std::vector<std::string> run_labels_in_order(const Workspace& ws);

}  // namespace bs
