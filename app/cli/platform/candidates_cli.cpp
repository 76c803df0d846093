// SPDX-License-Identifier: GPL-3.0-or-later
#include "platform/candidates_cli.h"

#include <ostream>
#include <stdexcept>

#include "common/args.h"
#include "common/flag_output.h"
#include "common/text_table.h"

namespace bs::cli {
namespace {

nlohmann::json opt(const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(nullptr); }

nlohmann::json flags_of(const std::vector<PlausibilityFlag>& flags) {
  nlohmann::json a = nlohmann::json::array();
  for (const PlausibilityFlag& f : flags) a.push_back({{"code", f.code}, {"reason", f.reason}});
  return a;
}

}  // namespace

void print_candidates(std::ostream& out, std::span<const CandidateClass> classes, std::span<const PeakClass> peaks,
                      bool constrained) {
  const ExportTable t = candidates_table(classes, constrained);
  // The export table's columns without Class (a heading here) and Source (listed under each class).
  std::vector<std::string> header(t.header.begin() + 1, t.header.end() - 1);
  std::size_t row = 0;
  out << "Candidates (inference): ranked within one network, scenario and precision; origin in every row\n";
  for (const CandidateClass& k : classes) {
    out << "\n== " << k.title() << " ==\n";
    TextTable text(header);
    std::vector<std::string> sources;
    for (std::size_t i = 0; i < k.rows.size(); ++i, ++row) {
      const auto& cells = t.rows[row];
      text.add(std::vector<std::string>(cells.begin() + 1, cells.end() - 1));
      sources.push_back("  " + std::to_string(i + 1) + ". " + k.rows[i].platform + ": " + cells.back());
    }
    text.print(out);
    if (!k.note.empty()) out << k.note << '\n';
    out << "sources:\n";
    for (const std::string& s : sources) out << s << '\n';
  }
  out << "\nNo class is ranked against another: a pick holds only within its class.\n";
  if (!t.notes.empty()) {
    out << "\nFlags (implausible numbers; docs/cli.md, \"Plausibility flags\"):\n";
    for (const std::string& n : t.notes) out << "  " << n << '\n';
  }
  if (peaks.empty()) return;
  const ExportTable p = peak_candidates_table(peaks);
  out << "\nCandidates (compute peaks): compared within one precision; the kernel differs where said\n";
  TextTable text(std::vector<std::string>(p.header.begin(), p.header.end() - 1));
  for (const auto& cells : p.rows) text.add(std::vector<std::string>(cells.begin(), cells.end() - 1));
  text.print(out);
  out << "sources:\n";
  for (const auto& cells : p.rows) out << "  " << cells[1] << ": " << cells.back() << '\n';
  for (const std::string& n : p.notes) out << "  " << n << '\n';
}

nlohmann::json candidates_json(std::span<const CandidateClass> classes, std::span<const PeakClass> peaks) {
  nlohmann::json cls = nlohmann::json::array();
  for (const CandidateClass& k : classes) {
    nlohmann::json rows = nlohmann::json::array();
    for (std::size_t i = 0; i < k.rows.size(); ++i) {
      const Candidate& c = k.rows[i];
      nlohmann::json checks = nlohmann::json::array();
      for (const ConstraintCheck& x : c.checks)
        checks.push_back({{"name", x.name},
                          {"unit", x.unit},
                          {"required", x.required},
                          {"actual", opt(x.actual)},
                          {"met", x.met},
                          {"margin", x.margin},
                          {"share_above", opt(x.share_above)},
                          {"samples", x.samples},
                          {"power_kind", x.power_kind}});
      rows.push_back({{"rank", c.not_ranked.empty() ? nlohmann::json(i + 1) : nlohmann::json(nullptr)},
                      {"not_ranked", c.not_ranked},
                      {"power_kind", c.power_kind},
                      {"platform", c.platform},
                      {"origin", origin_label(c.origin)},
                      {"latency_s", opt(c.latency_s)},
                      {"latency_statistic", c.latency_statistic},
                      {"throughput_per_s", opt(c.throughput_per_s)},
                      {"throughput_statistic", c.throughput_statistic},
                      {"power_w", opt(c.power_w)},
                      {"power_how", c.power_how},
                      {"energy_per_inference_j", opt(c.energy_per_inference_j)},
                      {"battery_runtime_h", opt(c.battery_runtime_h)},
                      {"meets_constraints", c.meets_all},
                      {"recommended", c.recommended},
                      {"checks", checks},
                      {"difference", c.difference},
                      {"conditions", c.conditions},
                      {"software", c.software},
                      {"source", c.source},
                      {"flags", flags_of(c.flags)}});
    }
    cls.push_back({{"network", k.network},
                   {"scenario", k.scenario},
                   {"precision", k.precision},
                   {"note", k.note},
                   {"rows", rows}});
  }
  nlohmann::json pk = nlohmann::json::array();
  for (const PeakClass& k : peaks)
    for (const PeakCandidate& c : k.rows)
      pk.push_back({{"precision", k.precision},
                    {"platform", c.platform},
                    {"origin", origin_label(c.origin)},
                    {"device", c.device},
                    {"kernel", c.kernel},
                    {"flops", c.flops},
                    {"power_w", opt(c.power_w)},
                    {"flops_per_watt", opt(c.flops_per_watt)},
                    {"difference", c.difference},
                    {"source", c.source},
                    {"flags", flags_of(c.flags)}});
  return {{"inference", cls}, {"peaks", pk}};
}

CandidateInputs library_candidate_inputs(std::span<const PlatformRow> rows, const LoadedData& data,
                                         const std::string& spec) {
  const BundledLibrary& lib = bundled_library();
  if (!lib.error.empty()) throw std::runtime_error("library: " + lib.error);
  CandidateInputs in;
  in.platforms = rows;
  in.pipelines = data.pipeline_runs;
  in.dnn_runs = data.dnn_runs;
  in.result_sets = data.result_sets;
  in.lib = &lib.library;
  try {
    in.library = select_library(lib.library, spec);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--library: ") + e.what());
  }
  return in;
}

void print_graph_benchmarks(std::ostream& out, const std::vector<const LibraryResult*>& chosen, const Library& lib) {
  const auto graphs = graph_benchmark_classes(chosen);
  if (graphs.empty()) return;
  out << "\nROS 2 graph benchmarks: compared within one tool, node, input, release and measure\n";
  for (const GraphBenchmarkClass& g : graphs) {
    out << "== " << g.title << " ==\n";
    for (const LibraryResult* r : g.rows)
      out << "  " << lib.computer_name(r->computer) << ": " << library_result_summary(*r) << "\n    " << r->source.url
          << '\n';
  }
}

nlohmann::json graph_benchmarks_json(const std::vector<const LibraryResult*>& chosen, const Library& lib) {
  nlohmann::json classes = nlohmann::json::array();
  for (const GraphBenchmarkClass& g : graph_benchmark_classes(chosen)) {
    nlohmann::json rows = nlohmann::json::array();
    for (const LibraryResult* r : g.rows) {
      rows.push_back({{"id", r->id},
                      {"computer", lib.computer_name(r->computer)},
                      {"value", r->value ? nlohmann::json(*r->value) : nlohmann::json(nullptr)},
                      {"unit", r->unit},
                      {"what_the_value_is", r->statistic},
                      {"release", r->release},
                      {"source", r->source.url},
                      {"flags", flags_json(r->flags)}});
    }
    classes.push_back({{"class", g.title}, {"rows", rows}});
  }
  return classes;
}

}  // namespace bs::cli
