// SPDX-License-Identifier: GPL-3.0-or-later
// benchscope-cli platforms: one column per platform (peaks, power, GFLOPS/W, pipeline, energy per frame, battery),
// and with constraints the recommendation: which platforms meet them, which constraint each one fails and by how
// much, and the one to pick.
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>

#include <nlohmann/json.hpp>

#include "analysis/library/candidates.h"
#include "analysis/platform/inference_table.h"
#include "analysis/platform/platform_table.h"
#include "common/args.h"
#include "common/command.h"
#include "common/flag_output.h"
#include "common/signals.h"
#include "common/text_table.h"
#include "headroom/headroom_table.h"
#include "platform/candidates_cli.h"
#include "platform/platform_args.h"
#include "platform/sustained_cli.h"
#include "store/decision_store.h"
#include "workspace/inputs.h"

namespace bs::cli {
namespace {

void write_file(const std::string& path, const std::string& text) {
  std::ofstream f(path, std::ios::binary);
  f << text;
  if (!f) throw std::runtime_error(path + ": cannot write");
}

std::string fmt_w(double w) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f W", w);
  return buf;
}

// The origins of the numbers in a platform's column (measured, reconstructed, published), each once.
// "5.25 (NUC GPU, OpenCL) [2]" -> "5.25 (NUC GPU, OpenCL) ⚠[2]": the table's footnote marker with the sign.
std::string with_warning_sign(const std::string& cell) {
  const auto open = cell.rfind(" [");
  if (open == std::string::npos || cell.back() != ']') return cell;
  return cell.substr(0, open + 1) + "\xE2\x9A\xA0" + cell.substr(open + 1);
}

nlohmann::json origins_json(const PlatformRow& r) {
  std::set<std::string> o;
  for (const auto& [col, src] : r.sources) o.insert(std::string(to_string(src.origin)));
  return nlohmann::json(std::vector<std::string>(o.begin(), o.end()));
}

nlohmann::json opt(const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(nullptr); }
// A stage's per-frame time: mean, SD (ms) and n; null when the platform has no pipeline run.
nlohmann::json stage_json(const std::optional<Summary>& s) {
  if (!s) return nullptr;
  return {{"mean", s->mean}, {"sd", s->sd}, {"n", s->n}};
}

// Each constraint check with its requirement, value (null: no data), verdict and margin.
nlohmann::json checks_json(const std::vector<ConstraintCheck>& checks) {
  nlohmann::json out = nlohmann::json::array();
  for (const ConstraintCheck& k : checks)
    out.push_back({{"name", k.name},
                   {"unit", k.unit},
                   {"required", k.required},
                   {"actual", opt(k.actual)},
                   {"met", k.met},
                   {"margin", k.margin}});
  return out;
}

nlohmann::json loop_json(const headroom::LoopRequirement& r, const std::vector<headroom::LoopVerdict>& loop) {
  nlohmann::json list = nlohmann::json::array();
  for (const headroom::LoopVerdict& v : loop) {
    list.push_back({{"platform", v.platform},
                    {"status", std::string(to_string(v.status))},
                    {"reason", v.reason},
                    {"measurement", v.measurement},
                    {"realtime", v.realtime},
                    {"checks", checks_json(v.checks)}});
  }
  return {{"requirement", r.text}, {"described", headroom::describe(r)}, {"platforms", list}};
}

// The loop requirement per platform, ranked: passing (widest margin first), failing (nearest first), unknown.
void print_loop(std::ostream& out, const headroom::LoopRequirement& r, const std::vector<headroom::LoopVerdict>& loop) {
  out << "\ncontrol loop: " << headroom::describe(r) << "\n";
  std::vector<std::string> header{"platform", "verdict"};
  for (const auto& k : loop.empty() ? std::vector<ConstraintCheck>{} : loop.front().checks) header.push_back(k.name);
  header.push_back("measurement / reason");
  TextTable t(header);
  for (const headroom::LoopVerdict& v : loop) {
    std::vector<std::string> row{v.platform, std::string(to_string(v.status))};
    for (std::size_t i = 0; i + 3 < header.size(); ++i) {
      const ConstraintCheck* k = i < v.checks.size() ? &v.checks[i] : nullptr;
      row.push_back(!k || !k->actual ? "–"
                                     : format_number("%g", *k->actual) + " " + k->unit + " (" +
                                           format_number("%+g", -k->margin) + ")");
    }
    row.push_back(v.status == RequirementStatus::Pass ? v.measurement
                                                      : v.reason + (v.measurement.empty() ? "" : "; " + v.measurement));
    t.add(row);
  }
  t.print(out);
  out << "(a platform without a headroom measurement at this rate and load is unknown, never passing; numbers in\n"
         " brackets are how far over (+) or under (-) each limit; non-real-time measurements are marked)\n";
}

int run_platforms(const std::vector<std::string>& raw, std::ostream& out) {
  std::set<std::string> values = platform_value_options();
  values.insert({"--latex", "--csv", "--library", "--candidates-csv", "--candidates-latex", "--use-log"});
  const ParsedArgs args = parse_args(raw, {"--json", "--no-stored", "--store"}, values);
  if (args.positional.empty()) throw UsageError("platforms needs a workspace or files");
  const bool one_workspace = args.positional.size() == 1 && looks_like_workspace(args.positional[0]);
  if (args.has("--store") && !one_workspace) throw UsageError("--store needs one workspace (WORKSPACE.bsw)");
  PlatformArgs platform_args = parse_platform_args(args);
  const BatteryPack* pack = &platform_args.pack;
  const ComparisonOptions& options = platform_args.options;
  const Constraints& c = platform_args.constraints;
  const bool constrained = platform_args.constrained();

  LoadedData data = load_inputs(args.positional, interrupt_token());
  // --use-log NUC=nuc-second-session.csv: that log for the NUC's numbers (with --store, from now on).
  if (const auto spec = args.value("--use-log")) {
    const std::size_t at = use_log(data.power_traces, *spec);
    platform_args.chosen_log_platforms.push_back(data.power_traces[at].platform);
  }
  // --store: the options in effect become the workspace's decision, as the GUI's Platforms tab keeps it.
  if (args.has("--store")) {
    Workspace ws(args.positional[0]);
    const StoredDecision d = decision_to_store(platform_args);
    set_stored_decision(ws, d);
    if (const auto spec = args.value("--use-log")) {
      const std::string platform = spec->substr(0, spec->find('=')), label = spec->substr(spec->find('=') + 1);
      for (const StoredPowerTrace& t : ws.power_trace_summaries())
        if (t.trace.platform == platform && t.trace.label == label) {
          set_chosen_log(ws, platform, t.id);
          break;
        }
    }
    const std::string words = describe_constraints(d);
    std::cerr << "platforms: stored in " << args.positional[0] << ": " << (words.empty() ? "no constraints" : words)
              << (args.value("--use-log") ? "; power log " + *args.value("--use-log") : std::string()) << '\n';
  }
  const auto pipelines = pipeline_timings(data.pipeline_runs);
  const auto rows = compare_platforms(data.runs, data.power_traces, pipelines, options);
  if (rows.empty()) throw std::runtime_error("no FLOPS runs or power logs to compare");
  auto verdicts = recommend(rows, c);
  // A control-loop requirement adds its checks to each platform's verdict (no measurement: unknown, never passing);
  // a sustained requirement likewise (no sustained run that answers it: unknown, never passing).
  const auto [loop, sustained] = judge_requirements(platform_args, rows, data);
  if (platform_args.loop) headroom::apply_loop(verdicts, loop);
  if (platform_args.sustained) sustain::apply_sustain(verdicts, sustained);
  const ExportTable table = platform_table(
      rows, constrained ? std::span<const PlatformVerdict>(verdicts) : std::span<const PlatformVerdict>());
  if (const auto p = args.value("--latex")) write_file(*p, to_latex(table));
  if (const auto p = args.value("--csv")) write_file(*p, to_csv(table));
  // Candidates: the own platforms beside the library's published results named by --library.
  std::vector<CandidateClass> classes;
  std::vector<PeakClass> peaks;
  std::vector<const LibraryResult*> library_results;  // the library results the selection names
  // The library computers given, else those the workspace's Platforms tab stored.
  const std::string library = args.value("--library").value_or(platform_args.library);
  const bool with_library = !library.empty();
  if (with_library) {
    CandidateInputs in = library_candidate_inputs(rows, data, library);
    if (platform_args.loop) in.loop = &loop;  // no class picks what the loop's verdict rejects
    if (platform_args.sustained) in.sustained = &sustained;
    classes = rank_candidates(in, c, options);
    peaks = peak_candidates(in);
    library_results = in.library;
    if (const auto p = args.value("--candidates-latex"))
      write_file(*p, to_latex(candidates_table(classes, constrained)));
    if (const auto p = args.value("--candidates-csv")) write_file(*p, to_csv(candidates_table(classes, constrained)));
  }

  if (args.has("--json")) {
    nlohmann::json list = nlohmann::json::array();
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const PlatformRow& r = rows[i];
      nlohmann::json sources = nlohmann::json::object();
      for (const auto& [col, s] : r.sources)
        sources[col] = {{"file", s.source_file}, {"origin", std::string(to_string(s.origin))}, {"how", s.how}};
      nlohmann::json column_flags = nlohmann::json::object();
      for (const auto& [col, f] : r.flags) column_flags[col] = flags_json(f);
      list.push_back({{"platform", r.platform},
                      {"origins", origins_json(r)},
                      {"gpu_peak_flops", r.gpu ? nlohmann::json(r.gpu->peak.flops) : nlohmann::json(nullptr)},
                      {"cpu_peak_flops", r.cpu ? nlohmann::json(r.cpu->peak.flops) : nlohmann::json(nullptr)},
                      {"mean_power_w", opt(r.mean_power_w)},
                      {"max_power_w", opt(r.max_power_w)},
                      {"gflops_per_watt_paper", opt(r.gflops_per_watt_paper)},
                      {"gflops_per_watt_mean_power", opt(r.gflops_per_watt_mean)},
                      {"preprocess_ms", stage_json(r.preprocess_ms)},
                      {"detect_ms", stage_json(r.detect_ms)},
                      {"fps", opt(r.fps)},
                      {"energy_per_frame_j", opt(r.energy_per_frame_j)},
                      {"energy_per_preprocess_j", opt(r.energy_per_preprocess_j)},
                      {"energy_per_inference_j", opt(r.energy_per_inference_j)},
                      {"battery_runtime_h", opt(r.battery_runtime_h)},
                      {"battery_load_w", opt(r.battery_load_w)},
                      {"frames_per_wh", opt(r.frames_per_wh)},
                      {"meets_constraints", verdicts[i].meets_all},
                      {"recommended", verdicts[i].recommended},
                      {"note", verdicts[i].note},
                      {"ranked_flops", verdicts[i].ranked_flops},
                      {"ranking_note", verdicts[i].ranking_note},
                      {"checks", checks_json(verdicts[i].checks)},
                      {"power_log", r.power_log},
                      {"power_logs", r.power_logs},
                      {"sources", sources},
                      {"power_measurement", r.power_measurement},
                      {"flags", flags_json(r.all_flags())},
                      {"column_flags", column_flags}});
    }
    out << nlohmann::json{{"format", "benchscope-platforms"},
                          {"version", 1},
                          {"battery", pack->name},
                          {"extra_load_w", options.extra_load_w},
                          {"mission", options.mission},
                          {"stored_in_workspace", platform_args.stored},
                          {"library", library},
                          {"platforms", list},
                          {"candidates", with_library ? candidates_json(classes, peaks) : nlohmann::json(nullptr)},
                          {"graph_benchmarks", with_library
                                                   ? graph_benchmarks_json(library_results, bundled_library().library)
                                                   : nlohmann::json(nullptr)},
                          {"control_loop",
                           platform_args.loop ? loop_json(*platform_args.loop, loop) : nlohmann::json(nullptr)},
                          {"sustained", platform_args.sustained ? sustained_json(*platform_args.sustained, sustained)
                                                                : nlohmann::json(nullptr)}}
               .dump(2)
        << '\n';
    return 0;
  }
  // Transposed for a terminal: one column per platform, one line per measure.
  std::vector<std::string> header{"measure"};
  for (const auto& r : table.rows) header.push_back(r[0]);
  TextTable text(header);
  for (std::size_t col = 1; col < table.header.size(); ++col) {
    std::vector<std::string> line{table.header[col]};
    // A flagged cell keeps its footnote number and shows the warning sign, as the GUI and the charts do.
    for (const auto& r : table.rows) line.push_back(with_warning_sign(r[col]));
    text.add(line);
  }
  text.print(out);
  // Which log each platform's power comes from, where it has several (the one chosen in the GUI, else its first).
  for (const PlatformRow& r : rows)
    if (r.power_logs > 1) {
      const auto& chosen = platform_args.chosen_log_platforms;
      out << "power log of " << r.platform << ": " << r.power_log << " ("
          << (std::find(chosen.begin(), chosen.end(), r.platform) != chosen.end() ? "chosen" : "the first") << " of "
          << r.power_logs << " logs)\n";
    }
  if (!table.notes.empty()) {
    out << "\nFlags (implausible numbers; docs/cli.md, \"Plausibility flags\"):\n";
    for (const std::string& n : table.notes) out << "  \xE2\x9A\xA0" << n << '\n';
  }
  char extra[64] = "";
  if (options.extra_load_w > 0) std::snprintf(extra, sizeof extra, ", plus %.1f W in parallel", options.extra_load_w);
  out << "battery: " << pack->name << " (" << pack->description << "), constant-power model" << extra;
  if (!options.mission.empty()) {
    out << ", mission " << options.mission << " repeated (mean load";
    for (const auto& r : rows)
      if (r.battery_load_w) out << ' ' << r.platform << ' ' << fmt_w(*r.battery_load_w);
    out << ')';
  }
  out << "\nframes per Wh: frames preprocessed and detected per Wh of the computer = 3600 / energy per frame (J)\n";
  for (const auto& v : verdicts)
    if (!v.ranking_note.empty()) out << "\xE2\x9A\xA0 ranking: " << v.platform << ": " << v.ranking_note << '\n';
  if (!data.dnn_runs.empty()) {
    // bench dnn runs, one row each: the table the Platforms and Pipeline views and the report show.
    const ExportTable inf = inference_table(data.dnn_runs);
    out << '\n' << inf.caption << ":\n";
    TextTable t(inf.header);
    for (const auto& r : inf.rows) t.add(r);
    t.print(out);
    for (const std::string& n : inf.notes) out << n << '\n';
  }
  if (with_library) {
    out << '\n';
    print_candidates(out, classes, peaks, constrained);
    print_graph_benchmarks(out, library_results, bundled_library().library);
  }
  if (platform_args.loop) print_loop(out, *platform_args.loop, loop);
  if (platform_args.sustained) print_sustained(out, *platform_args.sustained, sustained);
  if (!platform_args.stored.empty())
    out << "stored in the workspace (Platforms tab; --no-stored ignores it): " << platform_args.stored << '\n';
  if (constrained) {
    std::string chosen;
    for (const auto& v : verdicts)
      if (v.recommended) chosen = v.platform;
    out << (chosen.empty()
                ? "recommendation: no platform meets every constraint\n"
                : "recommendation: " + chosen + " (the most compute among the platforms that meet every constraint)\n");
  }
  return 0;
}

