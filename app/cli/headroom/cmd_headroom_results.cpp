// SPDX-License-Identifier: GPL-3.0-or-later
// benchscope-cli headroom-results INPUT...: the control-loop latency results a workspace holds (measured with
// `headroom`, imported from cyclictest, rttest or performance_test) or that files hold (read in memory), grouped by
// what they measured, so that a system wake-up latency is never read beside an application loop's or a message's
// without the heading saying which is which.
#include <algorithm>
#include <iostream>

#include <nlohmann/json.hpp>

#include "common/args.h"
#include "common/command.h"
#include "common/signals.h"
#include "headroom/headroom_json.h"
#include "headroom/headroom_print.h"
#include "workspace/inputs.h"

namespace bs::cli {
namespace {

using headroom::HeadroomMeasurement;
using headroom::LatencyKind;

std::string source_of(const HeadroomMeasurement& m) {
  std::string s = m.provenance.source_file.empty() ? m.provenance.date : m.provenance.source_file;
  if (!m.provenance.source_file.empty() && !m.provenance.date.empty()) s += ", " + m.provenance.date;
  return s;
}

int run_headroom_results(const std::vector<std::string>& raw, std::ostream& out, std::ostream& err) {
  const ParsedArgs args = parse_args(raw, {"--json"}, {"--kind", "--platform"});
  if (args.positional.empty()) throw UsageError("headroom-results needs a workspace or latency files");
  std::optional<LatencyKind> only_kind;
  if (const auto k = args.value("--kind")) {
    only_kind = headroom::latency_kind_from_id(*k);
    if (!only_kind) throw UsageError("--kind takes wakeup, loop or message, not '" + *k + "'");
  }
  const std::optional<std::string> only_platform = args.value("--platform");
  LoadedData data = load_inputs(args.positional, interrupt_token());
  std::vector<const HeadroomMeasurement*> shown;
  for (const HeadroomMeasurement& m : data.headroom)
    if ((!only_kind || m.kind == *only_kind) && (!only_platform || m.platform == *only_platform)) shown.push_back(&m);
  // One kind after the other (wake-up, loop, message), each under its own heading.
  std::stable_sort(shown.begin(), shown.end(),
                   [](const HeadroomMeasurement* a, const HeadroomMeasurement* b) { return a->kind < b->kind; });
  if (args.has("--json")) {
    nlohmann::json list = nlohmann::json::array();
    for (const HeadroomMeasurement* m : shown) list.push_back(headroom::to_json(*m, true));
    out << list.dump(2) << "\n";
    return 0;
  }
  if (shown.empty()) {
    err << "benchscope-cli: no control-loop latency result"
        << (only_kind || only_platform ? " matches --kind / --platform" : "") << " in the inputs\n";
    return 1;
  }
  std::optional<LatencyKind> heading;
  for (const HeadroomMeasurement* m : shown) {
    if (heading != m->kind) {
      heading = m->kind;
      const auto n =
          std::count_if(shown.begin(), shown.end(), [&](const HeadroomMeasurement* x) { return x->kind == m->kind; });
      out << "== " << headroom::to_string(m->kind) << ": " << n << (n == 1 ? " result" : " results")
          << " (not comparable with the other kinds) ==\n\n";
    }
    out << "from " << source_of(*m) << "\n";
    print_headroom(out, *m, source_of(*m));
    out << "\n";
  }
  return 0;
}

const CommandRegistrar registrar({
    "headroom-results",
    "list control-loop latency results: measured (headroom) and imported (cyclictest, rttest, performance_test)",
    "usage: benchscope-cli headroom-results INPUT... [--kind wakeup|loop|message] [--platform NAME] [--json]\n"
    "  Prints every control-loop latency result of a workspace (stored by the headroom command or `import`), or of\n"
    "  files read in memory (cyclictest -h/-H output or --json, rttest logs and statistics, performance_test CSV or\n"
    "  JSON logs), grouped by what they measured: system wake-up latency (cyclictest), an application loop (the\n"
    "  probe, rttest / pendulum_demo), message latency (performance_test). Per result: platform, tool, kernel facts,\n"
    "  the table per phase and thread (p50 / p99 / p99.9 / p99.99 / max, misses, longest miss run, n, policy), its\n"
    "  flags (non-real-time, policy unknown, overflows, summary only) and notes. A result without a histogram\n"
    "  (performance_test, rttest's statistics, cyclictest's status lines) shows '–' for what it does not know.\n"
    "  --kind and --platform keep only those results; --json prints them as benchscope-headroom JSON with each\n"
    "  thread's summary.",
    run_headroom_results,
});

}  // namespace
}  // namespace bs::cli
