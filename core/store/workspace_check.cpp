// SPDX-License-Identifier: GPL-3.0-or-later
#include "store/workspace_check.h"

#include <algorithm>
#include <cmath>

#include "analysis/power/trace_summary.h"
#include "store/row_map.h"
#include "store/sqlite_db.h"
#include "store/workspace.h"

namespace bs {
namespace {

using sqlite::Statement;

// SQLite's view of the file: page structure, indexes, and rows whose parent does not exist. Done on a connection
// of its own, so it runs even when BenchScope's reading fails (a dropped table, a damaged schema).
void sqlite_checks(const std::string& path, CheckReport& report) {
  try {
    const sqlite::Db db(path, SQLITE_OPEN_READONLY);
    report.schema_version = static_cast<int>(db.pragma_int("PRAGMA user_version"));
    {
      Statement st(db, "PRAGMA integrity_check");
      while (st.step())
        if (st.text(0) != "ok") report.findings.push_back({"sqlite", "integrity check: " + st.text(0)});
    }
    Statement fk(db, "PRAGMA foreign_key_check");
    while (fk.step())
      report.findings.push_back({fk.text(0) + " row " + std::to_string(fk.int64(1)),
                                 "refers to a " + fk.text(2) + " row that does not exist (foreign key)"});
  } catch (const WorkspaceError& e) {
    report.findings.push_back({"sqlite", e.what()});
  }
}

// Stored imports say how many runs and result sets they brought; the rows must agree (damaged ones included: a
// damaged run is reported once, as itself).
void import_counts(const std::string& path, CheckReport& report) {
  try {
    const sqlite::Db db(path, SQLITE_OPEN_READONLY);
    Statement st(db,
                 "SELECT i.id, i.path, i.run_count, i.result_set_count, "
                 "(SELECT COUNT(*) FROM runs r WHERE r.import_id = i.id), "
                 "(SELECT COUNT(*) FROM result_sets s WHERE s.import_id = i.id) FROM imports i ORDER BY i.id");
    while (st.step()) {
      const std::string item = "import #" + std::to_string(st.int64(0)) + " '" + st.text(1) + "'";
      if (st.int64(2) != st.int64(4))
        report.findings.push_back({item, "imports.run_count says " + std::to_string(st.int64(2)) + ", " +
                                             std::to_string(st.int64(4)) + " runs are stored"});
      if (st.int64(3) != st.int64(5))
        report.findings.push_back({item, "imports.result_set_count says " + std::to_string(st.int64(3)) + ", " +
                                             std::to_string(st.int64(5)) + " result sets are stored"});
    }
  } catch (const WorkspaceError& e) {
    report.findings.push_back({"imports", e.what()});
  }
}

bool same(double a, double b) {
  if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b);
  return std::abs(a - b) <= 1e-9 * std::max({1.0, std::abs(a), std::abs(b)});
}

// A trace's cached summary against the one its samples give (the same functions, so equal up to rounding).
void summary_matches(const StoredPowerTrace& t, CheckReport& report) {
  const TraceSummary fresh = summarize_trace(t.trace);
  const std::string item = "power trace #" + std::to_string(t.id) + " '" + t.trace.label + "'";
  const auto differ = [&](const std::string& what, double stored, double computed) {
    if (!same(stored, computed))
      report.findings.push_back({item, what + ": the summary says " + store::number_text(stored) +
                                           ", the samples give " + store::number_text(computed)});
  };
  differ("duration_s", t.summary.duration_s, fresh.duration_s);
  for (std::size_t k = 0; k < fresh.channels.size() && k < t.summary.channels.size(); ++k) {
    const ChannelSummary& s = t.summary.channels[k];
    const ChannelSummary& f = fresh.channels[k];
    const std::string c = "channel '" + s.name + "' ";
    differ(c + "n", static_cast<double>(s.stats.summary.n), static_cast<double>(f.stats.summary.n));
    differ(c + "mean", s.stats.summary.mean, f.stats.summary.mean);
    differ(c + "sd", s.stats.summary.sd, f.stats.summary.sd);
    differ(c + "min", s.stats.summary.min, f.stats.summary.min);
    differ(c + "max", s.stats.summary.max, f.stats.summary.max);
    differ(c + "p5", s.stats.pct.p5, f.stats.pct.p5);
    differ(c + "p50", s.stats.pct.p50, f.stats.pct.p50);
    differ(c + "p95", s.stats.pct.p95, f.stats.pct.p95);
    differ(c + "p99", s.stats.pct.p99, f.stats.pct.p99);
    differ(c + "integral", s.integral, f.integral);
    bool overview_same = s.overview.t.size() == f.overview.t.size();
    for (std::size_t i = 0; overview_same && i < f.overview.t.size(); ++i)
      overview_same = same(s.overview.t[i], f.overview.t[i]) && same(s.overview.v[i], f.overview.v[i]);
    if (!overview_same) report.findings.push_back({item, c + "overview differs from the one its samples give"});
  }
}

}  // namespace

CheckReport check_workspace(const std::string& path, const CancelToken* cancel) {
  CheckReport report;
  std::optional<Workspace> ws;
  try {
    ws.emplace(path, Workspace::OpenMode::ReadOnly);
  } catch (const WorkspaceError& e) {
    // Not readable as a workspace: say why, and what SQLite itself finds when it is an SQLite file at all.
    report.findings.push_back({"workspace", e.what()});
    if (e.kind() != WorkspaceError::Kind::NotAWorkspace && e.kind() != WorkspaceError::Kind::Io &&
        e.kind() != WorkspaceError::Kind::NewerVersion)
      sqlite_checks(path, report);
    return report;
  }
  report.opened = true;
  sqlite_checks(path, report);
  for (const WorkspaceDamage& d : ws->damage())
    report.findings.push_back({d.item, describe(d).substr(d.item.size() + 2)});
  import_counts(path, report);
  for (StoredPowerTrace& t : ws->power_trace_summaries()) {
    if (cancel) cancel->throw_if_cancelled();
    try {
      ws->load_power_samples(t, cancel);
    } catch (const WorkspaceError& e) {
      std::string why = e.what();
      if (why.rfind(path + ": ", 0) == 0) why.erase(0, path.size() + 2);
      report.findings.push_back({"power trace #" + std::to_string(t.id) + " '" + t.trace.label + "'", why});
      continue;
    }
    summary_matches(t, report);
  }
  return report;
}

}  // namespace bs
