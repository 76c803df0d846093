// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/power/range_table.h"

#include "analysis/power/sweep_energy.h"

#include <cstdio>

#include "analysis/power/power_phases.h"
#include "util/text.h"

namespace bs {
namespace {}  // namespace

RangeSignal default_signal(const PowerStats& s) { return s.power_w ? RangeSignal::Power : RangeSignal::Current; }

std::vector<std::string> range_headers(RangeSignal signal) {
  const std::string u = signal == RangeSignal::Power ? " (W)" : " (A)";
  return {"n",          "duration (s)", "mean" + u,   "SD" + u,      "min" + u,
          "max" + u,    "p2p" + u,      "p5" + u,     "p50" + u,     "p95" + u,
          "charge (C)", "charge (mAh)", "energy (J)", "energy (Wh)", "mean power (W)"};
}

std::vector<std::string> range_cells(const PowerStats& s, RangeSignal signal, bool mark_short) {
  const std::optional<SignalStats>& shown = signal == RangeSignal::Power ? s.power_w : s.current_a;
  std::vector<std::string> c;
  c.push_back(std::to_string(s.n) + (mark_short ? short_point_mark(s.n) : std::string()));
  c.push_back(format_number("%.4f", s.duration_s));
  if (shown) {
    const Summary& m = shown->summary;
    for (double v : {m.mean, m.sd, m.min, m.max, m.max - m.min}) c.push_back(format_number("%.4f", v));
    if (shown->has_percentiles)
      for (double v : {shown->pct.p5, shown->pct.p50, shown->pct.p95}) c.push_back(format_number("%.4f", v));
    else
      c.insert(c.end(), 3, "\xE2\x80\xA6");
  } else {
    c.insert(c.end(), 8, "-");
  }
  c.push_back(s.charge_c ? format_number("%.4f", *s.charge_c) : "-");
  c.push_back(s.charge_c ? format_number("%.4f", *s.charge_c / 3.6) : "-");  // 1 mAh = 3.6 C
  c.push_back(s.energy_j ? format_number("%.4f", *s.energy_j) : "-");
  c.push_back(s.energy_j ? format_number("%.6f", *s.energy_j / 3600) : "-");
  c.push_back(s.mean_power_w ? format_number("%.4f", *s.mean_power_w) : "-");
  return c;
}

std::string to_tsv(const std::vector<std::string>& headers, const std::vector<std::vector<std::string>>& rows) {
  std::string out;
  const auto line = [&](const std::vector<std::string>& cells) {
    for (std::size_t i = 0; i < cells.size(); ++i) out += (i ? "\t" : "") + cells[i];
    out += '\n';
  };
  line(headers);
  for (const auto& r : rows) line(r);
  return out;
}

std::vector<PhaseStatsRow> phase_stats_rows(const PowerIndex& index, const std::vector<TracePhase>& stored,
                                            const std::vector<TracePhase>& detected,
                                            const std::vector<std::string>& stored_origins) {
  std::vector<PhaseStatsRow> rows;
  const auto add = [&](const std::vector<TracePhase>& phases, const std::vector<std::string>* origins,
                       const char* origin) {
    for (std::size_t k = 0; k < phases.size(); ++k) {
      const TracePhase& p = phases[k];
      if (p.end_s < p.start_s) continue;  // a malformed mark: no range to summarise
      const std::string o = origins && k < origins->size() ? (*origins)[k] : std::string(origin);
      rows.push_back({p.name, o, p.start_s, p.end_s, index.stats(p.start_s, p.end_s)});
    }
  };
  add(stored, &stored_origins, "log");
  add(detected, nullptr, "detected");
  return rows;
}

std::vector<TracePhase> detect_level_phases(const PowerIndex& index, const PhaseOptions& options) {
  const TraceIndex* signal = index.main();
  if (!signal) return {};
  // The phases of k x v are those of v with the step scaled by 1/k (power as current x supply is a scaled index).
  PhaseOptions unscaled = options;
  if (unscaled.min_step) *unscaled.min_step /= signal->scale();
  return to_trace_phases(detect_phases(signal->time(), signal->unscaled_values(), unscaled));
}

}  // namespace bs
