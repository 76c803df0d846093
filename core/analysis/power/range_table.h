// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The statistics table of a time range (a selection, a phase, a whole log), as the Power tab shows it, copies it
// ("Copy as table": tab-separated, units in the headers) and `benchscope-cli power --phases` prints it: one set of
// columns and one way of writing each number, so the GUI and the CLI show the same table.
#include <optional>
#include <string>
#include <vector>

#include "analysis/power/power_phases.h"
#include "analysis/power/power_stats.h"

namespace bs {

// The signal whose level columns (mean, SD, min, max, p2p, p5/p50/p95) a row shows.
enum class RangeSignal { Current, Power };

// The signal shown for a trace's rows: power when it is known, else current.
RangeSignal default_signal(const PowerStats& s);

// "n", "duration (s)", "mean (W)", "SD (W)", "min (W)", "max (W)", "p2p (W)", "p5 (W)", "p50 (W)", "p95 (W)",
// "charge (C)", "charge (mAh)", "energy (J)", "energy (Wh)", "mean power (W)".
std::vector<std::string> range_headers(RangeSignal signal);
// The cells under those headers; "-" where a value is unknown (no current: no charge; no power: no energy), "…"
// for percentiles left out (PowerIndex::stats with_percentiles = false).
// `mark_short`: the n cell of a range sampled fewer than kMinSamplesPerPoint times carries short_point_mark()
// (analysis/power/sweep_energy.h), as phases' rows do in the Power tab and `power --phases`.
std::vector<std::string> range_cells(const PowerStats& s, RangeSignal signal, bool mark_short = false);

// Rows as tab-separated text, one header line first; cells must not contain tabs or newlines (they do not).
std::string to_tsv(const std::vector<std::string>& headers, const std::vector<std::vector<std::string>>& rows);

// A phase of a trace and its statistics: the per-phase table's row.
struct PhaseStatsRow {
  std::string name;
  std::string origin;  // "log" (stored with the trace: PTDaemon marks, BenchScope's runs), "user" (a selection
                       // the user saved) or "detected" (level changes, analysis/power_phases.h)
  double start_s = 0, end_s = 0;
  PowerStats stats;
};
// The stored phases of `trace` first, then `detected`, each over its own [start, end].
// `stored_origins`: "log" or "user" per stored phase (store/log_settings_store.h); missing ones are "log".
std::vector<PhaseStatsRow> phase_stats_rows(const PowerIndex& index, const std::vector<TracePhase>& stored,
                                            const std::vector<TracePhase>& detected,
                                            const std::vector<std::string>& stored_origins = {});

// Level changes of the trace's main signal (power, else current) as phases; empty when it has neither.
std::vector<TracePhase> detect_level_phases(const PowerIndex& index, const PhaseOptions& options);

}  // namespace bs
