// SPDX-License-Identifier: GPL-3.0-or-later
#include "store/power_samples.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>

#include "store/tables.h"

namespace bs::store {

using sqlite::Statement;

void SampleProgress::advance(std::uint64_t n) {
  done += n;
  if (!cancel) return;
  cancel->throw_if_cancelled();
  if (total > 0) cancel->report(static_cast<double>(std::min(done, total)) / static_cast<double>(total), step);
}

void write_series(const sqlite::Db& db, std::int64_t trace_id, std::int64_t series, const std::vector<double>& values,
                  SampleProgress& progress) {
  Statement st(db, "INSERT INTO power_chunks(trace_id, series, first, vals) VALUES (?, ?, ?, ?)");
  for (std::size_t first = 0; first < values.size(); first += kChunkSamples) {
    const std::size_t n = std::min(kChunkSamples, values.size() - first);
    // Bound in place: the vector outlives the step, so SQLite need not copy the chunk first.
    st.bind(1, trace_id)
        .bind(2, series)
        .bind(3, static_cast<std::int64_t>(first))
        .bind_doubles_static(4, values.data() + first, n);
    st.run();
    progress.advance(n);
  }
}

std::vector<double> read_series(const sqlite::Db& db, std::int64_t trace_id, std::int64_t series, std::size_t samples,
                                SampleProgress& progress) {
  const auto corrupt = [&](const std::string& why) {
    throw WorkspaceError(WorkspaceError::Kind::Corrupt, db.path() + ": power trace " + std::to_string(trace_id) +
                                                            ", series " + std::to_string(series) + ": " + why);
  };
  // `samples` comes from the workspace too: it must equal what the chunks hold (their lengths, read without their
  // content) before anything is allocated from it.
  {
    Statement len(db, "SELECT COALESCE(SUM(length(vals)), 0) FROM power_chunks WHERE trace_id = ? AND series = ?");
    len.bind(1, trace_id).bind(2, series);
    const std::int64_t stored = len.step() ? len.int64(0) : 0;
    if (stored < 0 || stored % static_cast<std::int64_t>(sizeof(double)) != 0 ||
        static_cast<std::uint64_t>(stored) / sizeof(double) != samples)
      corrupt("holds " + std::to_string(stored / static_cast<std::int64_t>(sizeof(double))) +
              " samples, its summary says " + std::to_string(samples));
  }
  std::vector<double> out(samples);
  Statement st(db, "SELECT first, vals FROM power_chunks WHERE trace_id = ? AND series = ? ORDER BY first");
  st.bind(1, trace_id).bind(2, series);
  std::size_t next = 0;
  while (st.step()) {
    if (st.int64(0) < 0) corrupt("a chunk starts at " + std::to_string(st.int64(0)));
    const auto first = static_cast<std::size_t>(st.int64(0));
    std::size_t bytes = 0;
    const void* p = st.blob(1, bytes);
    if (first != next || bytes % sizeof(double) != 0 || first + bytes / sizeof(double) > samples)
      corrupt("sample chunks do not follow each other (chunk at " + std::to_string(first) + ", expected " +
              std::to_string(next) + ")");
    if (bytes > 0) std::memcpy(out.data() + first, p, bytes);  // straight into place: no second copy of the log
    next = first + bytes / sizeof(double);
    progress.advance(bytes / sizeof(double));
  }
  if (next != samples)
    corrupt("holds " + std::to_string(next) + " samples, its summary says " + std::to_string(samples));
  return out;
}

void write_summary(const sqlite::Db& db, std::int64_t trace_id, const std::vector<std::int64_t>& channel_ids,
                   const TraceSummary& summary_of) {
  Statement tr(db, "UPDATE power_traces SET samples = ?, duration_s = ? WHERE id = ?");
  tr.bind(1, static_cast<std::int64_t>(summary_of.samples)).bind(2, summary_of.duration_s).bind(3, trace_id).run();
  // The same columns, and so the same JSON and BLOB, as an import writes (store/tables.cpp).
  const auto column = [](const char* name) -> const Column<ChannelSummary>& {
    for (const auto& c : power_channels_table().columns)
      if (c.sql == name) return c;
    throw std::logic_error(std::string("power_channels has no column ") + name);
  };
  const auto& summary = column("summary");
  const auto& overview = column("overview");
  Statement ch(db, "UPDATE power_channels SET summary = ?, overview = ? WHERE id = ?");
  for (std::size_t k = 0; k < channel_ids.size() && k < summary_of.channels.size(); ++k) {
    summary.bind(ch, 1, summary_of.channels[k]);
    overview.bind(ch, 2, summary_of.channels[k]);
    ch.bind(3, channel_ids[k]).run();
  }
}

}  // namespace bs::store
