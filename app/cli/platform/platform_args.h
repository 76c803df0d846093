// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The battery and constraint options shared by `platforms` and `report`.
#include <set>
#include <string>
#include <vector>

#include "analysis/platform/platform_comparison.h"
#include "analysis/power/battery.h"
#include "common/args.h"
#include "headroom/loop_requirement.h"
#include "store/decision_store.h"
#include "sustain/sustain_requirement.h"

namespace bs::cli {

struct LoadedData;

// --budget W, --min-fps FPS, --min-runtime MIN, --battery PRESET, --extra-load W, --supply-volts V,
// --mission SPEC (name:seconds:watts,... in parallel with each computer, as `battery --mission`),
// --require-loop SPEC (a control-loop requirement, headroom/loop_requirement.h), --require-sustained SPEC (a
// sustained-performance requirement, sustain/sustain_requirement.h)
const std::set<std::string>& platform_value_options();

struct PlatformArgs {
  BatteryPack pack;
  ComparisonOptions options;
  Constraints constraints;
  std::optional<headroom::LoopRequirement> loop;
  std::optional<sustain::SustainRequirement> sustained;
  bool constrained() const {
    return constraints.power_budget_w || constraints.min_fps || constraints.min_runtime_h || loop || sustained;
  }
  // Given one workspace, what its Platforms tab stored (store/decision_store.h) fills every option the command line
  // leaves out (issue #43.2; the constraints, the control loop and the sustained requirement among them, as a whole):
  // the recommendation is the one set in the GUI. `stored` says what was taken, in words ("a power budget of 10 W;
  // battery: the Battery tab's pack ..."), empty when nothing was; `library` is the stored candidates when --library is
  // not given; `chosen_log_platforms` the platforms whose log was chosen.
  std::string stored;
  std::string library;
  std::vector<std::string> chosen_log_platforms;
  std::string battery_choice;  // --battery, else the stored choice; "" follows the Battery tab's pack
};

// What `platforms --store` writes into the workspace: the options in effect (given or stored before).
StoredDecision decision_to_store(const PlatformArgs& p);

// "--use-log PLATFORM=LOG": moves the log labelled LOG of PLATFORM before the platform's other logs (the comparisons
// use a platform's first log). Throws UsageError naming the platform's logs when there is no such log. Returns the
// log's index after the move.
std::size_t use_log(std::vector<PowerTrace>& traces, const std::string& spec);

// The compared platforms (one per row) judged against --require-loop and --require-sustained; a vector is empty
// when its requirement is not given. `platforms` and `report` judge the same rows alike through it.
struct RequirementVerdicts {
  std::vector<headroom::LoopVerdict> loop;
  std::vector<sustain::SustainVerdict> sustained;
};
RequirementVerdicts judge_requirements(const PlatformArgs& p, const std::vector<PlatformRow>& rows,
                                       const LoadedData& data);

// Throws UsageError for an unknown battery preset, naming the known ones, or a malformed mission. `--no-stored`
// (a flag of the commands that read the stored decision) ignores what the workspace stored.
PlatformArgs parse_platform_args(const ParsedArgs& args);

}  // namespace bs::cli
