// SPDX-License-Identifier: GPL-3.0-or-later
#include "sustain/sustain_runner.h"

#include <time.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

#include "analysis/power/phase_energy.h"
#include "sensors/recorder.h"
#include "util/host_clock.h"
#include "util/text.h"

namespace bs::sustain {
namespace {

using Clock = std::chrono::steady_clock;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double seconds_between(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

// Sleeps until `when` in slices of at most 50 ms, so a cancel stops the run promptly. False when cancelled.
bool sleep_until(Clock::time_point when, const CancelToken* cancel) {
  for (;;) {
    if (cancel) {
      cancel->report(0, "sustain");  // lets the owner turn a Ctrl+C into a cancel (as headroom's progress does)
      if (cancel->cancelled()) return false;
    }
    const auto now = Clock::now();
    if (now >= when) return true;
    const auto left = std::min<Clock::duration>(when - now, std::chrono::milliseconds(50));
    const auto ns = std::chrono::duration_cast<std::chrono::nanoseconds>(left).count();
    const timespec ts{static_cast<time_t>(ns / 1'000'000'000), static_cast<long>(ns % 1'000'000'000)};
    nanosleep(&ts, nullptr);
  }
}

std::string number(double v) { return format_number("%g", v); }

}  // namespace

RunOutput run_sustain(const RunConfig& config, headroom::Load& load, const SysfsSampler& sampler,
                      sensors::PowerRecorder* power, const CancelToken* cancel, const IntervalFn& on_interval) {
  if (!(config.seconds > 0 && config.seconds <= kMaxRunS))
    throw std::invalid_argument("the run must last more than 0 and at most " + number(kMaxRunS) + " s");
  if (!(config.interval_s >= kMinIntervalS && config.interval_s <= kMaxIntervalS))
    throw std::invalid_argument("the interval must be from " + number(kMinIntervalS) + " to " + number(kMaxIntervalS) +
                                " s");
  RunOutput out;
  SustainRun& r = out.run;
  r.platform = config.platform.empty() ? host_name() : config.platform;
  r.load = load.name();
  r.rate_unit = load.rate_unit();
  r.interval_s = config.interval_s;
  r.label = r.load + " for " + number(config.seconds) + " s";
  r.not_exposed = sampler.not_exposed();
  for (const ClockSource& c : sampler.clocks()) r.clocks.push_back({c.name, c.max_hz, {}});
  for (const TemperatureSource& t : sampler.temperatures()) r.temperatures.push_back({t.name, t.trip_c, {}});
  r.provenance.origin = DataOrigin::Measured;
  r.provenance.host = host_name();
  r.provenance.date = utc_timestamp();
  r.provenance.tool = std::string("benchscope ") + BENCHSCOPE_VERSION;
  r.provenance.compiler = BENCHSCOPE_COMPILER;
  r.provenance.note = config.command;
  r.provenance.settings = {
      {"load", load.detail()}, {"seconds", number(config.seconds)}, {"interval_s", number(config.interval_s)}};

  std::map<std::string, std::size_t> warning_counts;  // each distinct warning once, counted
  std::vector<std::string> warning_order;
  const auto note_warning = [&](const std::string& w) {
    if (warning_counts[w]++ == 0) warning_order.push_back(w);
  };
  for (const std::string& w : sampler.discovery_warnings()) note_warning(w);

  load.start();  // throws std::runtime_error when it cannot run
  if (power) power->begin_phase("sustain " + r.load);
  std::vector<double> power_from, power_to;  // each interval's window on the recorder's clock
  try {
    if (!load.work_done())
      throw std::runtime_error("load '" + load.name() + "' cannot count its work, so it has no rate per interval");
    const auto t0 = Clock::now();
    double work_before = *load.work_done();
    double p_before = power ? power->now_s() : 0;
    auto before = t0;
    const auto n = static_cast<std::size_t>(std::ceil(config.seconds / config.interval_s - 1e-9));
    for (std::size_t i = 0; i < n; ++i) {
      const double end_s = std::min(config.seconds, static_cast<double>(i + 1) * config.interval_s);
      if (!sleep_until(t0 + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(end_s)),
                       cancel)) {
        out.cancelled = true;
        break;
      }
      const auto now = Clock::now();
      const double work = load.work_done().value_or(kNaN);
      const double dt = seconds_between(before, now);
      const SysfsSample s = sampler.sample();
      r.t_s.push_back(seconds_between(t0, now));
      r.rate.push_back(dt > 0 && std::isfinite(work) ? (work - work_before) / dt : kNaN);
      for (std::size_t k = 0; k < r.clocks.size(); ++k) r.clocks[k].hz.push_back(s.clock_hz[k]);
      for (std::size_t k = 0; k < r.temperatures.size(); ++k) r.temperatures[k].celsius.push_back(s.temperature_c[k]);
      if (power) {
        const double p_now = power->now_s();
        power_from.push_back(p_before);
        power_to.push_back(p_now);
        p_before = p_now;
      }
      for (const std::string& w : s.warnings) note_warning(w);
      work_before = std::isfinite(work) ? work : work_before;
      before = now;
      if (on_interval) on_interval(r, r.t_s.size() - 1, s.warnings);
    }
  } catch (...) {
    (void)load.stop();
    if (power) (void)power->finish("sustain (failed)");
    throw;
  }
  const headroom::LoadReport report = load.stop();
  if (power) power->end_phase();
  out.load_notes = report.notes;
  if (out.cancelled) r.label += " (cancelled after " + number(r.t_s.empty() ? 0 : r.t_s.back()) + " s)";
  if (power) {
    out.power = power->finish("sustain " + r.load + " " + r.platform + " " + r.provenance.date);
    out.power->platform = r.platform;
    r.power_sensor = out.power->provenance.sensor;
    r.provenance.measurement = out.power->provenance.measurement;
    r.provenance.sensor = out.power->provenance.sensor;
    bool any = false;
    for (std::size_t i = 0; i < power_from.size(); ++i) {
      const auto e = window_energy(*out.power, power_from[i], power_to[i]);
      const double w = e && std::isfinite(e->mean_power_w) ? e->mean_power_w : kNaN;
      any = any || std::isfinite(w);
      r.power_w.push_back(w);
    }
    if (!any) r.power_w.clear();
  }
  for (const std::string& w : warning_order) {
    const std::size_t count = warning_counts[w];
    out.warnings.push_back(count > 1 ? w + " (" + std::to_string(count) + " times)" : w);
  }
  return out;
}

}  // namespace bs::sustain
