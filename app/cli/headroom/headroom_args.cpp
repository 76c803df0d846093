// SPDX-License-Identifier: GPL-3.0-or-later
#include "headroom/headroom_args.h"

#include <cmath>

namespace bs::cli {
namespace {

double whole(const ParsedArgs& args, const std::string& option, double fallback, double min, double max) {
  const double v = args.number(option, fallback);
  if (!(v >= min && v <= max) || v != std::floor(v))
    throw UsageError(option + " must be a whole number from " + std::to_string(static_cast<long long>(min)) + " to " +
                     std::to_string(static_cast<long long>(max)));
  return v;
}

}  // namespace

headroom::ProbeConfig probe_config(const ParsedArgs& args) {
  headroom::ProbeConfig c;
  c.rate_hz = args.number("--rate", 1000);
  if (!(c.rate_hz >= headroom::kMinRateHz && c.rate_hz <= headroom::kMaxRateHz))
    throw UsageError("--rate must be from 50 to 10000 Hz");
  c.threads = static_cast<int>(whole(args, "--threads", 1, 1, 64));
  c.computation_ns = static_cast<std::int64_t>(std::llround(args.number("--computation-us", 0) * 1000));
  if (c.computation_ns < 0 || c.computation_ns >= c.period_ns())
    throw UsageError("--computation-us must be at least 0 and below the period (" +
                     std::to_string(c.period_ns() / 1000) + " us)");
  if (args.value("--deadline-us")) {
    const double d = args.number("--deadline-us", 0);
    if (!(d > 0 && d <= 1e7)) throw UsageError("--deadline-us must be above 0 and at most 10,000,000");
    c.deadline_ns = static_cast<std::int64_t>(std::llround(d * 1000));
  }
  c.priority = static_cast<int>(whole(args, "--priority", 80, 1, 99));
  c.limit_ns = static_cast<std::int64_t>(whole(args, "--limit-us", 10000, 10, 4'000'000)) * 1000;
  c.realtime = !args.has("--no-rt");
  if (const auto cpus = args.value("--cpu")) {
    std::string cur;
    for (char ch : *cpus + ",") {
      if (ch == ',') {
        if (cur.empty()) throw UsageError("--cpu takes CPU numbers separated by commas (got '" + *cpus + "')");
        char* end = nullptr;
        const long v = std::strtol(cur.c_str(), &end, 10);
        if (*end != '\0' || v < 0 || v > 4095) throw UsageError("--cpu: '" + cur + "' is not a CPU number");
        c.cpus.push_back(static_cast<int>(v));
        cur.clear();
      } else {
        cur += ch;
      }
    }
  }
  if (const std::string e = headroom::validate(c); !e.empty()) throw UsageError(e);
  return c;
}

}  // namespace bs::cli
