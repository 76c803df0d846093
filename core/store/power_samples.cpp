// SPDX-License-Identifier: GPL-3.0-or-later
#include "store/power_samples.h"

#include <algorithm>
#include <cstring>
#include <string>

#include <nlohmann/json.hpp>

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
  std::vector<double> out(samples);
  Statement st(db, "SELECT first, vals FROM power_chunks WHERE trace_id = ? AND series = ? ORDER BY first");
  st.bind(1, trace_id).bind(2, series);
  std::size_t next = 0;
  const auto corrupt = [&](const std::string& why) {
    throw WorkspaceError(WorkspaceError::Kind::Corrupt, db.path() + ": power trace " + std::to_string(trace_id) +
                                                            ", series " + std::to_string(series) + ": " + why);
  };
  while (st.step()) {
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
                   const TraceSummary& summary) {
  Statement tr(db, "UPDATE power_traces SET samples = ?, duration_s = ? WHERE id = ?");
  tr.bind(1, static_cast<std::int64_t>(summary.samples)).bind(2, summary.duration_s).bind(3, trace_id).run();
  Statement ch(db, "UPDATE power_channels SET summary = ?, overview = ? WHERE id = ?");
  for (std::size_t k = 0; k < channel_ids.size() && k < summary.channels.size(); ++k) {
    const ChannelSummary& c = summary.channels[k];
    const Summary& s = c.stats.summary;
    const nlohmann::json j = {{"n", s.n},
                              {"mean", s.mean},
                              {"sd", s.sd},
                              {"min", s.min},
                              {"max", s.max},
                              {"p5", c.stats.pct.p5},
                              {"p50", c.stats.pct.p50},
                              {"p95", c.stats.pct.p95},
                              {"p99", c.stats.pct.p99},
                              {"integral", c.integral}};
    std::vector<double> pairs;
    pairs.reserve(c.overview.t.size() * 2);
    for (std::size_t i = 0; i < c.overview.t.size(); ++i) {
      pairs.push_back(c.overview.t[i]);
      pairs.push_back(c.overview.v[i]);
    }
    ch.bind(1, std::string_view(j.dump())).bind_doubles(2, pairs).bind(3, channel_ids[k]).run();
  }
}

SignalStats channel_stats_from_json(const std::string& text, double& integral) {
  const auto j = nlohmann::json::parse(text, nullptr, false);
  if (!j.is_object()) throw WorkspaceError(WorkspaceError::Kind::Corrupt, "power channel summary is not JSON: " + text);
  SignalStats s;
  try {
    s.summary.n = j.at("n").get<std::size_t>();
    s.summary.mean = j.at("mean").get<double>();
    s.summary.sd = j.at("sd").get<double>();
    s.summary.min = j.at("min").get<double>();
    s.summary.max = j.at("max").get<double>();
    s.pct.p5 = j.at("p5").get<double>();
    s.pct.p50 = j.at("p50").get<double>();
    s.pct.p95 = j.at("p95").get<double>();
    s.pct.p99 = j.at("p99").get<double>();
    integral = j.at("integral").get<double>();
  } catch (const nlohmann::json::exception& e) {
    throw WorkspaceError(WorkspaceError::Kind::Corrupt, std::string("power channel summary: ") + e.what());
  }
  return s;
}

}  // namespace bs::store
