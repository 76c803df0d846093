// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/bench_host.h"

#include <ctime>
#include <fstream>

namespace bs::cli {

double process_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

std::string load_average_text() {
  std::ifstream f("/proc/loadavg");
  std::string one, five;
  f >> one >> five;
  return one.empty() ? "unknown" : one + " (1 min), " + five + " (5 min)";
}

double one_minute_load() {
  double load = -1;
  std::ifstream("/proc/loadavg") >> load;
  return load;
}

}  // namespace bs::cli
