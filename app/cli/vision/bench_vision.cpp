// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/bench_vision.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <functional>
#include <memory>
#include <ostream>

#include <opencv2/imgproc.hpp>

#include "analysis/power/power.h"
#include "analysis/stats/stats.h"
#include "commands/bench_vision_grammar.h"
#include "common/args.h"
#include "common/bench_host.h"
#include "power/power_args.h"
#include "vision/bench_demosaic.h"
#include "vision/lens/lens.h"
#include "vision/pipeline/threads.h"
#include "vision/reproject/cuda_preprocess.h"
#include "vision/reproject/fused.h"

namespace bs::cli {
namespace {

struct Method {
  const char* name;
  std::function<void()> work;
  std::vector<double> ms{};
};

}  // namespace

int bench_vision(const std::vector<std::string>& arguments, std::ostream& out) {
  const commands::BenchVisionSettings args = commands::bench_vision_from_words(arguments);
  const int frames = args.frames;
  if (args.threads) vision::set_vision_threads(*args.threads);
  using namespace bs::vision;
  // The paper's setup: 1280x1024 BGGR from a 195 degree equidistant lens -> 1280x1024 rectilinear, 150 degrees.
  // The scene is smoothed noise: every kernel here does the same work whatever the pixel values are.
  const Lens lens = Lens::paper();
  const View view;
  cv::Mat scene(lens.height, lens.width, CV_8UC3);
  cv::randu(scene, cv::Scalar::all(0), cv::Scalar::all(255));
  cv::GaussianBlur(scene, scene, {0, 0}, 3);
  const cv::Mat raw = mosaic(scene, BayerPattern::BGGR);
  const ReprojectionLut lut(lens, view);
  cv::Mat map16, map_fraction;
  cv::convertMaps(lut.map(), cv::noArray(), map16, map_fraction, CV_16SC2);
  const FusedTable fused(lut.map(), raw.size(), BayerPattern::BGGR);
  const cv::Mat rgb_in = demosaic(raw, BayerPattern::BGGR, DemosaicMethod::OpenCvBilinear);
  cv::Mat rgb, view_img;

  // OpenCV calls a BGGR sensor "BayerRG" (see bayer.cpp); the speed is the same for every pattern.
  std::vector<Method> methods;
  methods.push_back(
      {"OpenCV cvtColor BayerRG2BGR (bilinear demosaic)", [&] { cv::cvtColor(raw, rgb, cv::COLOR_BayerRG2BGR); }});
  methods.push_back({"OpenCV cvtColor + remap (CV_16SC2 map) [reference]", [&] {
                       cv::cvtColor(raw, rgb, cv::COLOR_BayerRG2BGR);
                       cv::remap(rgb, view_img, map16, map_fraction, cv::INTER_LINEAR);
                     }});
  methods.push_back({"BenchScope LUT reprojection of BGR (fixed-point, remap)", [&] { view_img = lut.apply(rgb_in); }});
  const std::string fused_name = "BenchScope fused demosaic+reprojection (" + std::string(fused.kernel_name()) + ")";
  methods.push_back({fused_name.c_str(), [&] { fused.run(raw, view_img); }});
  const std::size_t fused_index = methods.size() - 1;
  // The CUDA kernel, timed as the pipeline uses it (`pipeline --backend cuda`: mosaic upload, kernel, BGR download,
  // blocking), and the kernel alone on a mosaic uploaded once (launch and synchronisation included).
  std::string cuda_device;
  const std::string cuda_missing = cuda_preprocessing_unavailable(&cuda_device);
  Preprocessor cuda_fused;
  std::unique_ptr<CudaFusedSteps> cuda_steps;
  const std::string cuda_name = "CUDA fused, pipeline preprocessor (with copies)";
  const std::string cuda_kernel_name = "CUDA fused, kernel only (no copies)";
  if (cuda_missing.empty()) {
    cuda_fused = make_cuda_preprocessor(lens, view, BayerPattern::BGGR);
    methods.push_back({cuda_name.c_str(), [&] { view_img = cuda_fused(raw); }});
    cuda_steps = std::make_unique<CudaFusedSteps>(lens, view, BayerPattern::BGGR);
    cuda_steps->upload(raw);
    methods.push_back({cuda_kernel_name.c_str(), [&] { cuda_steps->compute(); }});
  }

  // Blocks of consecutive frames per method, not frame-by-frame interleaving: OpenCV's TBB pool and our OpenMP
  // team each spin for a while after their work, and interleaving would charge that spinning to the next method.
  // Four passes, in alternating order, still spread a busy neighbour on a shared machine over all methods.
  constexpr int kPasses = 4, kWarmUp = 2;
  // --power: each method's blocks are phases named after it, for its energy per frame (warm-up frames included).
  const auto power = start_power(args.power, out, false);
  for (int pass = 0; pass < kPasses; ++pass)
    for (std::size_t k = 0; k < methods.size(); ++k) {
      Method& m = methods[pass % 2 ? methods.size() - 1 - k : k];
      const int count = frames * (pass + 1) / kPasses - frames * pass / kPasses;
      if (power) power->begin_phase(m.name);
      struct EndPhase {
        sensors::PowerRecorder* r;
        ~EndPhase() {
          if (r) r->end_phase();
        }
      } end_phase{power.get()};
      for (int i = 0; i < kWarmUp + count; ++i) {
        const auto t0 = std::chrono::steady_clock::now();
        m.work();
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        if (i >= kWarmUp) m.ms.push_back(ms);
      }
    }

  char line[512];
  const double load = one_minute_load();
  std::snprintf(line, sizeof line,
                "1280x1024 BGGR 8-bit -> 1280x1024 BGR, 150 deg rectilinear from a 195 deg equidistant lens\n"
                "threads: %d in OpenCV's pool (OpenCV, our demosaic and fused path), %d OpenMP (building tables); n = "
                "%d frames per method, in %d blocks (each after %d warm-up frames) "
                "of alternating order; 1-min load average at the end: %.2f\n\n",
                opencv_threads(), vision_threads(), frames, kPasses, kWarmUp, load);
  out << line;
  const double reference = median(methods[1].ms);
  std::snprintf(line, sizeof line, "%-58s %10s  %18s  %s\n", "method", "median", "mean +- SD", "vs reference");
  out << line;
  for (const auto& m : methods) {
    const Summary s = summarize(m.ms);
    const double med = median(m.ms);
    std::snprintf(line, sizeof line, "%-58s %7.3f ms  %7.3f +- %5.3f ms  %5.2fx\n", m.name, med, s.mean, s.sd,
                  reference / med);
    out << line;
  }
  if (!cuda_missing.empty()) {
    out << "(CUDA fused path not measured: " << cuda_missing << ")\n";
  } else {
    // The transfers apart, and the kernel's device time (CUDA events), with the bytes it moves at the least.
    std::vector<double> up, down, kernel;
    cv::Mat bgr;
    for (int i = 0; i < std::max(frames, 20); ++i) {
      const auto t0 = std::chrono::steady_clock::now();
      cuda_steps->upload(raw);
      const auto t1 = std::chrono::steady_clock::now();
      cuda_steps->download(bgr);
      const auto t2 = std::chrono::steady_clock::now();
      up.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
      down.push_back(std::chrono::duration<double, std::milli>(t2 - t1).count());
      kernel.push_back(cuda_steps->kernel_seconds(10) * 1e3);
    }
    const double k = median(kernel);
    std::snprintf(line, sizeof line,
                  "CUDA on %s: upload %.3f ms, download %.3f ms, kernel %.3f ms by CUDA events (medians of %zu); "
                  "the kernel moves >= %.1f MB per frame: >= %.1f GB/s of device memory (`devices` shows the "
                  "device's copy ceiling)\n",
                  cuda_device.c_str(), median(up), median(down), k, kernel.size(), cuda_steps->kernel_bytes() / 1e6,
                  cuda_steps->kernel_bytes() / (k * 1e-3) / 1e9);
    out << line;
  }
  const double fused_ms = median(methods[fused_index].ms);
  const double speedup = reference / fused_ms;
  std::snprintf(line, sizeof line,
                "\nfused: %.2fx faster than OpenCV cvtColor + remap, median %.3f ms per frame "
                "(target: >= 2x and <= 2 ms: %s)\n",
                speedup, fused_ms, speedup >= 2 && fused_ms <= 2 ? "met" : "not met in this run");
  out << line;
  if (power) {
    const PowerTrace trace = power->finish("bench vision");
    std::vector<std::pair<std::string, std::size_t>> groups;
    for (const auto& m : methods) groups.emplace_back(m.name, static_cast<std::size_t>(frames + kPasses * kWarmUp));
    out << '\n';
    print_energy_per_item(out, trace, groups, "frame");
  }
  // BenchScope's own demosaics (the Frames tab, the triptych, figures, `pipeline --demosaic bilinear|mhc`).
  print_demosaic_bench(out, frames, opencv_threads());
  return 0;
}

}  // namespace bs::cli