const CommandRegistrar registrar({
    "platforms",
    "platform comparison and recommendation under constraints (power budget, fps, battery runtime)",
    "usage: benchscope-cli platforms (WORKSPACE | PATH...) [--budget W] [--min-fps FPS] [--min-runtime MIN]\n"
    "                                [--battery PRESET] [--extra-load W] [--mission SPEC] [--supply-volts V]\n"
    "                                [--latex FILE] [--csv FILE] [--json]\n"
    "                                [--library COMPUTERS [--candidates-csv FILE] [--candidates-latex FILE]]\n"
    "                                [--require-loop SPEC] [--require-sustained SPEC] [--no-stored]\n"
    "                                [--use-log PLATFORM=LOG] [--store]\n"
    "  One column per platform: best GPU and CPU peak, % of theoretical peak, pipeline timings, mean and max power,\n"
    "  GFLOPS/W (the paper's peak / max power, and peak / mean power), energy per frame, battery runtime\n"
    "  (constant-power model on the battery preset, default the paper's 4S 3850 mAh) and frames per Wh (frames\n"
    "  preprocessed and detected per Wh of the computer: 3600 / energy per frame).\n"
    "  --mission name:seconds:watts,... (e.g. idle:60:12,walk:30:140,kick:5:225) adds the phases' loads (servos)\n"
    "  in parallel with each computer's mean power and --extra-load, repeated until the pack is empty, as\n"
    "  `battery --mission`: the battery runtime and the runtime constraint then follow the mission.\n"
    "  With constraints, each platform is checked against them (the power budget against the mean power) with its\n"
    "  margin, and the platform with the most compute among those that meet all of them is recommended. Only\n"
    "  platforms with a power log can be recommended. --latex/--csv write the table (booktabs / RFC 4180).\n"
    "  Detection networks timed with `bench dnn --workspace` follow in a table of their own: time per image,\n"
    "  inferences per second, achieved GFLOPS, energy per inference and inferences per Wh per network and target.\n"
    "  --library orin,pi5 (computer ids or aliases from `library list`, or result ids) adds published results as\n"
    "  candidates: inference results ranked with the own detection and bench dnn results under the same\n"
    "  constraints, within one network, scenario and precision only (what still differs is said in the row), and\n"
    "  compute peaks within one precision. Every row names its origin (measured, reconstructed, published) and\n"
    "  its source; --candidates-csv/--candidates-latex write the inference table.\n"
    "  --require-loop \"1kHz,p99.9<=200us,max-consecutive-misses<=1,load=pipeline@30fps\" checks each platform's\n"
    "  headroom measurement (benchscope-cli headroom): a loop RATE, limits p50|p99|p99.9|p99.99|max<=TIME (ns, us,\n"
    "  ms), misses<=PERCENT%, max-consecutive-misses<=N, in the phase load=PHASE (absent: every phase, the worst\n"
    "  decides). Platforms are ranked (passing, failing by how much, unknown); one without a measurement is unknown\n"
    "  and never passes; the recommendation counts the requirement like the other constraints.\n"
    "  --require-sustained \"stability>=97%,minutes>=20\" checks each platform's sustained runs (benchscope-cli\n"
    "  sustain, imported logs with clocks): stability>=PERCENT% (worst interval / best), minutes>=N (the run's\n"
    "  length), throttle=none, sustained>=RATE (mean of the last third, in the run's unit). The longest run that\n"
    "  answers every term judges, else the newest; passing, failing by how much, unknown (no run, too short, no\n"
    "  clock or zone exposed, a log without a rate for a rate term) never passes.\n"
    "  A workspace keeps what its Platforms tab set (constraints, the control loop among them, battery, parallel\n"
    "  load, mission, library candidates, the power log chosen per platform): options not given here take those\n"
    "  values, and the output says which; constraints given here (--require-loop, --require-sustained too) replace\n"
    "  the stored ones as a whole. --no-stored ignores them (the chosen logs still count).\n"
    "  --use-log NUC=nuc-second-session.csv takes that log for the platform's power (a platform has one power column:\n"
    "  its chosen log, else its first). --store keeps the options in effect (and --use-log) in the workspace, as the\n"
    "  Platforms tab does: the GUI, `report` and later runs then use them.",
    out_only<run_platforms>,
});

}  // namespace
}  // namespace bs::cli
