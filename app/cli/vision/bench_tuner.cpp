// SPDX-License-Identifier: GPL-3.0-or-later
// Live tuning needs a new 1280x1024 reprojected frame per parameter change (target: median under 20 ms). Each
// iteration changes the view (yaw steps of 0.1 degree, as a slider drag does), rebuilds the map and remaps the
// fisheye frame; the coarse-grid map (fast_map.h) and the exact map are timed in the same run, interleaved in blocks.
#include "vision/bench_tuner.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <functional>
#include <ostream>

#include <opencv2/imgproc.hpp>

#include "analysis/power/power.h"
#include "analysis/stats/stats.h"
#include "common/args.h"
#include "common/bench_host.h"
#include "vision/lens/lens.h"
#include "vision/pipeline/threads.h"
#include "vision/reproject/fast_map.h"

namespace bs::cli {
namespace {

struct Method {
  std::string name;
  std::function<void(const vision::View&)> work;
  std::vector<double> ms{}, cpu_ms{};
};

}  // namespace

int bench_tuner(const std::vector<std::string>& arguments, std::ostream& out) {
  const ParsedArgs args = parse_args(arguments, {}, {"--frames", "--step"});
  const int frames = static_cast<int>(args.number("--frames", 60));
  if (frames < 1 || frames > 100000) throw UsageError("--frames must be between 1 and 100000");
  const int step = static_cast<int>(args.number("--step", 8));
  if (step < 2 || step > 64) throw UsageError("--step must be between 2 and 64");
  using namespace bs::vision;
  const Lens lens = Lens::paper();
  cv::Mat scene(lens.height, lens.width, CV_8UC3);
  cv::randu(scene, cv::Scalar::all(0), cv::Scalar::all(255));
  cv::GaussianBlur(scene, scene, {0, 0}, 3);
  cv::Mat view_img, map;
  std::vector<Method> methods;
  methods.push_back({"exact map build + remap [reference]", [&](const View& v) {
                       map = build_reprojection_map(lens, v);
                       view_img = reproject(scene, map);
                     }});
  // The coarse path reuses its map and output buffers across changes, as the tuner does (fast_map.h).
  cv::Mat coarse_map, coarse_img;
  methods.push_back({"coarse map (step " + std::to_string(step) + ") + remap", [&](const View& v) {
                       build_reprojection_map_coarse(lens, v, coarse_map, step);
                       cv::remap(scene, coarse_img, coarse_map, cv::noArray(), cv::INTER_LINEAR);
                     }});
  methods.push_back({"exact map build only", [&](const View& v) { map = build_reprojection_map(lens, v); }});
  methods.push_back(
      {"coarse map build only", [&](const View& v) { build_reprojection_map_coarse(lens, v, coarse_map, step); }});

  constexpr int kPasses = 4, kWarmUp = 2;
  int change = 0;
  for (int pass = 0; pass < kPasses; ++pass)
    for (std::size_t k = 0; k < methods.size(); ++k) {
      Method& m = methods[pass % 2 ? methods.size() - 1 - k : k];
      const int count = frames * (pass + 1) / kPasses - frames * pass / kPasses;
      for (int i = 0; i < kWarmUp + count; ++i) {
        View v;
        v.yaw_deg = 0.1 * (++change % 200);  // every frame is a new parameter set
        const double c0 = 1e3 * process_cpu_seconds();
        const auto t0 = std::chrono::steady_clock::now();
        m.work(v);
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        if (i >= kWarmUp) {
          m.ms.push_back(ms);
          m.cpu_ms.push_back(1e3 * process_cpu_seconds() - c0);
        }
      }
    }
  char line[320];
  const double load = one_minute_load();
  std::snprintf(line, sizeof line,
                "parameter change -> new 1280x1024 BGR frame, 150 deg rectilinear view of the paper's 195 deg lens\n"
                "%d OpenMP threads (map build), %d in OpenCV's pool (remap); n = %d changes per method in %d blocks of "
                "alternating order (each after %d warm-up); 1-min load average at the end: %.2f\n\n",
                vision_threads(), opencv_threads(), frames, kPasses, kWarmUp, load);
  out << line;
  out << "wall: steady_clock per change; CPU: process CPU time per change (all threads), what the work costs\n"
         "whatever else the shared machine runs (OpenMP teams spin-wait badly on oversubscribed cores)\n\n";
  std::snprintf(line, sizeof line, "%-40s %10s %10s  %20s  %12s  %s\n", "method", "median", "p95", "mean +- SD",
                "median CPU", "vs reference");
  out << line;
  const double reference = median(methods[0].ms);
  for (const auto& m : methods) {
    const Summary s = summarize(m.ms);
    const double med = median(m.ms);
    std::snprintf(line, sizeof line, "%-40s %7.2f ms %7.2f ms  %7.2f +- %5.2f ms  %9.2f ms  %5.2fx\n", m.name.c_str(),
                  med, percentile(m.ms, 95), s.mean, s.sd, median(m.cpu_ms), reference / med);
    out << line;
  }
  const double coarse = median(methods[1].ms);
  std::snprintf(
      line, sizeof line,
      "\ncoarse map + remap: median %.2f ms wall, %.2f ms CPU per parameter change (target < 20 ms wall: %s)\n", coarse,
      median(methods[1].cpu_ms), coarse < 20 ? "met" : "not met in this run");
  out << line;
  return 0;
}

}  // namespace bs::cli
