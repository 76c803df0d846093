// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a cyclictest command line asked for, read the way cyclictest's own getopt_long reads it (rt-tests
// src/cyclictest/cyclictest.c, process_options): short options grouped ("-mqp99"), values attached or separate
// ("-i200", "-i 200", "--interval=200", "--interval 200"). Only what a latency result needs is kept: the period, the
// histogram size, ns resolution, policy and priority, memory locking, threads and affinity.
//
// A cyclictest that could not get the priority or lock memory it was asked for exits with an error (rt-tests >= 0.84),
// so for a run that produced output, what was asked is what was obtained.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace bs::headroom_import {

struct CyclictestCommand {
  std::string text;                   // as given
  int interval_us = 1000;             // -i, default 1000
  int distance_us = 500;              // -d, default 500; ignored (0) when a histogram is kept
  std::optional<int> histogram_bins;  // -h / -H: bins of 1 us (1 ns with -N)
  bool histofall = false;             // -H: a sum column
  bool nsecs = false;                 // -N
  int priority = 0;                   // -p (0: none asked)
  bool priospread = false;            // --priospread: one lower per thread
  std::string policy;                 // "SCHED_FIFO", "SCHED_RR", "SCHED_OTHER", ... as cyclictest would settle it
  bool mlockall = false;              // -m
  std::optional<int> threads;         // -t N; empty with -t alone or -S (one per CPU)
  std::string affinity;               // -a CPUSET ("" when not given or "all")
  bool quiet = false;                 // -q

  // Period of thread `index` in ns: the interval plus index times the distance when no histogram is kept.
  std::int64_t period_ns(int index) const;
  // Priority of thread `index` (lower by one per thread with --priospread).
  int priority_of(int index) const;
};

// Splits a shell command line into words (single and double quotes, backslash escapes). Used on the command line
// rt-tests writes into its JSON (argv joined by spaces) and on a prompt line of a terminal capture.
std::vector<std::string> shell_words(std::string_view line);

// The command from the word that names cyclictest ("cyclictest", "/usr/bin/cyclictest", "./cyclictest") onwards;
// nullopt when no word names it. Words before it (sudo, taskset -c 2, chrt, a prompt) are skipped.
std::optional<CyclictestCommand> parse_cyclictest_command(std::string_view line);

}  // namespace bs::headroom_import
