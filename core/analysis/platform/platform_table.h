// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The platform comparison as a table of formatted cells (units in the header, mean ± SD (n) for repeated
// timings, "–" for unknown), shared by the CLI, the GUI view and the LaTeX/CSV export so they always agree.
#include <span>

#include "analysis/platform/platform_comparison.h"
#include "util/table_export.h"

namespace bs {

// Column ids in table order, matching ExportTable::header; the GUI uses them to find a cell's source.
std::vector<std::string> platform_table_columns(bool with_verdicts);

// Optional verdicts (same order as rows) add "Meets constraints" and "Failed constraints (margin)" columns.
ExportTable platform_table(std::span<const PlatformRow> rows, std::span<const PlatformVerdict> verdicts = {});

}  // namespace bs
