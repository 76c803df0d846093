// SPDX-License-Identifier: GPL-3.0-or-later
// bench sustain-sampler: the sampler's CPU cost (issue #53: under 1 % of a core at a 1 s interval), measured as the
// calling thread's CPU time (CLOCK_THREAD_CPUTIME_ID: immune to what else the machine runs), beside a reference
// that reads the same files with nothing but open/read/close, so the ratio shows what the sampler adds.
#include "sustain/bench_sustain_sampler.h"

#include <fcntl.h>
#include <time.h>
#include <unistd.h>

#include <ostream>

#include "analysis/stats/stats.h"
#include "common/args.h"
#include "sustain/sysfs_sampler.h"
#include "util/text.h"

namespace bs::cli {
namespace {

double thread_cpu_s() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec) * 1e-9;
}

// The reference: each file opened, read into a page and closed, nothing parsed.
std::size_t read_plain(const std::vector<std::string>& files) {
  char buf[4096];
  std::size_t bytes = 0;
  for (const std::string& f : files) {
    const int fd = ::open(f.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) continue;
    const ssize_t n = ::read(fd, buf, sizeof buf);
    if (n > 0) bytes += static_cast<std::size_t>(n);
    ::close(fd);
  }
  return bytes;
}

}  // namespace

int bench_sustain_sampler(const std::vector<std::string>& raw, std::ostream& out) {
  const ParsedArgs args = parse_args(raw, {}, {"--samples", "--rounds", "--seconds", "--sysfs-root"});
  const auto samples = static_cast<int>(commands::whole_number(args, "--samples", 200, 1, 1'000'000));
  const auto rounds = static_cast<int>(commands::whole_number(args, "--rounds", 5, 1, 1000));
  const auto seconds = static_cast<int>(commands::whole_number(args, "--seconds", 5, 0, 3600));
  const std::string root = args.value("--sysfs-root").value_or("/");
  const sustain::SysfsSampler sampler(root);
  std::vector<std::string> files;
  for (const auto& c : sampler.clocks()) files.push_back(c.current.string());
  for (const auto& t : sampler.temperatures()) files.push_back(t.file.string());
  out << "bench sustain-sampler: " << sampler.clocks().size() << " clock(s) and " << sampler.temperatures().size()
      << " temperature(s) under " << root << " (" << files.size() << " files per sample)\n";
  for (const std::string& n : sampler.not_exposed()) out << "  not exposed: " << n << "\n";
  if (files.empty()) {
    out << "bench sustain-sampler: nothing to read here; nothing measured\n";
    return 0;
  }
  RunningStats sampler_s, plain_s;
  std::size_t sink = 0;
  for (int r = 0; r < rounds; ++r) {
    // Alternate which goes first, so a cache warmed by one does not always favour the other.
    for (int which = 0; which < 2; ++which) {
      const bool sampler_turn = (which == 0) == (r % 2 == 0);
      const double t0 = thread_cpu_s();
      for (int i = 0; i < samples; ++i) {
        if (sampler_turn)
          sink += sampler.sample().clock_hz.size();
        else
          sink += read_plain(files);
      }
      const double per_sample = (thread_cpu_s() - t0) / samples;
      (sampler_turn ? sampler_s : plain_s).add(per_sample);
    }
  }
  const auto line = [&](const char* name, const RunningStats& s) {
    out << "  " << name << fixed(s.mean() * 1e6, 1) << " \xC2\xB1 " << fixed(s.sd() * 1e6, 1)
        << " us CPU per sample (n = " << s.count() << " rounds of " << samples << ") = " << fixed(s.mean() * 100, 4)
        << " % of one core at a 1 s interval\n";
  };
  line("sampler:              ", sampler_s);
  line("open/read/close only: ", plain_s);
  out << "  ratio sampler / reference: " << fixed(sampler_s.mean() / plain_s.mean(), 2) << "x\n";
  if (seconds > 0) {
    // The sampler as a run uses it: one sample a second, the thread asleep in between (wake-ups counted).
    const double t0 = thread_cpu_s();
    timespec next{};
    clock_gettime(CLOCK_MONOTONIC, &next);
    for (int i = 0; i < seconds; ++i) {
      next.tv_sec += 1;
      while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &next, nullptr) != 0) {
      }
      sink += sampler.sample().temperature_c.size();
    }
    const double cpu = thread_cpu_s() - t0;
    out << "  live, " << seconds << " s at a 1 s interval: " << fixed(cpu * 1e3, 3)
        << " ms CPU = " << fixed(100 * cpu / seconds, 4) << " % of one core (target: under 1 %)\n";
  }
  return sink == 0 ? 1 : 0;  // sink keeps the reads from being optimised away; 0 only if nothing was read
}

}  // namespace bs::cli
