// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the user sets that changes the decision (issue #43.2, #43.4), kept in the workspace (schema 10,
// store/schema_v10.h) so that a recommendation survives closing and reopening, the report states it on its first page,
// and `benchscope-cli platforms` / `report` on the workspace use it too:
//  - the Platforms tab's decision: constraints (the control-loop requirement of #45 among them), battery choice,
//    parallel load, mission, library candidates;
//  - per platform, the power log the comparisons use when the platform has several (otherwise its first log).
// Writes are the caller's one undo step each (the GUI's Edit > Undo); a read refuses a stored value out of range (a
// hand-edited file) with WorkspaceError(Corrupt) naming the column and the value, never guessing what was meant.
#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "analysis/platform/platform_comparison.h"
#include "store/workspace.h"

namespace bs {

struct StoredDecision {
  std::optional<double> power_budget_w;   // mean power <= this (W)
  std::optional<double> min_fps;          // preprocessing + detection frames per second >= this
  std::optional<double> min_runtime_min;  // battery runtime >= this (minutes)
  std::string battery;                    // a preset's name (built-in or the workspace's); "": the Battery tab's pack
  double extra_load_w = 0;                // in parallel with the computer (servos)
  std::string mission;                    // parse_mission() text; "": constant load
  std::string candidates;                 // library computers or result ids, "orin,pi5"; "": none
  // A control-loop requirement (headroom/loop_requirement.h syntax) as the user wrote it; "": none.
  std::string loop;
  // A sustained-performance requirement (sustain/sustain_requirement.h syntax) as the user wrote it; "": none.
  // Kept beside the decision's row as the workspace setting "decision/sustained" (the meta table), so that it needs
  // no schema change and an older BenchScope reads the rest of the decision as before.
  std::string sustained;
  bool operator==(const StoredDecision&) const = default;

  Constraints constraints() const;
  bool constrained() const {
    return power_budget_w || min_fps || min_runtime_min || !loop.empty() || !sustained.empty();
  }
};

// "a power budget of 10 W, at least 5 fps" (empty when no constraint is set), as the report's first page says it.
std::string describe_constraints(const Constraints& c);
// The same with the decision's control-loop and sustained requirements, when it has them ("..., control loop 1 kHz,
// p99.9 <= 200 us ..., sustained stability >= 97 %, at least 20 min").
std::string describe_constraints(const StoredDecision& d);

// nullopt: never set in this workspace (the defaults apply: no constraint, the Battery tab's pack). Throws
// WorkspaceError(Corrupt) for a stored value the schema's checks refuse (a budget <= 0, text for a number, a
// control-loop or sustained requirement that does not parse).
std::optional<StoredDecision> stored_decision(const Workspace& ws);
// nullopt removes it. Throws WorkspaceError(Constraint) for a value out of range (a budget <= 0, a negative load) or a
// control-loop or sustained requirement that does not parse (naming what is wrong with it).
void set_stored_decision(Workspace& ws, const std::optional<StoredDecision>& decision);

// Platform -> the id of the power log chosen for it.
std::map<std::string, std::int64_t> chosen_logs(const Workspace& ws);
// nullopt: the platform's first log again. Throws WorkspaceError(Constraint) for an unknown log or a blank platform.
void set_chosen_log(Workspace& ws, const std::string& platform, std::optional<std::int64_t> trace_id);

// The order in which to hand a workspace's logs to the comparisons (which use each platform's first log): the chosen
// log of each platform moves before the platform's other logs, everything else keeps its order. `platforms[i]` and
// `ids[i]` describe log i; returns indexes into them.
std::vector<std::size_t> chosen_logs_first(std::span<const std::string> platforms, std::span<const std::int64_t> ids,
                                           const std::map<std::string, std::int64_t>& chosen);

// The same for a workspace's logs as read (power_traces() or power_trace_summaries()), in place.
void order_chosen_logs_first(const Workspace& ws, std::vector<StoredPowerTrace>& traces);

}  // namespace bs
