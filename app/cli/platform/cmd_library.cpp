// SPDX-License-Identifier: GPL-3.0-or-later
// benchscope-cli library list|show|compare: the library of published results (resources/library/library.json):
// what it holds with sources, one result in full, and published results beside a workspace's own platforms.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <system_error>

#include <nlohmann/json.hpp>

#include "analysis/library/candidates.h"
#include "analysis/platform/platform_comparison.h"
#include "common/args.h"
#include "common/command.h"
#include "common/signals.h"
#include "common/text_table.h"
#include "platform/candidates_cli.h"
#include "platform/platform_args.h"
#include "util/resources.h"
#include "workspace/inputs.h"

#ifdef BENCHSCOPE_WITH_FIGURES
#include "candidates_figure.h"
#include "platform/figure_cli.h"
#endif

namespace bs::cli {
namespace {

const Library& library_or_throw() {
  const BundledLibrary& b = bundled_library();
  if (!b.error.empty()) throw std::runtime_error("library: " + b.error);
  return b.library;
}

// Where the kept copy of a result's source would be: the library's kept sources are third-party files, never
// installed, in the shared folder of them (public_data_dir(), resources/library/ there). Empty when none is named.
std::filesystem::path kept_copy(const LibraryResult& r) {
  if (r.source.kept.empty()) return {};
  return public_data_dir() / "resources" / "library" / r.source.kept;
}

bool is_file(const std::filesystem::path& p) {
  std::error_code ec;
  return !p.empty() && std::filesystem::is_regular_file(p, ec);
}

std::string flags_cell(const LibraryResult& r) {
  std::string s;
  for (const PlausibilityFlag& f : r.flags) s += (s.empty() ? "⚠ " : ", ") + f.code;
  return s;
}

nlohmann::json metric_json(const std::optional<LibraryMetric>& m) {
  if (!m) return nullptr;
  nlohmann::json j = {{"metric", m->metric},
                      {"value", m->value},
                      {"unit", m->unit},
                      {"statistic", m->statistic},
                      {"text", official_text(*m)}};
  if (!m->definition.empty()) j["definition"] = m->definition;
  if (m->differs_by) j["official_differs_by"] = *m->differs_by;
  return j;
}

nlohmann::json result_json(const LibraryResult& r, const Library& lib) {
  nlohmann::json cond = nlohmann::json::object();
  for (const auto& [k, v] : r.conditions) cond[k] = v;
  nlohmann::json lines = nlohmann::json::object();
  for (const auto& [k, v] : r.source.lines) lines[k] = v;
  nlohmann::json flags = nlohmann::json::array();
  for (const PlausibilityFlag& f : r.flags) flags.push_back({{"code", f.code}, {"reason", f.reason}});
  const auto opt = [](const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(nullptr); };
  const LibraryComputer* computer = lib.computer(r.computer);
  nlohmann::json power_metric = nullptr;
  if (r.power_metric)
    power_metric = {{"value", r.power_metric->value},
                    {"unit", r.power_metric->unit},
                    {"definition", r.power_metric->definition},
                    {"checker", r.power_metric->checker}};
  return {{"id", r.id},
          {"origin", "published"},
          {"kind", r.kind},
          {"computer", r.computer},
          {"computer_name", lib.computer_name(r.computer)},
          {"stand_in", computer ? computer->stand_in : std::string()},
          {"ranked", r.not_ranked.empty()},
          {"not_ranked", r.not_ranked},
          {"note", r.note},
          {"official", metric_json(r.official)},
          {"plain_percentile", metric_json(r.plain_percentile)},
          {"power_metric", power_metric},
          {"power_kind", r.power_kind},
          {"power_samples", r.power_samples_w.size()},
          {"energy_statistic", r.energy_statistic},
          {"benchmark", r.benchmark},
          {"input", r.input},
          {"release", r.release},
          {"statistic", r.statistic},
          {"network", r.network},
          {"scenario", r.scenario},
          {"precision", r.precision},
          {"latency_s", opt(r.latency_s)},
          {"latency_statistic", r.latency_statistic},
          {"throughput_per_s", opt(r.throughput_per_s)},
          {"throughput_statistic", r.throughput_statistic},
          {"measure", r.measure},
          {"value", opt(r.value)},
          {"unit", r.unit},
          {"mean_power_w", opt(r.mean_power_w)},
          {"energy_per_sample_j", opt(r.energy_per_sample_j)},
          {"power_measurement", r.power_measurement},
          {"round", r.round},
          {"date", r.date},
          {"system", r.system},
          {"software", r.software},
          {"conditions", cond},
          {"source",
           {{"url", r.source.url},
            {"commit", r.source.commit},
            {"kept", r.source.kept},
            {"kept_copy", kept_copy(r).string()},
            {"kept_copy_present", is_file(kept_copy(r))},
            {"lines", lines},
            {"system", r.source.system},
            {"precision_from", r.source.precision_from},
            {"power_from", r.source.power_from},
            {"licence", r.source.licence}}},
          {"flags", flags}};
}

int run_list(const std::vector<std::string>& raw, std::ostream& out) {
  const ParsedArgs args = parse_args(raw, {"--json"}, {"--computer"});
  const Library& lib = library_or_throw();
  std::vector<const LibraryResult*> results;
  if (const auto c = args.value("--computer")) {
    try {
      results = select_library(lib, *c);
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("--computer: ") + e.what());
    }
  } else {
    for (const LibraryResult& r : lib.results) results.push_back(&r);
  }
  if (args.has("--json")) {
    nlohmann::json a = nlohmann::json::array();
    for (const LibraryResult* r : results) a.push_back(result_json(*r, lib));
    nlohmann::json unused = nlohmann::json::array();
    for (const LibraryKeptNote& k : lib.kept_not_used) unused.push_back({{"kept", k.kept}, {"why", k.why}});
    out << nlohmann::json{{"format", "benchscope-library-list"},
                          {"library", lib.path},
                          {"results", a},
                          {"kept_not_used", unused}}
               .dump(2)
        << '\n';
    return 0;
  }
  TextTable t({"Id", "Computer", "Origin", "What", "Precision", "Result", "Round / date", "Flags"});
  std::set<std::string> computers;
  for (const LibraryResult* r : results) {
    computers.insert(r->computer);
    const std::string what =
        r->is_inference() ? r->network + " " + r->scenario : r->measure + (r->device.empty() ? "" : ", " + r->device);
    t.add({r->id, lib.computer_name(r->computer), "published", what, r->precision, library_result_summary(*r),
           r->round + (r->date.empty() ? "" : " (" + r->date + ")"), flags_cell(*r)});
  }
  t.print(out);
  out << results.size() << " published results for " << computers.size() << " computers (" << lib.path
      << "); sources: `benchscope-cli library show ID`\n";
  out << "MLPerf rows show the round's official metric first (from v2.0 SingleStream/MultiStream: LoadGen's "
         "early-stopping estimate) and the plain percentile beside it where different; power is AC wall power of "
         "the whole system unless said.\n";
  return 0;
}

int run_show(const std::vector<std::string>& raw, std::ostream& out) {
  const ParsedArgs args = parse_args(raw, {"--json"}, {});
  if (args.positional.size() != 1) throw UsageError("library show needs one result id (see `library list`)");
  const Library& lib = library_or_throw();
  const LibraryResult* r = lib.result(args.positional[0]);
  if (!r) throw UsageError("no library result '" + args.positional[0] + "' (see `library list`)");
  if (args.has("--json")) {
    out << result_json(*r, lib).dump(2) << '\n';
    return 0;
  }
  out << r->id << "  (origin: published)\n";
  out << "  computer:    " << lib.computer_name(r->computer) << (r->system.empty() ? "" : " — system " + r->system)
      << '\n';
  if (r->is_inference())
    out << "  network:     " << r->network << ", scenario " << r->scenario << ", precision " << r->precision << '\n';
  else
    out << "  measure:     " << r->measure << " (" << r->variant << "), " << r->device << ", precision " << r->precision
        << '\n';
  if (const LibraryComputer* c = lib.computer(r->computer); c && !c->stand_in.empty())
    out << "  stand-in:    " << c->stand_in << '\n';
  if (!r->not_ranked.empty()) out << "  NOT RANKED:  " << r->not_ranked << '\n';
  if (!r->note.empty()) out << "  note:        " << r->note << '\n';
  if (r->official) {
    out << "  official:    " << r->official->statistic << " " << official_text(*r->official) << " — "
        << r->official->definition << '\n';
    if (r->plain_percentile)
      out << "  plain:       " << r->plain_percentile->statistic << " " << official_text(*r->plain_percentile)
          << " (the summary's percentile line; not the official result)\n";
  }
  if (r->power_metric)
    out << "  power:       " << r->power_metric->value << " " << r->power_metric->unit << " — "
        << r->power_metric->definition << " (" << r->power_metric->checker << ")\n";
  if (!r->power_measurement.empty()) out << "  measured:    " << r->power_measurement << '\n';
  out << "  result:      " << library_result_summary(*r) << '\n';
  out << "  round/date:  " << r->round << (r->date.empty() ? "" : " (" + r->date + ")")
      << (r->division.empty() ? "" : ", " + r->division) << (r->submitter.empty() ? "" : ", " + r->submitter)
      << (r->validity.empty() ? "" : ", " + r->validity) << '\n';
  out << "  software:    " << r->software << '\n';
  for (const auto& [k, v] : r->conditions) out << "  condition:   " << k << ": " << v << '\n';
  out << "  source:      " << r->source.url << '\n';
  if (const std::filesystem::path copy = kept_copy(*r); !copy.empty()) {
    out << "  kept copy:   " << copy.string();
    if (!is_file(copy))
      out << "  (not here: kept sources are third-party files, not installed; set BENCHSCOPE_PUBLIC_DATA_DIR to the "
             "folder that has resources/library/sources/)";
    out << '\n';
  }
  if (!r->source.precision_from.empty())
    out << "  precision:   " << r->source.precision_from << " (" << r->source.precision_rule << ")\n";
  for (const auto& [k, v] : r->source.lines)
    out << "  line " << v << ":" << std::string(6 - std::min<std::size_t>(6, std::to_string(v).size()), ' ') << k
        << '\n';
  if (!r->source.licence.empty()) out << "  licence:     " << r->source.licence << '\n';
  for (const PlausibilityFlag& f : r->flags) out << "  ⚠ " << f.code << ": " << f.reason << '\n';
  return 0;
}

int run_compare(const std::vector<std::string>& raw, std::ostream& out) {
  std::set<std::string> values = platform_value_options();
  values.insert({"--csv", "--latex", "--figure"});
  const ParsedArgs args = parse_args(raw, {"--json"}, values);
  if (args.positional.empty())
    throw UsageError("library compare needs COMPUTERS (e.g. orin,pi5), then optionally a workspace or files");
  const PlatformArgs pa = parse_platform_args(args);
  const Library& lib = library_or_throw();
  CandidateInputs in;
  in.lib = &lib;
  try {
    in.library = select_library(lib, args.positional[0]);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  LoadedData data;
  std::vector<PlatformRow> rows;
  if (args.positional.size() > 1) {
    data = load_inputs(std::vector<std::string>(args.positional.begin() + 1, args.positional.end()), interrupt_token());
    rows = compare_platforms(data.runs, data.power_traces, pipeline_timings(data.pipeline_runs), pa.options);
  }
  in.platforms = rows;
  in.pipelines = data.pipeline_runs;
  in.dnn_runs = data.dnn_runs;
  in.result_sets = data.result_sets;
  const auto classes = rank_candidates(in, pa.constraints, pa.options);
  const auto peaks = peak_candidates(in);
  const ExportTable table = candidates_table(classes, pa.constrained());
  if (const auto p = args.value("--csv")) {
    std::ofstream f(*p, std::ios::binary);
    f << to_csv(table);
    if (!f) throw std::runtime_error(*p + ": cannot write");
  }
  if (const auto p = args.value("--latex")) {
    std::ofstream f(*p, std::ios::binary);
    f << to_latex(table);
    if (!f) throw std::runtime_error(*p + ": cannot write");
  }
  if (const auto p = args.value("--figure")) {
#ifdef BENCHSCOPE_WITH_FIGURES
    const auto app = offscreen_application();
    QString note;
    const QImage image = ui::render_candidates(classes, 1200, 750, &note);
    if (!image.save(QString::fromStdString(*p), "PNG")) throw std::runtime_error(*p + ": cannot write");
    if (!note.isEmpty()) out << note.toStdString() << '\n';
#else
    throw std::runtime_error("--figure needs a benchscope-cli built with Qt (BENCHSCOPE_GUI=ON)");
#endif
  }
  if (args.has("--json")) {
    out << nlohmann::json{{"format", "benchscope-candidates"},
                          {"version", 1},
                          {"battery", pa.pack.name},
                          {"candidates", candidates_json(classes, peaks)},
                          {"graph_benchmarks", graph_benchmarks_json(in.library, lib)}}
               .dump(2)
        << '\n';
    return 0;
  }
  print_candidates(out, classes, peaks, pa.constrained());
  print_graph_benchmarks(out, in.library, lib);
  out << "battery: " << pa.pack.name << ", constant-power model at each row's power\n";
  return 0;
}

int run_library(const std::vector<std::string>& raw, std::ostream& out) {
  if (raw.empty()) throw UsageError("library needs list, show or compare");
  const std::vector<std::string> rest(raw.begin() + 1, raw.end());
  if (raw[0] == "list") return run_list(rest, out);
  if (raw[0] == "show") return run_show(rest, out);
  if (raw[0] == "compare") return run_compare(rest, out);
  throw UsageError("unknown library command '" + raw[0] + "' (list, show, compare)");
}

const CommandRegistrar registrar({
    "library",
    "published results of computers you do not own yet (MLPerf, clpeak, HPL): list, show, compare",
    "usage: benchscope-cli library list [--computer COMPUTERS] [--json]\n"
    "       benchscope-cli library show ID [--json]\n"
    "       benchscope-cli library compare COMPUTERS [WORKSPACE | PATH...] [--budget W] [--min-fps FPS]\n"
    "                                      [--min-runtime MIN] [--battery PRESET] [--extra-load W]\n"
    "                                      [--csv FILE] [--latex FILE] [--figure FILE.png] [--json]\n"
    "  The library (resources/library/library.json) holds published results of candidate robot computers, built\n"
    "  by scripts/build-library.py from public files it keeps: MLPerf Inference edge results (network,\n"
    "  scenario, precision, latency, throughput, power and energy where submitted), clpeak peaks and HPL results.\n"
    "  Every result is origin \"published\", names its URL, commit, kept file and lines, and is checked for\n"
    "  plausibility as imports are. The kept files are third-party and not installed: show says where a copy\n"
    "  would be ($BENCHSCOPE_PUBLIC_DATA_DIR/resources/library/...) and whether it is there. COMPUTERS: ids or\n"
    "  aliases (orin, orin-nx, xavier, xavier-nx, tx2, nano, pi4, cm4, pi5, icl, uhd620) or result ids,\n"
    "  comma-separated.\n"
    "  compare ranks the named published results beside a workspace's own platforms (detection stage, bench dnn,\n"
    "  imported MLPerf runs) under the constraints, within one network, scenario and precision only. --figure\n"
    "  writes the candidates figure (inferences per second against power, a marker per origin) as PNG.",
    out_only<run_library>,
});

}  // namespace
}  // namespace bs::cli
