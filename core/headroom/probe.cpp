// SPDX-License-Identifier: GPL-3.0-or-later
#include "headroom/probe.h"

#include <pthread.h>
#include <sched.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <time.h>

#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <thread>

#include "headroom/latency_recorder.h"

namespace bs::headroom {
namespace {

constexpr std::int64_t kNsPerS = 1'000'000'000;

std::int64_t now_ns(clockid_t clock = CLOCK_MONOTONIC) {
  timespec ts{};
  clock_gettime(clock, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * kNsPerS + ts.tv_nsec;
}

timespec to_timespec(std::int64_t ns) {
  timespec ts{};
  ts.tv_sec = static_cast<time_t>(ns / kNsPerS);
  ts.tv_nsec = static_cast<long>(ns % kNsPerS);
  return ts;
}

std::string policy_name(int policy) {
  switch (policy) {
    case SCHED_FIFO:
      return "SCHED_FIFO";
    case SCHED_RR:
      return "SCHED_RR";
    case SCHED_OTHER:
      return "SCHED_OTHER";
#ifdef SCHED_BATCH
    case SCHED_BATCH:
      return "SCHED_BATCH";
#endif
#ifdef SCHED_IDLE
    case SCHED_IDLE:
      return "SCHED_IDLE";
#endif
  }
  return "policy " + std::to_string(policy);
}

// What one probe thread hands back; written by the thread only, read after join.
struct ThreadState {
  LatencyRecorder recorder;
  std::string policy;
  std::optional<int> priority;
  std::string refusal;  // why SCHED_FIFO or the pinning was refused, "" when granted
  double cpu_s = 0;
  explicit ThreadState(const ProbeConfig& c) : recorder(c.limit_ns, c.bin_ns, c.deadline()) {}
};

// Touches `bytes` of stack so the loop never page-faults on it after mlockall (cyclictest does the same).
void prefault_stack() {
  constexpr std::size_t kBytes = 64 * 1024;
  [[maybe_unused]] volatile unsigned char buffer[kBytes];
  for (std::size_t i = 0; i < kBytes; i += 4096) buffer[i] = 0;
}

void probe_thread(const ProbeConfig& config, int index, ThreadState& state, const std::atomic<bool>& stop,
                  std::int64_t start_ns) {
  if (!config.cpus.empty()) {
    cpu_set_t set;
    CPU_ZERO(&set);
    const int cpu = config.cpus[static_cast<std::size_t>(index) % config.cpus.size()];
    CPU_SET(cpu, &set);
    if (const int e = pthread_setaffinity_np(pthread_self(), sizeof set, &set); e != 0)
      state.refusal += "pinning to CPU " + std::to_string(cpu) + " refused (" + std::strerror(e) + "); ";
  }
  if (config.realtime) {
    sched_param param{};
    param.sched_priority = config.priority;
    if (const int e = pthread_setschedparam(pthread_self(), SCHED_FIFO, &param); e != 0)
      state.refusal += "SCHED_FIFO " + std::to_string(config.priority) + " refused (" + std::strerror(e) + "); ";
  }
  int policy = 0;
  sched_param got{};
  pthread_getschedparam(pthread_self(), &policy, &got);
  state.policy = policy_name(policy);
  if (policy == SCHED_FIFO || policy == SCHED_RR) state.priority = got.sched_priority;
  prefault_stack();

  const std::int64_t period = config.period_ns();
  const std::int64_t cpu0 = now_ns(CLOCK_THREAD_CPUTIME_ID);
  std::int64_t next = start_ns;
  while (!stop.load(std::memory_order_relaxed)) {
    const timespec target = to_timespec(next);
    while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &target, nullptr) == EINTR) {
    }
    const std::int64_t woke = now_ns();
    std::int64_t end = woke;
    if (config.computation_ns > 0)  // the "control computation": busy, like a controller's arithmetic
      while ((end = now_ns()) - woke < config.computation_ns) {
      }
    state.recorder.add(woke - next, end - woke);
    next += period;
    // A whole period or more behind: the activations already past are lost (see probe.h), counted as misses.
    while (end - next >= period) {
      state.recorder.add_skipped(end - next);
      next += period;
    }
  }
  state.cpu_s = static_cast<double>(now_ns(CLOCK_THREAD_CPUTIME_ID) - cpu0) / kNsPerS;
}

bool try_fifo_on_scratch_thread() {
  bool ok = false;
  std::thread t([&] {
    sched_param param{};
    param.sched_priority = 1;
    ok = pthread_setschedparam(pthread_self(), SCHED_FIFO, &param) == 0;
  });
  t.join();
  return ok;
}

}  // namespace

std::int64_t ProbeConfig::period_ns() const {
  return rate_hz > 0 ? static_cast<std::int64_t>(std::llround(1e9 / rate_hz)) : 0;
}

std::string validate(const ProbeConfig& c) {
  if (!(c.rate_hz >= kMinRateHz && c.rate_hz <= kMaxRateHz))
    return "rate " + std::to_string(c.rate_hz) + " Hz is outside 50 .. 10000 Hz";
  if (c.threads < 1 || c.threads > 64) return "threads " + std::to_string(c.threads) + " is outside 1 .. 64";
  if (c.computation_ns < 0 || c.computation_ns >= c.period_ns())
    return "computation " + std::to_string(c.computation_ns / 1000) + " us is not below the period (" +
           std::to_string(c.period_ns() / 1000) + " us)";
  if (c.deadline_ns && *c.deadline_ns <= 0) return "deadline must be positive";
  if (c.priority < 1 || c.priority > 99) return "priority " + std::to_string(c.priority) + " is outside 1 .. 99";
  if (c.bin_ns <= 0 || c.limit_ns < c.bin_ns || c.limit_ns / c.bin_ns > (1 << 22))
    return "histogram limit " + std::to_string(c.limit_ns) + " ns with " + std::to_string(c.bin_ns) +
           " ns bins is out of range";
  const int cpus = static_cast<int>(std::thread::hardware_concurrency());
  for (int cpu : c.cpus)
    if (cpu < 0 || (cpus > 0 && cpu >= cpus))
      return "CPU " + std::to_string(cpu) + " does not exist (0 .. " + std::to_string(cpus - 1) + ")";
  return {};
}

