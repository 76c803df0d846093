// SPDX-License-Identifier: GPL-3.0-or-later
#include "headroom/cyclictest_threads.h"

#include <charconv>
#include <vector>

namespace bs::headroom_import {
namespace {

// Reads "<label><spaces><integer>" at the front of *s and advances past it.
template <class T>
bool labelled(std::string_view* s, std::string_view label, T* value) {
  std::string_view t = *s;
  while (!t.empty() && t.front() == ' ') t.remove_prefix(1);
  if (!t.starts_with(label)) return false;
  t.remove_prefix(label.size());
  while (!t.empty() && t.front() == ' ') t.remove_prefix(1);
  const auto [ptr, ec] = std::from_chars(t.data(), t.data() + t.size(), *value);
  if (ec != std::errc() || ptr == t.data()) return false;
  t.remove_prefix(static_cast<std::size_t>(ptr - t.data()));
  *s = t;
  return true;
}

}  // namespace

std::optional<StatusLine> parse_status_line(std::string_view text, std::size_t line) {
  StatusLine s;
  s.line = line;
  std::string_view t = text;
  if (!labelled(&t, "T:", &s.index) || !labelled(&t, "(", &s.pid)) return std::nullopt;
  while (!t.empty() && t.front() == ' ') t.remove_prefix(1);
  if (!t.starts_with(")")) return std::nullopt;
  t.remove_prefix(1);
  if (!labelled(&t, "P:", &s.priority) || !labelled(&t, "I:", &s.interval_us) || !labelled(&t, "C:", &s.cycles) ||
      !labelled(&t, "Min:", &s.min) || !labelled(&t, "Act:", &s.act) || !labelled(&t, "Avg:", &s.avg) ||
      !labelled(&t, "Max:", &s.max))
    return std::nullopt;
  // Beyond these the line is not a real run, and the values would overflow on the way to nanoseconds.
  constexpr std::int64_t kMax = 1'000'000'000'000'000;
  if (s.index < 0 || s.index > 1 << 20 || s.cycles > static_cast<std::uint64_t>(kMax)) return std::nullopt;
  for (std::int64_t v : {s.interval_us, s.min, s.act, s.avg, s.max})
    if (v > kMax || v < -kMax) return std::nullopt;
  // Field width of Act (between "Act:" and " Avg:"): %8ld with -N, %5ld without, when the number fits.
  const auto act = text.find("Act:");
  const auto avg = text.find(" Avg:", act);
  if (act != std::string_view::npos && avg != std::string_view::npos) {
    const std::size_t width = avg - (act + 4);
    if (width == 8) s.nsecs = true;
    if (width == 5) s.nsecs = false;
  }
  return s;
}

std::optional<int> cpu_of_thread(std::string_view cpuset, int index) {
  std::vector<int> cpus;
  std::size_t i = 0;
  while (i < cpuset.size()) {
    const std::size_t comma = std::min(cpuset.find(',', i), cpuset.size());
    const std::string_view part = cpuset.substr(i, comma - i);
    int lo = 0, hi = 0;
    const auto dash = part.find('-');
    const std::string_view a = part.substr(0, dash);
    const auto [pa, ea] = std::from_chars(a.data(), a.data() + a.size(), lo);
    if (ea != std::errc() || pa != a.data() + a.size()) return std::nullopt;
    hi = lo;
    if (dash != std::string_view::npos) {
      const std::string_view b = part.substr(dash + 1);
      const auto [pb, eb] = std::from_chars(b.data(), b.data() + b.size(), hi);
      if (eb != std::errc() || pb != b.data() + b.size() || hi < lo || hi - lo > 4096) return std::nullopt;
    }
    for (int c = lo; c <= hi; ++c) cpus.push_back(c);
    i = comma + 1;
  }
  if (cpus.empty() || index < 0) return std::nullopt;
  return cpus[static_cast<std::size_t>(index) % cpus.size()];
}

void apply_thread_facts(headroom::ThreadLatency* thread, int index, const std::optional<CyclictestCommand>& command,
                        const std::map<int, StatusLine>& status, const std::string& policy_line,
                        std::optional<int> cpu_from_file) {
  const auto s = status.find(index);
  const StatusLine* line = s == status.end() ? nullptr : &s->second;
  if (line && line->interval_us > 0) {
    thread->period_ns = line->interval_us * 1000;
  } else if (command) {
    thread->period_ns = command->period_ns(index);
  }
  thread->deadline_ns = thread->period_ns;
  if (line) {
    thread->priority = line->priority;
  } else if (command) {
    thread->priority = command->priority_of(index);
  }
  if (command) {
    thread->policy = command->policy;
  } else if (!policy_line.empty()) {
    // "policy: fifo: loadavg: ...", or "fifo/other" when cyclictest had to fall back to SCHED_OTHER.
    const std::string_view p = std::string_view(policy_line).substr(0, policy_line.find(':'));
    if (p.find('/') != std::string_view::npos || p.starts_with("other")) {
      thread->policy = "SCHED_OTHER";
    } else if (p.starts_with("fifo")) {
      thread->policy = "SCHED_FIFO";
    } else if (p.starts_with("rr")) {
      thread->policy = "SCHED_RR";
    }
  }
  // Priority 0 is no real-time priority: cyclictest then runs the thread SCHED_OTHER.
  if (thread->priority && *thread->priority == 0) {
    thread->policy = thread->policy.empty() || thread->realtime() ? "SCHED_OTHER" : thread->policy;
    thread->priority.reset();
  }
  if (command) thread->memory_locked = command->mlockall;
  if (cpu_from_file && *cpu_from_file >= 0) {
    thread->cpu = cpu_from_file;
  } else if (command && !command->affinity.empty() && command->affinity != "all") {
    thread->cpu = cpu_of_thread(command->affinity, index);
  }
}

}  // namespace bs::headroom_import
