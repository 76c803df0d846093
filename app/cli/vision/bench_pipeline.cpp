// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/bench_pipeline.h"

#include <time.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <ostream>
#include <thread>

#include <opencv2/core/utility.hpp>

#include "analysis/stats/stats.h"
#include "common/args.h"
#include "common/bench_host.h"
#include "common/signals.h"
#include "power/power_args.h"
#include "vision/pipeline/detector.h"
#include "vision/pipeline/pipeline.h"
#include "vision/pipeline/pipeline_measure.h"
#include "vision/pipeline/threads.h"
#include "vision/pipeline_args.h"
#include "vision/reproject/preprocess.h"

namespace bs::cli {
namespace {

using namespace bs::vision;
using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

// The sequential side over all rounds.
struct Sequential {
  std::vector<double> pre_ms, detect_ms;
  double wall_s = 0, cpu_s = 0;
  double fps() const { return wall_s > 0 ? static_cast<double>(pre_ms.size()) / wall_s : 0; }
  void add(const Sequential& r) {
    pre_ms.insert(pre_ms.end(), r.pre_ms.begin(), r.pre_ms.end());
    detect_ms.insert(detect_ms.end(), r.detect_ms.begin(), r.detect_ms.end());
    wall_s += r.wall_s;
    cpu_s += r.cpu_s;
  }
};

// The concurrent side over all rounds (each round one run_pipeline).
struct Concurrent {
  std::vector<double> pre_ms, detect_ms, e2e_ms;
  std::size_t processed = 0;
  double wall_s = 0, cpu_s = 0;
  double fps() const { return wall_s > 0 ? static_cast<double>(processed) / wall_s : 0; }
  void add(const std::pair<PipelineResult, double>& run) {
    const PipelineResult& r = run.first;
    const auto append = [&](std::vector<double>& to, const char* stage) {
      if (const StageTiming* t = r.stage(stage)) to.insert(to.end(), t->ms.begin(), t->ms.end());
    };
    append(pre_ms, "preprocessing");
    append(detect_ms, "detection");
    append(e2e_ms, "end-to-end");
    processed += r.processed;
    wall_s += r.wall_s;
    cpu_s += run.second;
  }
};

// run_pipeline with the process CPU time it took.
std::pair<PipelineResult, double> timed_pipeline(const FrameSource& source, const Preprocessor& preprocess,
                                                 const Detector& detector, const PipelineConfig& config,
                                                 const CancelToken& cancel) {
  const double cpu0 = process_cpu_seconds();
  PipelineResult r = run_pipeline(source, preprocess, detector, config, cancel);
  return {std::move(r), process_cpu_seconds() - cpu0};
}

// The stages one after another on this thread: the same preprocessor and detector the pipeline calls.
Sequential run_sequential(const cv::Mat& raw, std::size_t frames, const Preprocessor& preprocess,
                          const Detector& detector, const CancelToken& cancel) {
  Sequential s;
  const double cpu0 = process_cpu_seconds();
  const auto start = Clock::now();
  for (std::size_t i = 0; i < frames && !cancel.cancelled(); ++i) {
    auto t0 = Clock::now();
    const cv::Mat bgr = preprocess(raw);
    s.pre_ms.push_back(ms_since(t0));
    t0 = Clock::now();
    const std::vector<Detection> found = detector(bgr);
    s.detect_ms.push_back(ms_since(t0));
  }
  s.wall_s = std::chrono::duration<double>(Clock::now() - start).count();
  s.cpu_s = process_cpu_seconds() - cpu0;
  return s;
}

std::string stat(const std::vector<double>& ms) {
  const Summary s = summarize(ms);
  char b[96];
  std::snprintf(b, sizeof b, "%9.2f ± %6.2f ms (n = %zu)", s.mean, s.sd, s.n);
  return b;
}

// Restores OpenCV's and OpenMP's thread counts however the benchmark ends.
class ThreadingGuard {
 public:
  ThreadingGuard() : cv_(cv::getNumThreads()), omp_(vision_threads()) {}
  ~ThreadingGuard() {
    set_vision_threads(std::max(omp_, 1));
    cv::setNumThreads(cv_);
  }
  int opencv() const { return cv_; }

