// SPDX-License-Identifier: GPL-3.0-or-later
// bench headroom: the probe checked against the reference tool robotics people trust, on the same machine, under
// the same conditions, alternating so that a neighbour's load on a shared machine falls on both alike.
#include "headroom/bench_headroom.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <ostream>

#include <nlohmann/json.hpp>

#include "common/args.h"
#include "common/signals.h"
#include "common/text_table.h"
#include "headroom/headroom_args.h"
#include "headroom/headroom_print.h"
#include "headroom/headroom_table.h"
#include "headroom/kernel_facts.h"
#include "headroom/loads/load_spec.h"
#include "headroom/probe.h"

extern char** environ;

namespace bs::cli {
namespace {

using namespace bs::headroom;

// The program's path on PATH, or "" when it is not installed.
std::string find_program(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "/usr/bin:/bin";
  std::size_t start = 0;
  while (start <= dirs.size()) {
    const std::size_t end = std::min(dirs.find(':', start), dirs.size());
    const std::filesystem::path candidate = std::filesystem::path(dirs.substr(start, end - start)) / name;
    if (access(candidate.c_str(), X_OK) == 0) return candidate.string();
    start = end + 1;
  }
  return {};
}

double child_cpu_s() {
  rusage u{};
  getrusage(RUSAGE_CHILDREN, &u);
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec) * 1e-6;
}

double monotonic_s() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec) * 1e-9;
}

struct ToolRun {
  ThreadLatency thread;
  double cpu_s_per_s = 0;
};

// The histogram cyclictest wrote with --json (rt-tests 2.x: thread -> "0" -> histogram {"<us>": count}, cycles,
// min, max, avg in us). Only what this bench asked cyclictest for is read; importing cyclictest files in general
// (every format in the wild) is the importers' business.
ThreadLatency read_cyclictest_json(const std::string& path, std::int64_t limit_ns) {
  std::ifstream in(path);
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (j.is_discarded() || !j.contains("thread") || !j["thread"].contains("0"))
    throw std::runtime_error(path + ": cyclictest wrote no thread 0 in its JSON");
  const nlohmann::json& t = j["thread"]["0"];
  ThreadLatency out;
  out.histogram = make_histogram(limit_ns);
  for (const auto& [bin, count] : t.at("histogram").items()) {
    const auto us = std::stoll(bin);
    if (us < 0 || static_cast<std::size_t>(us) >= out.histogram.bins.size())
      throw std::runtime_error(path + ": histogram bin " + bin + " outside the limit");
    out.histogram.bins[static_cast<std::size_t>(us)] = count.get<std::uint64_t>();
  }
  out.histogram.cycles = t.at("cycles").get<std::uint64_t>();
  const std::uint64_t binned = out.histogram.binned();
  if (binned > out.histogram.cycles) throw std::runtime_error(path + ": more cycles in the histogram than counted");
  out.histogram.overflows = out.histogram.cycles - binned;  // rt-tests: overflows are cycles minus the bins
  out.histogram.min_ns = t.at("min").get<std::int64_t>() * 1000;
  out.histogram.max_ns = t.at("max").get<std::int64_t>() * 1000;
  out.mean_ns = t.at("avg").get<double>() * 1000;
  return out;
}

