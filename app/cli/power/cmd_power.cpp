// SPDX-License-Identifier: GPL-3.0-or-later
// benchscope-cli power: statistics of current/power logs (the paper's section on current consumption), and
// `bench power-csv`, the throughput of the power-log parser against a getline + stod reference.
#include <malloc.h>
#include <unistd.h>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

#include <nlohmann/json.hpp>

#include "analysis/peaks/plausibility.h"
#include "analysis/power/power.h"
#include "analysis/power/power_phases.h"
#include "analysis/power/power_stats.h"
#include "analysis/power/range_table.h"
#include "analysis/stats/measurement_text.h"
#include "common/args.h"
#include "common/command.h"
#include "common/flag_output.h"
#include "common/signals.h"
#include "common/text_table.h"
#include "power/power_csv.h"
#include "power/power_import.h"
#include "store/log_settings_store.h"
#include "store/workspace.h"
#include "workspace/inputs.h"

namespace bs::cli {

int bench_power_csv(const std::vector<std::string>& raw, std::ostream& out);  // run by `bench power-csv`

namespace {

nlohmann::json signal_json(const std::optional<SignalStats>& s) {
  if (!s) return nullptr;
  return {{"n", s->summary.n},     {"mean", s->summary.mean}, {"sd", s->summary.sd},
          {"min", s->summary.min}, {"max", s->summary.max},   {"p5", s->pct.p5},
          {"p50", s->pct.p50},     {"p95", s->pct.p95},       {"p99", s->pct.p99}};
}

// "2.53 ± 0.35 A (n = 1200), min 1.92, p5 2.08 / p50 2.51 / p95 3.01 / p99 3.05, max 3.14 A"
std::string signal_line(const SignalStats& s, std::string_view unit) {
  const std::string u(unit);
  char buf[320];
  std::snprintf(buf, sizeof buf,
                "%.3f \xC2\xB1 %.3f %s (n = %zu), min %.3f, p5 %.3f / p50 %.3f / p95 %.3f / p99 %.3f, max %.3f %s",
                s.summary.mean, s.summary.sd, u.c_str(), s.summary.n, s.summary.min, s.pct.p5, s.pct.p50, s.pct.p95,
                s.pct.p99, s.summary.max, u.c_str());
  return buf;
}

struct LoadedTrace {
  PowerTrace trace;
  std::vector<std::string> warnings;
  std::vector<std::string> phase_origins;  // from a workspace: "log" or "user" per phase (empty: all "log")
};

// Files through the power importers with the options; a single workspace argument through the workspace.
std::vector<LoadedTrace> load_traces(const std::vector<std::string>& paths, const ParseOptions& options) {
  std::vector<LoadedTrace> out;
  if (paths.size() == 1 && looks_like_workspace(paths[0])) {
    for (PowerTrace& t : load_inputs(paths, interrupt_token()).power_traces) out.push_back({std::move(t), {}, {}});
    // Which phases the user saved (the GUI's "Save as phase…"), as the Power tab shows them.
    const Workspace ws(paths[0], Workspace::OpenMode::ReadOnly);
    const std::vector<StoredPowerTrace> stored = ws.power_trace_summaries();
    for (std::size_t i = 0; i < out.size() && i < stored.size(); ++i)
      if (stored[i].trace.label == out[i].trace.label) out[i].phase_origins = phase_origins(ws, stored[i].id);
    return out;
  }
  for (const InputFile& in : expand_inputs(paths)) {
    ImportBatch batch;
    try {
      batch = import_power_log(in.path, options, interrupt_token());
    } catch (const ImportError& e) {
      if (in.from_folder && (e.category() == ImportErrorCategory::UnknownFormat || skippable_in_folder(e))) continue;
      throw;
    }
    for (PowerTrace& t : batch.power_traces) out.push_back({std::move(t), batch.warnings, {}});
  }
  return out;
}

int run_power(const std::vector<std::string>& raw, std::ostream& out, std::ostream& err) {
  const ParsedArgs args = parse_args(raw, {"--json", "--phases"},
                                     {"--supply-volts", "--from", "--to", "--interval", "--min-phase", "--min-step"});
  if (args.positional.empty()) throw UsageError("power needs current/power log files (or a workspace)");
  ParseOptions options;
  PowerStatsOptions stats_options;
  if (args.value("--supply-volts")) {
    options.supply_voltage_v = args.number("--supply-volts", 0);
    if (!(*options.supply_voltage_v > 0)) throw UsageError("--supply-volts must be > 0");
    stats_options.supply_v = options.supply_voltage_v;
  }
  options.interval_s = args.number("--interval", 1.0);
  if (!(options.interval_s > 0)) throw UsageError("--interval must be > 0 s");
  if (args.value("--from")) stats_options.from_s = args.number("--from", 0);
  if (args.value("--to")) stats_options.to_s = args.number("--to", 0);
  if (stats_options.from_s && stats_options.to_s && *stats_options.to_s < *stats_options.from_s)
    throw UsageError("--to must not be before --from");
  PhaseOptions phase_options;
  phase_options.min_phase_s = args.number("--min-phase", 2.0);
  if (args.value("--min-step")) phase_options.min_step = args.number("--min-step", 0);
  if (!(phase_options.min_phase_s > 0) || (phase_options.min_step && !(*phase_options.min_step > 0)))
    throw UsageError("--min-phase and --min-step must be > 0");

  const std::vector<LoadedTrace> traces = load_traces(args.positional, options);
  if (traces.empty()) throw std::runtime_error("no current or power logs in the given inputs");
  const bool json = args.has("--json");
  nlohmann::json list = nlohmann::json::array();
  for (const LoadedTrace& lt : traces) {
    const PowerTrace& t = lt.trace;
    for (const std::string& w : lt.warnings) err << "warning: " << w << '\n';
    // One index per log answers the whole range and every phase (analysis/power_stats.h: the Power tab asks the
    // same index type, so both show the same numbers).
    const PowerIndex index(t, stats_options.supply_v);
    const PowerStats s = index.stats(stats_options.from_s, stats_options.to_s);
    const std::vector<PlausibilityFlag> flags = check_power_trace_bundled(t);  // of the whole log, not the range
    std::vector<PhaseStatsRow> phases;
    if (args.has("--phases"))  // the log's own phases (PTDaemon marks, runs, saved selections), then level changes
      phases = phase_stats_rows(index, t.phases, detect_level_phases(index, phase_options), lt.phase_origins);
    if (json) {
      nlohmann::json channels = nlohmann::json::array();
      for (const ChannelStats& c : s.channels)
        channels.push_back(
            {{"name", c.name}, {"unit", std::string(unit_of(c.quantity))}, {"stats", signal_json(c.stats)}});
      nlohmann::json phase_list = nlohmann::json::array();
      for (const PhaseStatsRow& p : phases) {
        const PowerStats& ps = p.stats;
        const auto opt = [](const std::optional<double>& v) {
          return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
        };
        phase_list.push_back({{"name", p.name},
                              {"origin", p.origin},
                              {"start_s", p.start_s},
                              {"end_s", p.end_s},
                              {"n", ps.n},
                              {"duration_s", ps.duration_s},
                              {"mean", ps.power_w     ? ps.power_w->summary.mean
                                       : ps.current_a ? ps.current_a->summary.mean
                                                      : 0.0},
                              {"current_a", signal_json(ps.current_a)},
                              {"power_w", signal_json(ps.power_w)},
                              {"charge_c", opt(ps.charge_c)},
                              {"energy_j", opt(ps.energy_j)},
                              {"mean_power_w", opt(ps.mean_power_w)}});
      }
      list.push_back({{"platform", t.platform},
                      {"label", t.label},
                      {"source_file", t.provenance.source_file},
                      {"origin", std::string(to_string(t.provenance.origin))},
                      {"measurement", measurement_text(t.provenance)},
                      {"measurement_kind", std::string(to_string(t.provenance.measurement))},
                      {"sensor", t.provenance.sensor},
                      {"start_time", t.start_time},
                      {"n", s.n},
                      {"rows", s.rows},
                      {"from_s", s.from_s},
                      {"to_s", s.to_s},
                      {"duration_s", s.duration_s},
                      {"power_source", std::string(to_string(s.power_source))},
                      {"supply_voltage_v", s.supply_v ? nlohmann::json(*s.supply_v) : nlohmann::json(nullptr)},
                      {"current_a", signal_json(s.current_a)},
                      {"power_w", signal_json(s.power_w)},
                      {"energy_j", s.energy_j ? nlohmann::json(*s.energy_j) : nlohmann::json(nullptr)},
                      {"charge_c", s.charge_c ? nlohmann::json(*s.charge_c) : nlohmann::json(nullptr)},
                      {"mean_power_w", s.mean_power_w ? nlohmann::json(*s.mean_power_w) : nlohmann::json(nullptr)},
                      {"channels", channels},
                      {"phases", phase_list},
                      {"warnings", lt.warnings},
                      {"flags", flags_json(flags)}});
      continue;
    }
    char line[512];
    std::snprintf(line, sizeof line, "%s (%s, %s): n = %zu over %.3f s (%.3f .. %.3f s)\n", t.label.c_str(),
                  t.platform.empty() ? "unknown platform" : t.platform.c_str(),
                  std::string(to_string(t.provenance.origin)).c_str(), s.n, s.duration_s, s.from_s, s.to_s);
    out << line << "  measured by: " << measurement_text(t.provenance) << '\n';
    for (const PlausibilityFlag& f : flags) out << "  \xE2\x9A\xA0 " << f.code << ": " << f.reason << '\n';
    if (s.current_a) out << "  current  " << signal_line(*s.current_a, "A") << '\n';
    if (s.power_w) {
      out << "  power    " << signal_line(*s.power_w, "W") << "\n           from the " << to_string(s.power_source);
      if (s.supply_v) out << " (" << format_number("%g", *s.supply_v) << " V)";
      out << '\n';
    } else {
      out << "  power    unknown: the log has current only; give --supply-volts\n";
    }
    if (s.energy_j)
      out << "  energy   " << format_number("%.1f", *s.energy_j) << " J (" << format_number("%.4f", *s.energy_j / 3600)
          << " Wh), trapezoidal; mean power " << format_number("%.3f", s.mean_power_w.value_or(0)) << " W over "
          << format_number("%.3f", s.duration_s) << " s\n";
    if (s.charge_c)
      out << "  charge   " << format_number("%.2f", *s.charge_c) << " C (" << format_number("%.2f", *s.charge_c / 3.6)
          << " mAh)\n";
    if (s.channels.size() > 1) {
      out << "  channels\n";
      for (const ChannelStats& c : s.channels)
        out << "    " << c.name << ": " << signal_line(c.stats, unit_of(c.quantity)) << '\n';
    }
    if (args.has("--phases")) {
      // The Power tab's per-phase table (analysis/range_table.h): the same columns and numbers.
      out << "  phases (the log's own, then level changes of at least "
          << format_number("%g", phase_options.min_phase_s) << " s)\n";
      const RangeSignal signal = default_signal(s);
      std::vector<std::string> header = {"phase", "origin", "from (s)", "to (s)"};
      for (std::string& h : range_headers(signal)) header.push_back(std::move(h));
      TextTable table(std::move(header));
      for (const PhaseStatsRow& p : phases) {
        std::vector<std::string> row = {p.name, p.origin, format_number("%.3f", p.start_s),
                                        format_number("%.3f", p.end_s)};
        for (std::string& c : range_cells(p.stats, signal, true)) row.push_back(std::move(c));
        table.add(std::move(row));
      }
      if (table.empty())
        out << "  (none)\n";
      else
        table.print(out);
    }
  }
  if (json) out << nlohmann::json{{"format", "benchscope-power"}, {"version", 2}, {"traces", list}}.dump(2) << '\n';
  return 0;
}

// ---- bench power-csv --------------------------------------------------------------------------------------

// Resident memory figures of this process (kB) from /proc; the peak can be reset with clear_refs (Linux >= 4.0).
long proc_status_kb(const char* key) {
  std::ifstream f("/proc/self/status");
  std::string line;
  const std::string k = std::string(key) + ":";
  while (std::getline(f, line))
    if (line.rfind(k, 0) == 0) return std::strtol(line.c_str() + k.size(), nullptr, 10);
  return -1;
}
bool reset_peak_rss() {
  std::ofstream f("/proc/self/clear_refs");
  f << "5";
  return static_cast<bool>(f);
}

struct ParseRun {
  double seconds = 0;
  double sum = 0;  // checksum of the parsed values, so both parsers are seen to agree
  std::size_t rows = 0;
  long peak_extra_kb = -1;  // peak resident memory above the level before parsing
};

template <class Parse>
ParseRun measure(Parse parse) {
  // Hand freed heap memory back first, or the previous run's pages are reused and the peak shows nothing.
  ::malloc_trim(0);
  const long before = proc_status_kb("VmRSS");
  const bool reset = reset_peak_rss();
  const auto t0 = std::chrono::steady_clock::now();
  ParseRun r = parse();
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (reset && before >= 0) r.peak_extra_kb = proc_status_kb("VmHWM") - before;
  return r;
}

// The plain way: std::getline per line, split at the comma, std::stod per cell.
ParseRun reference_parse(const std::string& path) {
  std::ifstream f(path);
  std::string line;
  std::getline(f, line);  // header
  std::vector<double> time, current;
  while (std::getline(f, line)) {
    const auto comma = line.find(',');
    time.push_back(std::stod(line.substr(0, comma)));
    current.push_back(std::stod(line.substr(comma + 1)));
  }
  ParseRun r;
  r.rows = time.size();
  for (std::size_t k = 0; k < time.size(); ++k) r.sum += time[k] + current[k];
  return r;
}

int bench_power_csv_impl(const std::vector<std::string>& raw, std::ostream& out) {
  const ParsedArgs args = parse_args(raw, {}, {"--rows", "--runs"});
  const double rows_arg = args.number("--rows", 1'000'000);
  const double runs_arg = args.number("--runs", 3);
  if (!(rows_arg >= 1000 && rows_arg <= 50'000'000)) throw UsageError("--rows must be between 1000 and 50,000,000");
  if (!(runs_arg >= 1 && runs_arg <= 20)) throw UsageError("--runs must be between 1 and 20");
  const auto rows = static_cast<std::size_t>(rows_arg);
  const int runs = static_cast<int>(runs_arg);
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("benchscope-bench-power-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "current.csv").string();
  struct Cleanup {
    std::filesystem::path dir;
    ~Cleanup() {
      std::error_code ec;
      std::filesystem::remove_all(dir, ec);
    }
  } cleanup{dir};
  {
    // A 1 kHz current log with a load step every second and some ripple: realistic digits, not one repeated row.
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) throw std::runtime_error("cannot write " + path);
    std::fputs("time_s,current_A\n", f);
    for (std::size_t k = 0; k < rows; ++k) {
      const double t = static_cast<double>(k) * 1e-3;
      const double i = ((k / 1000) % 2 ? 2.9 : 2.1) + 0.05 * std::sin(static_cast<double>(k) * 0.37);
      std::fprintf(f, "%.3f,%.6f\n", t, i);
    }
    std::fclose(f);
  }
  const double mb = static_cast<double>(std::filesystem::file_size(path)) / 1e6;
  // Warm the page cache so both parsers read from memory, then alternate them.
  {
    std::ifstream warm(path, std::ios::binary);
    std::string all((std::istreambuf_iterator<char>(warm)), {});
  }
  std::vector<double> ours_s, ref_s;
  ParseRun ours, ref;
  for (int r = 0; r < runs; ++r) {
    ours = measure([&] {
      const ImportBatch b = kPowerCsvFileFormat.parse(path, {}, {}, interrupt_token());
      ParseRun p;
      const PowerTrace& t = b.power_traces.at(0);
      p.rows = t.time_s.size();
      for (std::size_t k = 0; k < p.rows; ++k) p.sum += t.time_s[k] + t.channels[0].values[k];
      return p;
    });
    ours_s.push_back(ours.seconds);
    ref = measure([&] { return reference_parse(path); });
    ref_s.push_back(ref.seconds);
  }
  if (ours.rows != rows || ref.rows != rows || std::abs(ours.sum - ref.sum) > 1e-9 * std::abs(ref.sum))
    throw std::runtime_error("the two parsers disagree (rows " + std::to_string(ours.rows) + " vs " +
                             std::to_string(ref.rows) + ")");
  std::sort(ours_s.begin(), ours_s.end());
  std::sort(ref_s.begin(), ref_s.end());
  const double ours_med = ours_s[ours_s.size() / 2], ref_med = ref_s[ref_s.size() / 2];
  const double column_mb = static_cast<double>(rows) * 2 * sizeof(double) / 1e6;
  char line[256];
  std::snprintf(line, sizeof line,
                "power-csv bench: %zu rows of time_s,current_A, %.1f MB, page cache warm, 1 thread, median of %d\n",
                rows, mb, runs);
  out << line;
  std::snprintf(line, sizeof line, "  BenchScope power-csv (streaming, from_chars): %8.1f MB/s  (%.3f s)\n",
                mb / ours_med, ours_med);
  out << line;
  std::snprintf(line, sizeof line, "  reference std::getline + std::stod:            %8.1f MB/s  (%.3f s)\n",
                mb / ref_med, ref_med);
  out << line;
  std::snprintf(line, sizeof line, "  ratio: %.2fx\n", ref_med / ours_med);
  out << line;
  if (ours.peak_extra_kb >= 0) {
    std::snprintf(
        line, sizeof line,
        "  peak memory while parsing (last run, above the level before): BenchScope %.1f MB, reference %.1f MB;\n"
        "  parsed columns %.1f MB (2 x %zu doubles) -> BenchScope peak / columns = %.2f\n",
        static_cast<double>(ours.peak_extra_kb) / 1e3, static_cast<double>(ref.peak_extra_kb) / 1e3, column_mb, rows,
        static_cast<double>(ours.peak_extra_kb) / 1e3 / column_mb);
    out << line;
  } else {
    out << "  peak memory: not available (/proc/self/clear_refs not writable)\n";
  }
  return 0;
}

const CommandRegistrar registrar({
    "power",
    "statistics of current/power logs (mean \xC2\xB1 SD, percentiles, energy, phases)",
    "usage: benchscope-cli power (FILE... | FOLDER | WORKSPACE) [--supply-volts V] [--from S] [--to S] [--interval S]\n"
    "         [--phases [--min-phase S] [--min-step X]] [--json]\n"
    "  Per log: current and power (a power channel, else I x a voltage channel, else I x the supply voltage of a\n"
    "  current-only log) as mean \xC2\xB1 SD (n), min, p5/p50/p95/p99, max; energy (trapezoidal) and every channel "
    "(e.g.\n"
    "  tegrastats rails), over the whole log or seconds [S, S] from its start. --interval: seconds between\n"
    "  tegrastats lines without timestamps (default 1). A range cut between samples is interpolated at its ends.\n"
    "  --phases: a statistics table per phase (n, duration, mean, SD, min, max, p2p, p5/p50/p95, charge, energy,\n"
    "  mean power), for the log's own phases (PTDaemon marks, BenchScope's runs, selections saved in the Power tab)\n"
    "  and load phases found from level changes (--min-phase S, default 2; --min-step X in the signal's unit).\n"
    "  Formats: power CSV (generic, Joulescope, Otii, INA219 loggers), NVIDIA tegrastats, nvidia-smi --query-gpu\n"
    "  CSV (one trace per GPU), perf stat RAPL energy and SPEC PTDaemon (MLPerf spl.txt; marks as phases).",
    run_power,
});

}  // namespace

int bench_power_csv(const std::vector<std::string>& raw, std::ostream& out) { return bench_power_csv_impl(raw, out); }

}  // namespace bs::cli
