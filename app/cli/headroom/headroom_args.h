// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The probe's options, shared by `headroom` and `bench headroom`: --rate, --threads, --computation-us,
// --deadline-us, --cpu, --priority, --no-rt, --limit-us. Bad values are UsageErrors naming the option and the range.
// They are read by the headroom grammar (core/commands/headroom_grammar.h), the one a robot's words are written with.
#include "commands/headroom_grammar.h"
#include "common/args.h"

namespace bs::cli {

using commands::kProbeOptions;
inline constexpr const char* kProbeUsage =
    "  Probe: --rate HZ (50 .. 10000, default 1000) periodic threads (--threads N, default 1) sleeping to absolute\n"
    "  times of CLOCK_MONOTONIC; --computation-us C of busy work per cycle (default 0); a cycle misses when\n"
    "  latency + C > the period, or > --deadline-us D; --cpu LIST pins thread k to the k-th CPU of LIST (e.g. 2,3);\n"
    "  SCHED_FIFO at --priority P (1 .. 99, default 80) with mlockall when permitted, else a normal thread, said on\n"
    "  every output (--no-rt asks for a normal thread); histogram of 1 us bins up to --limit-us L (default 10000),\n"
    "  the true maximum kept beyond it.\n";

// From the options above; `--no-rt` is a flag the caller adds to its flag set.
// Throws UsageError for bad words or CPUs this computer does not have.
headroom::ProbeConfig probe_config(const ParsedArgs& args);

}  // namespace bs::cli
