// SPDX-License-Identifier: GPL-3.0-or-later
#include "commands/remote_commands.h"

#include "commands/bench_dnn_grammar.h"
#include "commands/bench_kernels_grammar.h"
#include "commands/bench_vision_grammar.h"
#include "commands/headroom_grammar.h"
#include "commands/inventory_grammar.h"
#include "commands/pipeline_grammar.h"
#include "commands/record_power_grammar.h"
#include "commands/run_bandwidth_grammar.h"
#include "commands/run_flops_grammar.h"
#include "commands/sustain_grammar.h"
#include "remote/job_agent.h"

namespace bs::commands {
namespace {

// Each grammar's words read and written again: the name comes back first, as to_words writes it.
template <typename Settings, Settings (*From)(const std::vector<std::string>&)>
std::vector<std::string> canonical(const std::vector<std::string>& words) {
  return to_words(From(words));
}

}  // namespace

const std::vector<RemoteCommand>& remote_commands() {
  static const std::vector<RemoteCommand> list = {
      {"run flops", 2, true, true, canonical<RunFlopsSettings, run_flops_from_words>},
      {"record-power", 1, true, true, canonical<RecordPowerSettings, record_power_from_words>},
      {"run bandwidth", 2, false, true, canonical<RunBandwidthSettings, run_bandwidth_from_words>},
      {"bench dnn", 2, false, true, canonical<BenchDnnSettings, bench_dnn_from_words>},
      {"bench vision", 2, false, false, canonical<BenchVisionSettings, bench_vision_from_words>},
      {"bench kernels", 2, false, false, canonical<BenchKernelsSettings, bench_kernels_from_words>},
      {"devices", 1, false, false, canonical<DevicesSettings, devices_from_words>},
      {"sensors", 1, false, false, canonical<SensorsSettings, sensors_from_words>},
      {"headroom", 1, false, true, canonical<HeadroomSettings, headroom_from_words>},
      {"pipeline", 1, false, true, canonical<PipelineSettings, pipeline_from_words>},
      {"sustain", 1, true, true, canonical<SustainSettings, sustain_from_words>},
  };
  return list;
}

std::optional<RemoteCommand> find_remote_command(const std::vector<std::string>& args) {
  for (const RemoteCommand& c : remote_commands()) {
    const std::string first = args.empty() ? std::string() : args[0];
    const std::string two = args.size() >= 2 ? args[0] + " " + args[1] : std::string();
    if ((c.words == 1 && first == c.name) || (c.words == 2 && two == c.name)) return c;
  }
  return std::nullopt;
}

std::string remote_command_names() {
  std::string names;
  for (const RemoteCommand& c : remote_commands()) names += (names.empty() ? "" : ", ") + c.name;
  return names;
}

std::vector<std::string> job_words(const RemoteCommand& command, std::vector<std::string> args,
                                   const std::string& result_workspace) {
  if (args.size() < static_cast<std::size_t>(command.words)) throw UsageError("expected '" + command.name + "'");
  std::vector<std::string> extra;
  if (command.workspace) extra.insert(extra.end(), {"--workspace", result_workspace});
  if (command.native_events) extra.insert(extra.end(), {"--events", "jsonl"});
  args.insert(args.begin() + command.words, extra.begin(), extra.end());
  return args;
}

void check_remote_words(const RemoteCommand& command, const std::vector<std::string>& args) {
  // With the job's options, so that a rule that needs one (record-power's --out or --workspace) reads as there.
  const std::vector<std::string> words = job_words(command, args, remote::kJobResultFile);
  command.grammar({words.begin() + command.words, words.end()});
}

}  // namespace bs::commands
