// SPDX-License-Identifier: GPL-3.0-or-later
// benchscope-cli compare A B: regression compare of two workspaces (or sets of result files), fit for CI on a robot:
// exit code 3 when a significant regression beyond the threshold is found.
#include <cmath>
#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>

#include "analysis/platform/regression_compare.h"
#include "analysis/stats/units.h"
#include "common/args.h"
#include "common/command.h"
#include "common/signals.h"
#include "common/text_table.h"
#include "workspace/inputs.h"

namespace bs::cli {
namespace {

constexpr int kExitRegression = 3;

double parse_fraction(const ParsedArgs& args, const std::string& option, double fallback) {
  const auto v = args.value(option);
  if (!v) return fallback;
  std::string text = *v;
  const bool percent = !text.empty() && text.back() == '%';
  if (percent) text.pop_back();
  try {
    std::size_t used = 0;
    const double x = std::stod(text, &used);
    if (used != text.size() || !(x >= 0)) throw std::invalid_argument(text);
    return percent ? x / 100.0 : x;
  } catch (const std::exception&) {
    throw UsageError(option + " takes a number or a percentage, e.g. 5% or 0.05; got '" + *v + "'");
  }
}

std::string summary_text(const Summary& s, const std::string& unit) {
  if (s.n == 0) return "-";
  if (unit.empty()) return format_mean_sd(s.mean, s.sd, s.n, "", 3);
  // Mean and SD with the mean's SI prefix: "5.251 ± 0.052 TFLOP/s (n = 10)".
  const int e = si_exponent(s.mean);
  const double scale = std::pow(10.0, e);
  return format_mean_sd(s.mean / scale, s.sd / scale, s.n, std::string(si_prefix(e)) + unit, 3);
}

int run_compare(const std::vector<std::string>& raw, std::ostream& out) {
  const ParsedArgs args = parse_args(raw, {"--json", "--every-point", "--all"}, {"--threshold", "--alpha"});
  if (args.positional.size() != 2) throw UsageError("compare needs exactly two inputs, A (baseline) and B");
  CompareOptions options;
  options.threshold = parse_fraction(args, "--threshold", 0.05);
  options.alpha = parse_fraction(args, "--alpha", 0.05);
  if (!(options.alpha > 0 && options.alpha < 1)) throw UsageError("--alpha must be between 0 and 1");
  options.every_point = args.has("--every-point");
  const LoadedData a = load_inputs({args.positional[0]}, interrupt_token());
  const LoadedData b = load_inputs({args.positional[1]}, interrupt_token());
  const auto rows = compare_results({a.runs, a.result_sets}, {b.runs, b.result_sets}, options);

  int regressions = 0, improvements = 0, not_significant = 0;
  for (const auto& r : rows) {
    regressions += r.verdict == CompareVerdict::Regression;
    improvements += r.verdict == CompareVerdict::Improvement;
    not_significant += r.verdict == CompareVerdict::NotSignificant;
  }
  if (args.has("--json")) {
    nlohmann::json list = nlohmann::json::array();
    for (const auto& r : rows) {
      list.push_back({{"key", r.key},
                      {"measure", r.measure},
                      {"unit", r.unit},
                      {"a", {{"n", r.a.n}, {"mean", r.a.mean}, {"sd", r.a.sd}}},
                      {"b", {{"n", r.b.n}, {"mean", r.b.mean}, {"sd", r.b.sd}}},
                      {"change", r.change},
                      {"u", r.test.u},
                      {"p_value", r.test.p_value},
                      {"exact", r.test.exact},
                      {"verdict", std::string(to_string(r.verdict))}});
    }
    out << nlohmann::json{{"format", "benchscope-compare"},
                          {"version", 1},
                          {"a", args.positional[0]},
                          {"b", args.positional[1]},
                          {"threshold", options.threshold},
                          {"alpha", options.alpha},
                          {"regressions", regressions},
                          {"improvements", improvements},
                          {"rows", list}}
               .dump(2)
        << '\n';
  } else {
    TextTable table({"measure", "what", "A", "B", "change", "p (Mann-Whitney)", "verdict"});
    for (const auto& r : rows) {
      // Unchanged rows only with --all: a CI log should show what moved.
      if (r.verdict == CompareVerdict::Unchanged && !args.has("--all")) continue;
      const bool both = r.a.n > 0 && r.b.n > 0;
      table.add({r.measure, r.key, summary_text(r.a, r.unit), summary_text(r.b, r.unit),
                 both ? format_number("%+.1f %%", 100 * r.change) : "-",
                 both ? format_number("%.3g", r.test.p_value) : "-", std::string(to_string(r.verdict))});
    }
    if (!table.empty()) table.print(out);
    char line[256];
    std::snprintf(line, sizeof line,
                  "%zu measures compared (threshold %.1f %%, alpha %.3g): %d regressions, %d improvements, %d changes "
                  "beyond the threshold without enough evidence\n",
                  rows.size(), 100 * options.threshold, options.alpha, regressions, improvements, not_significant);
    out << line;
  }
  if (rows.empty()) throw std::runtime_error("the two inputs have no measures in common or at all");
  return regressions > 0 ? kExitRegression : 0;
}

const CommandRegistrar registrar({
    "compare",
    "regression compare of two workspaces or result files (exit 3 on a regression)",
    "usage: benchscope-cli compare A B [--threshold 5%] [--alpha 0.05] [--every-point] [--all] [--json]\n"
    "  A is the baseline, B the candidate; each is a workspace or a result file. FLOPS runs are matched on\n"
    "  platform, device, backend, variant, D and N and compared at A's peak worker count (--every-point: at every\n"
    "  common worker count); Google Benchmark and clpeak measures on platform, device, backend, name and metric.\n"
    "  A regression is a change in the worse direction larger than the threshold with Mann-Whitney U p < alpha\n"
    "  over the repetitions. Exit codes: 0 no regression, 3 regression found, 1 error, 2 usage.",
    out_only<run_compare>,
});

}  // namespace
}  // namespace bs::cli