ToolRun run_cyclictest(const std::string& program, const ProbeConfig& c, bool realtime, double seconds,
                       const std::string& json_path) {
  std::vector<std::string> argv = {program,
                                   "-q",
                                   "-t",
                                   "1",
                                   "-i",
                                   std::to_string(c.period_ns() / 1000),
                                   "-D",
                                   std::to_string(static_cast<int>(std::ceil(seconds))),
                                   "-h",
                                   std::to_string(c.limit_ns / 1000),
                                   "--json=" + json_path};
  if (realtime) argv.insert(argv.end(), {"-m", "-p", std::to_string(c.priority)});
  if (!c.cpus.empty()) argv.push_back("-a" + std::to_string(c.cpus.front()));
  std::vector<char*> args;
  for (std::string& a : argv) args.push_back(a.data());
  args.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  const double cpu0 = child_cpu_s(), t0 = monotonic_s();
  pid_t pid = -1;
  const int e = posix_spawn(&pid, program.c_str(), &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (e != 0) throw std::runtime_error(program + ": cannot start (" + std::strerror(e) + ")");
  int status = 0;
  while (waitpid(pid, &status, WNOHANG) == 0) {
    if (interrupt_token().cancelled()) kill(pid, SIGINT);
    const timespec ts{0, 20'000'000};
    nanosleep(&ts, nullptr);
  }
  interrupt_token().throw_if_cancelled();
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error(program + " failed (exit status " + std::to_string(WEXITSTATUS(status)) + ")");
  ToolRun r;
  r.thread = read_cyclictest_json(json_path, c.limit_ns);
  r.cpu_s_per_s = (child_cpu_s() - cpu0) / std::max(1e-9, monotonic_s() - t0);
  return r;
}

ToolRun run_probe_once(const ProbeConfig& c, double seconds) {
  CancelToken token;
  token.set_progress([&](double, std::string_view) {
    if (interrupt_token().cancelled()) token.cancel();
  });
  ProbeResult p = run_probe(c, seconds, &token, "bench");
  return {std::move(p.threads.front()), p.cpu_s_per_s};
}

// Both tools' merged results for one condition.
struct Side {
  ThreadLatency thread;
  double cpu = 0, mean_sum = 0;
  int runs = 0;
  void add(const ToolRun& r) {
    if (runs == 0)
      thread = r.thread;
    else
      thread.histogram.merge(r.thread.histogram);
    cpu += r.cpu_s_per_s;
    mean_sum += r.thread.mean_ns.value_or(0) * static_cast<double>(r.thread.histogram.cycles);
    ++runs;
  }
};

void print_condition(std::ostream& out, const std::string& name, const Side& ct, const Side& probe) {
  out << "\n" << name << ":\n";
  TextTable t({"", "cyclictest", "BenchScope probe", "probe / cyclictest"});
  const auto row = [&](const std::string& label, const HistogramPercentile& a, const HistogramPercentile& b) {
    const std::string ratio = a.ns > 0 && !a.at_least && !b.at_least
                                  ? format_number("%.2f", static_cast<double>(b.ns) / static_cast<double>(a.ns))
                                  : "–";
    t.add({label, latency_text(a), latency_text(b), ratio});
  };
  const LatencyHistogram &a = ct.thread.histogram, &b = probe.thread.histogram;
  for (const auto& [label, q] : {std::pair{"p50", 50.0}, {"p99", 99.0}, {"p99.9", 99.9}, {"p99.99", 99.99}})
    row(label, a.percentile(q), b.percentile(q));
  row("max", {a.max_ns.value_or(0), false}, {b.max_ns.value_or(0), false});
  const double ma = ct.mean_sum / std::max<double>(1, static_cast<double>(a.cycles));
  const double mb = probe.mean_sum / std::max<double>(1, static_cast<double>(b.cycles));
  t.add({"mean", format_number("%.1f us", ma / 1000), format_number("%.1f us", mb / 1000),
         ma > 0 ? format_number("%.2f", mb / ma) : "–"});
  t.add({"n cycles", std::to_string(a.cycles), std::to_string(b.cycles), ""});
  t.add({"overflows", std::to_string(a.overflows), std::to_string(b.overflows), ""});
  t.add({"CPU time per s", format_number("%.4f s", ct.cpu / ct.runs), format_number("%.4f s", probe.cpu / probe.runs),
         ct.cpu > 0 ? format_number("%.2f", (probe.cpu / probe.runs) / (ct.cpu / ct.runs)) : "–"});
  t.print(out);
}

}  // namespace

