// SPDX-License-Identifier: GPL-3.0-or-later
#include "headroom/headroom_run.h"

#include <time.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "analysis/power/phase_energy.h"
#include "sensors/recorder.h"
#include "util/host_clock.h"

namespace bs::headroom {
namespace {

// Waits `seconds` in short slices, polling the cancel token (the load settles meanwhile).
void settle(double seconds, const CancelToken* cancel) {
  double left = seconds;
  while (left > 0) {
    if (cancel) cancel->throw_if_cancelled();
    const double slice = std::min(left, 0.02);
    const timespec ts{0, static_cast<long>(slice * 1e9)};
    nanosleep(&ts, nullptr);
    left -= slice;
  }
}

// Phase i of n: the probe's progress within it, mapped onto the whole run, and the outer cancel passed inward.
struct PhaseToken {
  CancelToken inner;
  PhaseToken(const CancelToken* outer, std::size_t i, std::size_t n, const std::string& step) {
    inner.set_progress([this, outer, i, n, step](double f, std::string_view) {
      if (!outer) return;
      if (outer->cancelled()) inner.cancel();
      outer->report((static_cast<double>(i) + f) / static_cast<double>(n), step);
    });
  }
};

Phase measure(const RunConfig& config, Load* load, std::size_t index, std::size_t count, const CancelToken* cancel,
              sensors::PowerRecorder* power, std::vector<std::string>& run_notes) {
  Phase phase;
  phase.name = load ? load->name() : "idle";
  phase.load = load ? load->kind() : LoadKind::Idle;
  if (load) {
    phase.load_detail = load->detail();
    phase.target_rate = load->target_rate();
    phase.rate_unit = load->rate_unit();
    if (cancel) cancel->report(static_cast<double>(index) / static_cast<double>(count), "starting " + phase.name);
    load->start();
  }
  ProbeResult probe;
  try {
    if (load) settle(config.settle_s, cancel);
    PhaseToken token(cancel, index, count, phase.name);
    if (power) power->begin_phase(phase.name);
    probe = run_probe(config.probe, config.phase_s, &token.inner, phase.name);
    if (power) power->end_phase();
  } catch (...) {
    if (load) (void)load->stop();
    throw;
  }
  if (load) {
    LoadReport report = load->stop();
    phase.achieved_rate = report.achieved_rate;
    phase.notes = std::move(report.notes);
    // A shortfall is a flag of the measurement (headroom::flags), shown in every view; no note repeats it.
    if (!phase.achieved_rate && !phase.rate_unit.empty())
      phase.notes.push_back("achieved rate unknown (the load did not report one)");
  }
  phase.duration_s = probe.wall_s;
  phase.probe_cpu_s_per_s = probe.cpu_s_per_s;
  phase.threads = std::move(probe.threads);
  // What the probe says about this phase (activations skipped) stays with it; what holds for every phase (the
  // policy refused, memory not locked) is said once, on the first phase that met it.
  for (std::string& n : probe.notes)
    if (std::find(run_notes.begin(), run_notes.end(), n) == run_notes.end()) {
      run_notes.push_back(n);
      phase.notes.push_back(std::move(n));
    }
  return phase;
}

}  // namespace

RunOutput run_headroom(const RunConfig& config, const std::vector<Load*>& loads, sensors::PowerRecorder* power,
                       const CancelToken* cancel) {
  if (const std::string e = validate(config.probe); !e.empty()) throw std::invalid_argument(e);
  if (!(config.phase_s > 0)) throw std::invalid_argument("phase duration must be positive");
  if (!config.idle_phase && loads.empty()) throw std::invalid_argument("nothing to measure: no idle phase, no load");
  RunOutput out;
  HeadroomMeasurement& m = out.measurement;
  m.platform = config.platform.empty() ? host_name() : config.platform;
  m.kind = LatencyKind::ApplicationLoop;
  m.tool = "benchscope probe";
  m.command = config.command;
  m.kernel = read_kernel_facts(config.kernel_root);
  m.provenance.origin = DataOrigin::Measured;
  m.provenance.host = host_name();
  m.provenance.date = utc_timestamp();
  m.provenance.tool = std::string("benchscope ") + BENCHSCOPE_VERSION;
  m.provenance.compiler = BENCHSCOPE_COMPILER;
  const ProbeConfig& p = config.probe;
  m.provenance.settings = {{"rate_hz", std::to_string(p.rate_hz)},
                           {"threads", std::to_string(p.threads)},
                           {"computation_us", std::to_string(p.computation_ns / 1000)},
                           {"deadline_us", std::to_string(p.deadline() / 1000)},
                           {"realtime asked", p.realtime ? "SCHED_FIFO " + std::to_string(p.priority) : "no"},
                           {"phase_s", std::to_string(config.phase_s)},
                           {"settle_s", std::to_string(config.settle_s)}};
  std::vector<Load*> phases;
  if (config.idle_phase) phases.push_back(nullptr);
  phases.insert(phases.end(), loads.begin(), loads.end());
  std::vector<std::string> run_notes;
  try {
    for (std::size_t i = 0; i < phases.size(); ++i)
      m.phases.push_back(measure(config, phases[i], i, phases.size(), cancel, power, run_notes));
  } catch (...) {
    if (power) (void)power->finish("headroom (cancelled)");
    throw;
  }
  if (power) {
    out.power = power->finish("headroom " + m.platform + " " + m.provenance.date);
    out.power->platform = m.platform;
    const std::vector<PhaseEnergy> energies = phase_energies(*out.power);
    for (Phase& ph : m.phases)
      for (const PhaseEnergy& e : energies)
        if (e.name == ph.name && std::isfinite(e.mean_power_w) && e.end_s > e.start_s) {
          ph.mean_power_w = e.mean_power_w;
          ph.power_sensor = out.power->provenance.sensor;
        }
    m.provenance.measurement = out.power->provenance.measurement;
    m.provenance.sensor = out.power->provenance.sensor;
  }
  // What was obtained, beside what was asked, in the provenance every export carries.
  std::string obtained = "yes";
  for (const Phase& ph : m.phases)
    for (const ThreadLatency& t : ph.threads)
      if (!t.realtime()) obtained = "no (" + t.policy + "): not comparable with real-time results";
  m.provenance.settings.emplace_back("realtime obtained", obtained);
  if (const std::string e = m.bookkeeping_error(); !e.empty()) throw std::logic_error("probe bookkeeping: " + e);
  return out;
}

}  // namespace bs::headroom
