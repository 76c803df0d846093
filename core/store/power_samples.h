// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// How schema 6 keeps a power trace's samples and summary (store/schema.cpp, migrate_5_to_6):
//  - samples as BLOB chunks of kChunkSamples native doubles in power_chunks (series 0: time_s, else the
//    power_channels row id), so a 100-million-sample log is written and read a few MB at a time, with cancel and
//    progress between chunks, and never meets SQLite's 1 GB limit on one value;
//  - the summary (analysis/trace_summary.h) in power_traces.samples/duration_s and, per channel,
//    power_channels.summary (JSON statistics) and power_channels.overview (BLOB of t, v pairs).
// Used by the workspace (store/workspace.cpp) and by the migration that converts schema 5's one-BLOB traces.
#include <cstdint>
#include <vector>

#include "analysis/power/trace_summary.h"
#include "model/power_trace.h"
#include "store/sqlite_db.h"
#include "util/cancel.h"

namespace bs::store {

inline constexpr std::size_t kChunkSamples = std::size_t{1} << 18;  // 2 MiB of doubles

// Progress across everything one import or load moves: `done` samples of `total`, reported through the token.
struct SampleProgress {
  const CancelToken* cancel = nullptr;
  const char* step = "";
  std::uint64_t done = 0, total = 0;
  void advance(std::uint64_t n);  // polls cancel, reports done/total
};

// Writes `values` as chunks of series `series` of trace `trace_id` (inside the caller's transaction).
void write_series(const sqlite::Db& db, std::int64_t trace_id, std::int64_t series, const std::vector<double>& values,
                  SampleProgress& progress);
// Reads series `series` of `trace_id` (`samples` values expected). Throws WorkspaceError(Corrupt) when chunks are
// missing, overlap or do not add up to `samples`.
std::vector<double> read_series(const sqlite::Db& db, std::int64_t trace_id, std::int64_t series, std::size_t samples,
                                SampleProgress& progress);

// Stores the summary of trace `trace_id` whose channels' row ids are `channel_ids` (the trace's channel order).
void write_summary(const sqlite::Db& db, std::int64_t trace_id, const std::vector<std::int64_t>& channel_ids,
                   const TraceSummary& summary);

}  // namespace bs::store
