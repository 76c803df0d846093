// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Samples the chosen sensors on a thread of its own while a benchmark runs, and turns the samples into a
// PowerTrace (watts, seconds from the first sample) with named phases (warm-up, each sweep point, each pipeline
// stage) that the benchmark marks as it goes. Energy counters become power as delta E / delta t between
// consecutive samples, stamped at the interval's end; the first row repeats the first interval's power so the
// trace starts when the recording did. The sampler only sleeps between samples (a few sysfs reads each), so it
// costs the benchmark next to nothing: `bench kernels` measures how much.
#include <chrono>
#include <condition_variable>
#include <functional>
#include <limits>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "model/power_trace.h"
#include "sensors/discovery.h"

namespace bs::sensors {

class PowerRecorder {
 public:
  PowerRecorder(Selection selection, std::chrono::microseconds interval);
  ~PowerRecorder();
  PowerRecorder(const PowerRecorder&) = delete;
  PowerRecorder& operator=(const PowerRecorder&) = delete;

  // Called on the sampling thread after every sample, with its time and each sensor's power in W (an energy
  // counter: the mean over the interval since the previous sample; NaN for its first sample or a failed read),
  // in the order of channel_names(): a live view or an event stream follows the recording as it happens. Set it
  // before start(); it must not call back into the recorder.
  using SampleFn = std::function<void(double time_s, const std::vector<double>& watts)>;
  void set_on_sample(SampleFn fn) { on_sample_ = std::move(fn); }
  // The channels' names as finish() gives them, and the index of the total among them.
  std::vector<std::string> channel_names() const;
  std::size_t total_index() const { return selection_.total; }
  void start();          // first sample now, then one every interval
  double now_s() const;  // seconds since start()
  // Phases: begin_phase closes the open one (if any) at now and opens `name`; end_phase closes it.
  void begin_phase(const std::string& name);
  void end_phase();
  void add_phase(const std::string& name, double start_s, double end_s);
  std::size_t samples() const;
  double interval_s() const { return std::chrono::duration<double>(interval_).count(); }
  // CPU time the sampling thread used (reads, bookkeeping, wake-ups), known after finish(): the direct measure of
  // what recording costs a benchmark, immune to the noise of a shared machine that a with/without ratio suffers.
  // NaN where the platform has no per-thread CPU clock.
  double sampler_cpu_s() const { return sampler_cpu_s_; }
  double recorded_s() const { return recorded_s_; }  // wall time from start() to finish()
  // Stops the thread after one last sample and builds the trace (platform = this host, label, provenance:
  // measured, on-board sensor, the total sensor's id and the selection note in the settings).
  PowerTrace finish(const std::string& label);
  const Selection& selection() const { return selection_; }

 private:
  void sample();  // caller holds mutex_
  void loop();

  Selection selection_;
  std::chrono::microseconds interval_;
  std::chrono::steady_clock::time_point t0_;
  std::string start_iso_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  bool stop_ = false, started_ = false, finished_ = false;
  std::thread thread_;
  std::vector<double> time_s_;
  std::vector<std::vector<double>> raw_;  // per sensor: W, or cumulative J for energy sensors; NaN: failed read
  std::vector<TracePhase> phases_;
  std::string open_phase_;
  double open_start_ = 0;
  bool phase_open_ = false;
  double sampler_cpu_s_ = std::numeric_limits<double>::quiet_NaN();  // written by the thread as it ends
  double recorded_s_ = 0;
  SampleFn on_sample_;
};

// Raw readings of one energy counter (cumulative J, NaN where a read failed) at `time_s` -> watts: the mean
// power of the interval ending at each sample; the first sample takes the first interval's power. A sample
// whose own or previous reading failed is NaN.
std::vector<double> power_from_energy(const std::vector<double>& time_s, const std::vector<double>& joules);

}  // namespace bs::sensors
