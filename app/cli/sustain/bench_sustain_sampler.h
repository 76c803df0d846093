// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <iosfwd>
#include <string>
#include <vector>

namespace bs::cli {

// `benchscope-cli bench sustain-sampler`: what the sustained run's sysfs sampler costs at a 1 s interval, as % of one
// core, on this machine's real /sys (or --sysfs-root), against an independent reference in the same process: plain
// open/read/close of the same files with no parsing. Figures only: nothing passes or fails on time.
int bench_sustain_sampler(const std::vector<std::string>& args, std::ostream& out);

inline constexpr const char* kBenchSustainSamplerUsage =
    "       benchscope-cli bench sustain-sampler [--samples N] [--rounds R] [--seconds S] [--sysfs-root DIR]\n";

inline constexpr const char* kBenchSustainSamplerHelp =
    "  bench sustain-sampler: the sustained run's sampler (every cpufreq and devfreq clock, thermal zone and hwmon\n"
    "  temperature under --sysfs-root, default /) against plain open/read/close of the same files, N samples\n"
    "  back to back (default 200) per round, R rounds (default 5, alternating): CPU time per sample mean \xC2\xB1 SD\n"
    "  (n), their ratio, and the % of one core each costs at a 1 s interval; then S seconds (default 5) of the\n"
    "  sampler at a 1 s interval with its thread's CPU time, wake-ups included.\n";

}  // namespace bs::cli