 private:
  int cv_, omp_;
};

}  // namespace

int bench_pipeline(const std::vector<std::string>& arguments, std::ostream& out) {
  const ParsedArgs args = parse_args(
      arguments, {},
      {"--frames", "--rounds", "--detect-workers", "--detect-scale", "--power", "--power-interval-ms", "--sysfs-root"});
  const double rounds_arg = args.number("--rounds", 3);
  if (!(rounds_arg >= 1 && rounds_arg <= 100) || rounds_arg != static_cast<double>(static_cast<long>(rounds_arg)))
    throw UsageError("--rounds must be a whole number from 1 to 100");
  const int rounds = static_cast<int>(rounds_arg);
  const double frames_arg = args.number("--frames", 16);
  if (!(frames_arg >= 2 && frames_arg <= 100000) || frames_arg != static_cast<double>(static_cast<long>(frames_arg)))
    throw UsageError("--frames must be a whole number from 2 to 100000");
  const auto frames = static_cast<std::size_t>(frames_arg);
  const std::size_t workers = detect_workers_option(args);
  const double scale = detect_scale_option(args);
  const CancelToken& cancel = interrupt_token();

  // The synthetic capture of the paper's camera (1280x1024 BGGR through the 195 degree lens, the test chart that
  // `synth-frame` writes to sample_data/paper-2018/frames) and the pipeline's default stages: fused demosaic +
  // reprojection to the 150 degree view, then OpenCV's HOG people detector on the view shrunk by `scale`.
  const Lens lens = Lens::paper();
  const View view;
  const cv::Mat raw = synthetic_paper_capture();
  const Preprocessor preprocess =
      make_preprocessor(lens, view, BayerPattern::BGGR, DemosaicMethod::Bilinear, PreprocessPath::Fused);
  const Detector detector = hog_people_detector(scale);
  const FrameSource source = [&](std::size_t i) { return i < frames ? std::optional<cv::Mat>(raw) : std::nullopt; };
  PipelineConfig config;
  config.max_frames = frames;
  config.detection_workers = workers;
  config.policy = QueuePolicy::Block;  // every frame is processed: both sides do the same work

  ThreadingGuard guard;
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  // One warm-up frame (HOG's first call allocates its buffers and builds OpenCV's pool).
  detector(preprocess(raw));

  // The comparison runs with ONE OpenCV (and OpenMP) thread per call on both sides. HOG's detectMultiScale and our
  // fused kernel use cv::parallel_for_: with OpenCV's default pool the "sequential" baseline would already spread
  // each frame over every core, and the pipeline's workers would then compete for the same cores, so the ratio
  // would measure OpenCV's pool against our threads rather than the pipeline against its stages run in sequence.
  // With one thread per call both sides run exactly the same per-frame code; the pipeline's parallelism is its own.
  // The default-threading baseline is printed as well (below), so nobody reads the ratio as a speed-up over it.
  // Rounds alternate the order (sequential first, then concurrent first, ...) so that a neighbour's load on a
  // shared machine falls on both sides alike; process CPU time shows how much of the cores each side really got.
  set_vision_threads(1);
  Sequential seq;
  Concurrent conc;
  // --power: each side's rounds are phases of the trace, for the energy per frame of each.
  const auto power = start_power(args, out, false);
  const auto sequential = [&](int round) {
    if (power) power->begin_phase("sequential round " + std::to_string(round + 1));
    seq.add(run_sequential(raw, frames, preprocess, detector, cancel));
    if (power) power->end_phase();
  };
  const auto concurrent = [&](int round) {
    if (power) power->begin_phase("concurrent round " + std::to_string(round + 1));
    conc.add(timed_pipeline(source, preprocess, detector, config, cancel));
    if (power) power->end_phase();
  };
  int done_rounds = 0;
  for (int round = 0; round < rounds && !cancel.cancelled(); ++round, ++done_rounds) {
    if (round % 2 == 0) {
      sequential(round);
      concurrent(round);
    } else {
      concurrent(round);
      sequential(round);
    }
  }
  std::optional<PowerTrace> trace;
  if (power) trace = power->finish("bench pipeline");
  // For reference: OpenCV's default threading (its pool on every core), stages in sequence and pipelined, one
  // round each.
  set_vision_threads(std::max(guard.opencv(), 1));
  cv::setNumThreads(guard.opencv());
  const int default_threads = cv::getNumThreads();
  Sequential seq_default;
  Concurrent conc_default;
  seq_default.add(run_sequential(raw, frames, preprocess, detector, cancel));
  conc_default.add(timed_pipeline(source, preprocess, detector, config, cancel));
  if (cancel.cancelled()) {
    out << "bench pipeline: cancelled\n";
    return 1;
  }

  const double load = one_minute_load();
  char line[512];
  std::snprintf(line, sizeof line,
                "synthetic capture: %dx%d BGGR 8-bit, paper lens (195 deg equidistant) -> %dx%d 150 deg view; fused "
                "demosaic + reprojection; HOG people detector at scale %.2f (%dx%d)\n"
                "%d rounds of %zu frames per side, alternating which side goes first; %u hardware threads; %zu "
                "detection workers; queues of %zu frames (block); 1-min load average at the end: %.2f\n"
                "comparison with 1 OpenCV/OpenMP thread per call on both sides (cv::setNumThreads(1); restored to %d "
                "afterwards)\n\n",
                lens.width, lens.height, view.width, view.height, scale, cvRound(view.width * scale),
                cvRound(view.height * scale), rounds, frames, cores, workers, config.queue_capacity, load,
                guard.opencv());
  out << line;

  const double seq_fps = seq.fps(), conc_fps = conc.fps();
  std::vector<double> seq_total(seq.pre_ms.size());
  for (std::size_t i = 0; i < seq_total.size(); ++i) seq_total[i] = seq.pre_ms[i] + seq.detect_ms[i];
  out << "sequential (one thread, preprocessing then detection for each frame):\n";
  out << "  preprocessing  " << stat(seq.pre_ms) << '\n';
  out << "  detection      " << stat(seq.detect_ms) << '\n';
  out << "  per frame      " << stat(seq_total) << '\n';
  std::snprintf(
      line, sizeof line,
      "  throughput     %9.2f fps (%zu frames in %.3f s; %.2f cores busy on average, %.1f ms CPU per frame)\n", seq_fps,
      seq.pre_ms.size(), seq.wall_s, seq.wall_s > 0 ? seq.cpu_s / seq.wall_s : 0,
      seq.pre_ms.empty() ? 0 : 1e3 * seq.cpu_s / static_cast<double>(seq.pre_ms.size()));
  out << line;

  std::snprintf(line, sizeof line, "concurrent pipeline (capture, preprocessing, %zu detection workers):\n", workers);
  out << line;
  out << "  preprocessing  " << stat(conc.pre_ms) << '\n';
  out << "  detection      " << stat(conc.detect_ms) << '\n';
  out << "  end-to-end     " << stat(conc.e2e_ms) << '\n';
  std::snprintf(
      line, sizeof line,
      "  throughput     %9.2f fps (%zu frames in %.3f s; %.2f cores busy on average, %.1f ms CPU per frame)\n",
      conc_fps, conc.processed, conc.wall_s, conc.wall_s > 0 ? conc.cpu_s / conc.wall_s : 0,
      conc.processed == 0 ? 0 : 1e3 * conc.cpu_s / static_cast<double>(conc.processed));
  out << line;

  // Bound: the pipeline can go no faster than its slowest stage (preprocessing on one thread, detection on W) and
  // than the cores allow for the work of a frame, both taken from the sequential run's stage means.
  const double t_pre = summarize(seq.pre_ms).mean, t_det = summarize(seq.detect_ms).mean;
  const double bound_fps =
      std::min({1e3 / t_pre, 1e3 * static_cast<double>(workers) / t_det, 1e3 * cores / (t_pre + t_det)});
  const double ratio = seq_fps > 0 ? conc_fps / seq_fps : 0;
  std::snprintf(line, sizeof line,
                "\nconcurrent / sequential = %.2fx (target >= 1.6x: %s)\n"
                "theoretical bound: %.2f fps = %.2fx of sequential (min of 1 / preprocessing mean, %zu / detection "
                "mean, %u cores / per-frame work; sequential means); reached %.0f%% of it\n",
                ratio, ratio >= 1.6 ? "met" : "not met in this run", bound_fps, bound_fps * (t_pre + t_det) / 1e3,
                workers, cores, 100 * conc_fps / bound_fps);
  out << line;

  std::snprintf(line, sizeof line,
                "\nfor reference, OpenCV's default threading (%d threads per call; one run of %zu frames each):\n"
                "  sequential     %9.2f fps (detection %s)\n"
                "  concurrent     %9.2f fps (detection %s)\n"
                "  concurrent (1 thread per call) / sequential (default threading) = %.2fx; "
                "concurrent / sequential, both default threading = %.2fx\n",
                default_threads, frames, seq_default.fps(), stat(seq_default.detect_ms).c_str(), conc_default.fps(),
                stat(conc_default.detect_ms).c_str(), seq_default.fps() > 0 ? conc_fps / seq_default.fps() : 0,
                seq_default.fps() > 0 ? conc_default.fps() / seq_default.fps() : 0);
  out << line;
  if (trace) {
    const std::size_t n = frames * static_cast<std::size_t>(done_rounds);
    out << '\n';
    print_energy_per_item(out, *trace, {{"sequential", n}, {"concurrent", n}}, "frame");
  }
  return 0;
}

}  // namespace bs::cli
