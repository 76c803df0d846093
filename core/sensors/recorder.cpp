// SPDX-License-Identifier: GPL-3.0-or-later
#include "sensors/recorder.h"

#include <cmath>
#include <cstdio>
#include <ctime>
#include <limits>
#include <set>

#include "analysis/power/power_time.h"
#include "util/host_clock.h"

namespace bs::sensors {

std::vector<double> power_from_energy(const std::vector<double>& time_s, const std::vector<double>& joules) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> watts(joules.size(), nan);
  for (std::size_t i = 1; i < joules.size() && i < time_s.size(); ++i) {
    const double dt = time_s[i] - time_s[i - 1];
    if (std::isfinite(joules[i]) && std::isfinite(joules[i - 1]) && dt > 0) watts[i] = (joules[i] - joules[i - 1]) / dt;
  }
  if (watts.size() >= 2) watts[0] = watts[1];
  return watts;
}

PowerRecorder::PowerRecorder(Selection selection, std::chrono::microseconds interval)
    : selection_(std::move(selection)), interval_(interval), raw_(selection_.sensors.size()) {}

PowerRecorder::~PowerRecorder() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void PowerRecorder::start() {
  std::lock_guard lock(mutex_);
  if (started_) return;
  started_ = true;
  // The wall-clock time of the first sample (to the millisecond), so a trace lines up with other logs.
  const auto wall = std::chrono::system_clock::now();
  t0_ = std::chrono::steady_clock::now();
  start_iso_ = format_iso8601(std::chrono::duration<double>(wall.time_since_epoch()).count()) + "Z";
  sample();
  thread_ = std::thread([this] { loop(); });
}

double PowerRecorder::now_s() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
}

void PowerRecorder::sample() {
  time_s_.push_back(now_s());
  for (std::size_t i = 0; i < selection_.sensors.size(); ++i) {
    const auto v = selection_.sensors[i]->read();
    raw_[i].push_back(v ? *v : std::numeric_limits<double>::quiet_NaN());
  }
  if (!on_sample_) return;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::size_t n = time_s_.size();
  std::vector<double> watts(raw_.size(), nan);
  for (std::size_t i = 0; i < raw_.size(); ++i) {
    if (selection_.sensors[i]->info().quantity != SensorQuantity::Energy) {
      watts[i] = raw_[i].back();
    } else if (n >= 2 && time_s_[n - 1] > time_s_[n - 2]) {
      watts[i] = (raw_[i][n - 1] - raw_[i][n - 2]) / (time_s_[n - 1] - time_s_[n - 2]);  // NaN from a failed read
    }
  }
  on_sample_(time_s_.back(), watts);
}

std::vector<std::string> PowerRecorder::channel_names() const {
  std::set<std::string> labels;
  for (const auto& s : selection_.sensors) labels.insert(s->info().label);
  const bool unique = labels.size() == selection_.sensors.size();
  std::vector<std::string> names;
  for (const auto& s : selection_.sensors) names.push_back(unique ? s->info().label : s->info().id);
  return names;
}

namespace {

// CPU seconds the calling thread has used (POSIX per-thread clock); NaN without one.
double thread_cpu_s() {
#if defined(CLOCK_THREAD_CPUTIME_ID)
  timespec ts{};
  if (clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts) == 0) return static_cast<double>(ts.tv_sec) + ts.tv_nsec * 1e-9;
#endif
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

void PowerRecorder::loop() {
  std::unique_lock lock(mutex_);
  struct CpuAtExit {  // every way out of the loop records what the thread used
    double& into;
    ~CpuAtExit() { into = thread_cpu_s(); }
  } cpu_at_exit{sampler_cpu_s_};
  auto next = t0_ + interval_;
  while (!stop_) {
    // Deadlines on a fixed grid, so a slow read does not shift every later sample.
    if (wake_.wait_until(lock, next, [this] { return stop_; })) break;
    sample();
    next += interval_;
    const auto now = std::chrono::steady_clock::now();
    if (next < now) next = now + interval_;  // fell behind (machine suspended): skip, do not burst
  }
}

void PowerRecorder::begin_phase(const std::string& name) {
  const double t = now_s();
  std::lock_guard lock(mutex_);
  if (phase_open_) phases_.push_back({open_phase_, open_start_, t});
  open_phase_ = name;
  open_start_ = t;
  phase_open_ = true;
}

void PowerRecorder::end_phase() {
  const double t = now_s();
  std::lock_guard lock(mutex_);
  if (phase_open_) phases_.push_back({open_phase_, open_start_, t});
  phase_open_ = false;
}

void PowerRecorder::add_phase(const std::string& name, double start_s, double end_s) {
  std::lock_guard lock(mutex_);
  phases_.push_back({name, start_s, end_s});
}

std::size_t PowerRecorder::samples() const {
  std::lock_guard lock(mutex_);
  return time_s_.size();
}

PowerTrace PowerRecorder::finish(const std::string& label) {
  end_phase();
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  if (thread_.joinable()) thread_.join();
  std::lock_guard lock(mutex_);
  if (started_ && !finished_) {
    sample();  // the end of the last interval
    recorded_s_ = now_s();
  }
  finished_ = true;
  PowerTrace trace;
  trace.platform = host_name();
  trace.label = label;
  trace.start_time = start_iso_;
  trace.time_s = time_s_;
  const std::vector<std::string> names = channel_names();
  for (std::size_t i = 0; i < selection_.sensors.size(); ++i) {
    const SensorInfo& info = selection_.sensors[i]->info();
    PowerChannel c;
    c.name = names[i];
    c.quantity = PowerQuantity::Power;
    c.values = info.quantity == SensorQuantity::Energy ? power_from_energy(time_s_, raw_[i]) : raw_[i];
    trace.channels.push_back(std::move(c));
  }
  if (!trace.channels.empty()) trace.total_channel = trace.channels[selection_.total].name;
  trace.phases = phases_;
  Provenance& p = trace.provenance;
  p.origin = DataOrigin::Measured;
  p.host = host_name();
  p.date = start_iso_;
  p.tool = std::string("benchscope ") + BENCHSCOPE_VERSION;
  p.measurement = MeasurementKind::OnBoardSensor;
  if (!selection_.sensors.empty()) {
    const SensorInfo& total = selection_.sensors[selection_.total]->info();
    p.sensor = std::string(to_string(total.kind)) + " " + total.label + " (" + total.id + ")";
    p.settings.emplace_back("sensor kind", std::string(to_string(total.kind)));
    p.settings.emplace_back("sensor source", total.source);
  }
  char interval[32];
  std::snprintf(interval, sizeof interval, "%g ms", static_cast<double>(interval_.count()) / 1000.0);
  p.settings.emplace_back("sample interval", interval);
  if (!selection_.note.empty()) p.settings.emplace_back("sensor choice", selection_.note);
  if (std::isfinite(sampler_cpu_s_) && recorded_s_ > 0) {
    char cost[96];
    std::snprintf(cost, sizeof cost, "%.3f ms CPU in %.3f s (%.4f %% of one core)", sampler_cpu_s_ * 1e3, recorded_s_,
                  100.0 * sampler_cpu_s_ / recorded_s_);
    p.settings.emplace_back("sampler cost", cost);
  }
  return trace;
}

}  // namespace bs::sensors
