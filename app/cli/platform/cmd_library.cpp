// SPDX-License-Identifier: GPL-3.0-or-later
// benchscope-cli library list|show|compare: the library of published results (resources/library/library.json):
// what it holds with sources, one result in full, and published results beside a workspace's own platforms.
#include <fstream>
#include <iostream>

#include <nlohmann/json.hpp>

#include "analysis/library/candidates.h"
#include "analysis/platform/platform_comparison.h"
#include "common/args.h"
#include "common/command.h"
#include "common/signals.h"
#include "common/text_table.h"
#include "platform/candidates_cli.h"
#include "platform/platform_args.h"
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

std::string flags_cell(const LibraryResult& r) {
  std::string s;
  for (const PlausibilityFlag& f : r.flags) s += (s.empty() ? "⚠ " : ", ") + f.code;
  return s;
}

nlohmann::json result_json(const LibraryResult& r, const Library& lib) {
  nlohmann::json cond = nlohmann::json::object();
  for (const auto& [k, v] : r.conditions) cond[k] = v;
  nlohmann::json lines = nlohmann::json::object();
  for (const auto& [k, v] : r.source.lines) lines[k] = v;
  nlohmann::json flags = nlohmann::json::array();
  for (const PlausibilityFlag& f : r.flags) flags.push_back({{"code", f.code}, {"reason", f.reason}});
  const auto opt = [](const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(nullptr); };
  return {{"id", r.id},
          {"origin", "published"},
          {"kind", r.kind},
          {"computer", r.computer},
          {"computer_name", lib.computer_name(r.computer)},
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
            {"lines", lines},
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
    out << nlohmann::json{{"format", "benchscope-library-list"}, {"library", lib.path}, {"results", a}}.dump(2) << '\n';
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
  out << "  result:      " << library_result_summary(*r) << '\n';
  out << "  round/date:  " << r->round << (r->date.empty() ? "" : " (" + r->date + ")")
      << (r->division.empty() ? "" : ", " + r->division) << (r->submitter.empty() ? "" : ", " + r->submitter)
      << (r->validity.empty() ? "" : ", " + r->validity) << '\n';
  out << "  software:    " << r->software << '\n';
  for (const auto& [k, v] : r->conditions) out << "  condition:   " << k << ": " << v << '\n';
  out << "  source:      " << r->source.url << '\n';
  if (!r->source.kept.empty()) out << "  kept copy:   resources/library/" << r->source.kept << '\n';
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
                          {"candidates", candidates_json(classes, peaks)}}
               .dump(2)
        << '\n';
    return 0;
  }
  print_candidates(out, classes, peaks, pa.constrained());
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
    "  by scripts/build-library.py from public files kept with it: MLPerf Inference edge results (network,\n"
    "  scenario, precision, latency, throughput, power and energy where submitted), clpeak peaks and HPL results.\n"
    "  Every result is origin \"published\", names its URL, commit, kept file and lines, and is checked for\n"
    "  plausibility as imports are. COMPUTERS: ids or aliases (orin, orin-nx, xavier, xavier-nx, tx2, nano, pi4,\n"
    "  cm4, pi5, icl, uhd620) or result ids, comma-separated.\n"
    "  compare ranks the named published results beside a workspace's own platforms (detection stage, bench dnn,\n"
    "  imported MLPerf runs) under the constraints, within one network, scenario and precision only. --figure\n"
    "  writes the candidates figure (inferences per second against power, a marker per origin) as PNG.",
    out_only<run_library>,
});

}  // namespace
}  // namespace bs::cli
