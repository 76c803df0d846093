// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the kernel offers a real-time loop, recorded with every headroom result: two latency distributions are only
// comparable when these agree (a PREEMPT_RT kernel with isolated CPUs and the performance governor is another
// machine than the same board with a generic kernel and ondemand).
//
// Read through a root folder ("/" on the machine; a fixture tree in tests): proc/sys/kernel/osrelease,
// proc/sys/kernel/version, sys/kernel/realtime, proc/cmdline, sys/devices/system/cpu/cpu*/cpufreq/scaling_governor.
#include <filesystem>
#include <optional>
#include <string>

namespace bs::headroom {

struct KernelFacts {
  std::string release;             // "6.1.0-18-rt-amd64"; "" when unreadable
  std::string version;             // "#1 SMP PREEMPT_RT Debian 6.1.76-1 (2024-02-01)"
  std::optional<bool> preempt_rt;  // /sys/kernel/realtime reads 1 (or the version names PREEMPT_RT); empty: unknown
  std::string preemption;          // "PREEMPT_RT", "PREEMPT_DYNAMIC", "PREEMPT", "none" from the version string
  std::string isolcpus;            // the isolcpus= value of /proc/cmdline, "" when absent
  std::string nohz_full;           // the nohz_full= value, "" when absent
  std::string governor;            // "performance"; "performance x4, powersave x4" when CPUs differ; "" unknown
};

KernelFacts read_kernel_facts(const std::filesystem::path& root = "/");

// The value of `key=` in a kernel command line ("" when absent); the last one wins, as the kernel reads it.
std::string cmdline_value(const std::string& cmdline, const std::string& key);

}  // namespace bs::headroom