int bench_headroom(const std::vector<std::string>& raw, std::ostream& out, std::ostream& err) {
  std::set<std::string> valued = kProbeOptions;
  valued.insert({"--seconds", "--rounds", "--load"});
  const ParsedArgs args = parse_args(raw, {"--no-rt"}, valued);
  const std::string cyclictest = find_program("cyclictest");
  if (cyclictest.empty()) {
    out << "bench headroom: skipped: cyclictest is not installed (Debian: apt-get install rt-tests)\n";
    return 0;
  }
  ProbeConfig c = probe_config(args);
  if (c.threads != 1 || c.computation_ns != 0)
    throw UsageError(
        "bench headroom compares one pure wake-up thread with cyclictest's: no --threads, no --computation-us");
  const double seconds = args.number("--seconds", 10);
  if (!(seconds >= 1 && seconds <= 3600)) throw UsageError("--seconds must be from 1 to 3600");
  const double rounds_arg = args.number("--rounds", 2);
  if (!(rounds_arg >= 1 && rounds_arg <= 100) || rounds_arg != std::floor(rounds_arg))
    throw UsageError("--rounds must be a whole number from 1 to 100");
  const int rounds = static_cast<int>(rounds_arg);
  const std::string load_spec = args.value("--load").value_or("pipeline");
  std::vector<std::unique_ptr<Load>> loads;
  if (load_spec != "none") {
    try {
      loads = make_loads(load_spec);
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("--load: ") + e.what());
    }
    if (loads.size() != 1) throw UsageError("--load takes one load for bench headroom");
  }
  // Both tools get the same rights: real-time only when this process may have it, and then both.
  const RealtimeRights rights = probe_realtime_rights();
  const bool realtime = c.realtime && rights.fifo;
  c.realtime = realtime;
  const std::string json_path =
      (std::filesystem::temp_directory_path() / ("benchscope-cyclictest-" + std::to_string(getpid()) + ".json"))
          .string();

  out << "bench headroom: cyclictest (" << cyclictest << ") vs BenchScope's probe, one thread at "
      << format_number("%g", c.rate_hz) << " Hz each, "
      << (realtime ? "SCHED_FIFO " + std::to_string(c.priority) + " with mlockall (both)"
                   : "normal threads (both): " + (c.realtime ? std::string("--no-rt") : rights.explanation))
      << (c.cpus.empty() ? "" : ", pinned to CPU " + std::to_string(c.cpus.front())) << "; " << rounds << " round"
      << (rounds == 1 ? "" : "s") << " of " << format_number("%g", seconds)
      << " s per tool and condition, the order swapped every round\n";
  out << kernel_line(read_kernel_facts()) << "\n";
  std::vector<std::pair<std::string, Load*>> conditions = {{"idle", nullptr}};
  if (!loads.empty()) conditions.push_back({"beside " + loads.front()->name(), loads.front().get()});
  try {
    for (auto& [name, load] : conditions) {
      Side ct, probe;
      if (load) {
        err << "bench headroom: starting " << load->name() << "\n";
        load->start();
        const timespec settle{1, 0};
        nanosleep(&settle, nullptr);
      }
      for (int r = 0; r < rounds; ++r) {
        err << "bench headroom: " << name << ", round " << r + 1 << " of " << rounds << "\n";
        if (r % 2 == 0) {
          ct.add(run_cyclictest(cyclictest, c, realtime, seconds, json_path));
          probe.add(run_probe_once(c, seconds));
        } else {
          probe.add(run_probe_once(c, seconds));
          ct.add(run_cyclictest(cyclictest, c, realtime, seconds, json_path));
        }
      }
      std::string achieved;
      if (load) {
        const LoadReport report = load->stop();
        if (report.achieved_rate)
          achieved = " (load achieved " + format_number("%.3g", *report.achieved_rate) + " " + load->rate_unit() + ")";
      }
      print_condition(out, name + achieved, ct, probe);
    }
  } catch (const Cancelled&) {
    std::filesystem::remove(json_path);
    err << "bench headroom: cancelled\n";
    return 1;
  }
  std::filesystem::remove(json_path);
  out << "\nPercentiles are nearest-rank over 1 us bins (lower edge) for both tools; the maximum is exact for the "
         "probe, whole microseconds for cyclictest. Figures only: nothing passes or fails on time.\n";
  return 0;
}

}  // namespace bs::cli
