// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What cyclictest says about each measuring thread beside its latencies, shared by the text and JSON importers: the
// status line it redraws while running ("T: 0 ( 2604) P:95 I:1000 C: 349868 Min: 4 Act: 6 Avg: 5 Max: 35") and
// the command line, which together give each thread's period, priority, policy, CPU and memory locking.
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>

#include "headroom/cyclictest_command.h"
#include "headroom/thread_latency.h"

namespace bs::headroom_import {

struct StatusLine {
  int index = 0;
  int pid = 0;
  int priority = 0;
  std::int64_t interval_us = 0;
  std::uint64_t cycles = 0;
  std::int64_t min = 0, act = 0, avg = 0, max = 0;  // us, or ns with -N (avg truncated by cyclictest)
  // cyclictest prints Act and Avg 8 wide with -N and 5 wide without: true / false when the width shows it.
  std::optional<bool> nsecs;
  std::size_t line = 0;
};

// nullopt when `text` is not a status line.
std::optional<StatusLine> parse_status_line(std::string_view text, std::size_t line);

// CPUs of a cyclictest cpuset ("3", "2-5", "0,2,4-6"); empty when it cannot be read ("!1", "+2", "all").
std::optional<int> cpu_of_thread(std::string_view cpuset, int index);

// Fills period, deadline (the period), priority, policy, CPU and memory locking of thread `index` from the status
// lines (what ran), then the command line (what was asked, which cyclictest enforces), then the "policy:" line.
// `cpu_from_file` (the JSON's "cpu") wins over the command's affinity.
void apply_thread_facts(headroom::ThreadLatency* thread, int index, const std::optional<CyclictestCommand>& command,
                        const std::map<int, StatusLine>& status, const std::string& policy_line,
                        std::optional<int> cpu_from_file = std::nullopt);

}  // namespace bs::headroom_import