RealtimeRights probe_realtime_rights() {
  RealtimeRights r;
  rlimit rtprio{};
  getrlimit(RLIMIT_RTPRIO, &rtprio);
  r.fifo = try_fifo_on_scratch_thread();
  // With CAP_SYS_NICE the limit does not apply; the scratch thread's success at priority 1 shows the right.
  r.max_priority = !r.fifo                            ? 0
                   : rtprio.rlim_cur == RLIM_INFINITY ? 99
                                                      : static_cast<int>(std::min<rlim_t>(rtprio.rlim_cur, 99));
  if (r.fifo && r.max_priority == 0) r.max_priority = 99;  // allowed through CAP_SYS_NICE
  rlimit memlock{};
  getrlimit(RLIMIT_MEMLOCK, &memlock);
  r.memlock = memlock.rlim_cur == RLIM_INFINITY;
  if (!r.fifo)
    r.explanation = "SCHED_FIFO not permitted (no CAP_SYS_NICE, RLIMIT_RTPRIO " +
                    (rtprio.rlim_cur == RLIM_INFINITY ? std::string("unlimited") : std::to_string(rtprio.rlim_cur)) +
                    "): the probe runs as a normal thread and its numbers are not comparable with real-time ones";
  return r;
}

ProbeResult run_probe(const ProbeConfig& config, double seconds, const CancelToken* cancel, const std::string& step) {
  if (const std::string e = validate(config); !e.empty()) throw std::invalid_argument(e);
  if (!(seconds > 0)) throw std::invalid_argument("probe duration must be positive");
  ProbeResult result;
  // Locked memory: MCL_FUTURE only where the limit is unlimited, so that a load in the same process (the vision
  // pipeline) cannot start failing its allocations against a small RLIMIT_MEMLOCK.
  bool locked = false;
  if (config.realtime) {
    rlimit memlock{};
    getrlimit(RLIMIT_MEMLOCK, &memlock);
    const int flags = memlock.rlim_cur == RLIM_INFINITY ? (MCL_CURRENT | MCL_FUTURE) : MCL_CURRENT;
    locked = mlockall(flags) == 0;
    if (!locked)
      result.notes.push_back(std::string("memory not locked: mlockall refused (") + std::strerror(errno) + ")");
  }
  std::vector<std::unique_ptr<ThreadState>> states;
  for (int i = 0; i < config.threads; ++i) states.push_back(std::make_unique<ThreadState>(config));
  std::atomic<bool> stop{false};
  // Every thread starts its schedule on the same absolute time, far enough ahead for the threads to set up.
  const std::int64_t start = now_ns() + 50'000'000;
  std::vector<std::thread> threads;
  try {
    for (int i = 0; i < config.threads; ++i)
      threads.emplace_back(probe_thread, std::cref(config), i, std::ref(*states[static_cast<std::size_t>(i)]),
                           std::cref(stop), start);
  } catch (const std::system_error& e) {
    stop = true;
    for (auto& t : threads) t.join();
    if (locked) munlockall();
    throw std::runtime_error(std::string("cannot start a probe thread: ") + e.what());
  }
  const std::int64_t end = start + static_cast<std::int64_t>(seconds * 1e9);
  bool cancelled = false;
  for (;;) {
    const std::int64_t t = now_ns();
    if (t >= end) break;
    if (cancel && cancel->cancelled()) {
      cancelled = true;
      break;
    }
    if (cancel)
      cancel->report(std::clamp(static_cast<double>(t - start) / static_cast<double>(end - start), 0.0, 1.0), step);
    const timespec slice = to_timespec(std::min<std::int64_t>(end - t, 20'000'000));
    nanosleep(&slice, nullptr);
  }
  stop = true;
  for (auto& t : threads) t.join();
  result.wall_s = static_cast<double>(now_ns() - start) / 1e9;
  if (locked) munlockall();
  if (cancelled) throw Cancelled();

  double cpu = 0;
  std::uint64_t skipped = 0;
  for (int i = 0; i < config.threads; ++i) {
    ThreadState& s = *states[static_cast<std::size_t>(i)];
    ThreadLatency t = s.recorder.result();
    t.index = i;
    if (!config.cpus.empty()) t.cpu = config.cpus[static_cast<std::size_t>(i) % config.cpus.size()];
    t.policy = s.policy;
    t.priority = s.priority;
    t.memory_locked = locked;
    t.period_ns = config.period_ns();
    t.computation_ns = config.computation_ns;
    t.deadline_ns = config.deadline();
    result.threads.push_back(std::move(t));
    cpu += s.cpu_s;
    skipped += s.recorder.skipped();
    if (!s.refusal.empty()) {
      std::string why = s.refusal.substr(0, s.refusal.size() - 2);
      result.notes.push_back("thread " + std::to_string(i) + ": " + why + ": ran as " + s.policy);
    }
  }
  result.cpu_s_per_s = result.wall_s > 0 ? cpu / result.wall_s : 0;
  if (skipped > 0)
    result.notes.push_back(std::to_string(skipped) +
                           " activations skipped while a whole period behind (counted as misses)");
  return result;
}

}  // namespace bs::headroom
