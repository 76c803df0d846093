// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/bench_demosaic.h"

#include <opencv2/core/utility.hpp>
#include <opencv2/imgproc.hpp>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "analysis/power/power.h"
#include "analysis/stats/stats.h"
#include "vision/demosaic/bayer.h"
#include "vision/demosaic/bayer_simd.h"

namespace bs::cli {
namespace {

struct Timed {
  std::function<void()> work;
  std::vector<double> ms{};
};

std::string load_average() {
  std::string one, five, fifteen;
  std::ifstream("/proc/loadavg") >> one >> five >> fifteen;
  return one.empty() ? "unavailable" : one + " " + five + " " + fifteen + " (1, 5, 15 min)";
}

// Blocks of `kBlock` frames per method, each after warm-up frames that are not counted, the methods' order
// reversed every pass: a neighbour's build on the shared machine then slows every method alike, and no method
// pays for the previous one's thread pool still spinning down.
void measure(std::vector<Timed>& methods, int frames) {
  constexpr int kBlock = 10, kWarmUp = 2;
  for (int pass = 0, done = 0; done < frames; ++pass, done += kBlock) {
    const int count = std::min(kBlock, frames - done);
    for (std::size_t k = 0; k < methods.size(); ++k) {
      Timed& m = methods[pass % 2 ? methods.size() - 1 - k : k];
      for (int i = 0; i < kWarmUp + count; ++i) {
        const auto t0 = std::chrono::steady_clock::now();
        m.work();
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        if (i >= kWarmUp) m.ms.push_back(ms);
      }
    }
  }
}

// OpenCV's thread pool as its build reports it ("pthreads", "TBB (ver ...)", "OpenMP"): 4.6 has no call for it.
std::string opencv_parallel_framework() {
  const std::string info = cv::getBuildInformation();
  const std::string key = "Parallel framework:";
  const auto at = info.find(key);
  if (at == std::string::npos) return "unknown";
  const auto begin = info.find_first_not_of(' ', at + key.size());
  return info.substr(begin, info.find('\n', begin) - begin);
}

std::string figure(const std::vector<double>& ms) {
  const Summary s = summarize(ms);
  char buf[112];
  std::snprintf(buf, sizeof buf, "%.3f +- %.3f (n %zu), median %.3f, min %.3f", s.mean, s.sd, s.n, median(ms), s.min);
  return buf;
}

}  // namespace

void print_demosaic_bench(std::ostream& out, int frames, int all_threads) {
  using namespace bs::vision;
  // The same smoothed-noise scene as the rest of bench vision; the 16-bit mosaic is it scaled to the full range.
  cv::Mat scene8(1024, 1280, CV_8UC3), scene16;
  cv::randu(scene8, cv::Scalar::all(0), cv::Scalar::all(255));
  cv::GaussianBlur(scene8, scene8, {0, 0}, 3);
  scene8.convertTo(scene16, CV_16UC3, 257);
  const cv::Mat raw8 = mosaic(scene8, BayerPattern::BGGR), raw16 = mosaic(scene16, BayerPattern::BGGR);
  cv::Mat dst_ocv, dst_ours;

  // Which fast path this build has: Highway's best instruction set here, or the portable scalar one.
  const std::string engine = demosaic_simd_uses_highway()
                                 ? "Highway " + std::string(demosaic_simd_target()) + " (run-time choice;"
                                 : std::string("portable C++ (built without Highway;");
  char line[1024];
  std::snprintf(
      line, sizeof line,
      "\nDemosaic, 1280x1024 BGGR mosaic -> BGR. BenchScope: %s equal to the scalar "
      "reference pixel for pixel, tests compare), row stripes on OpenCV's pool; OpenCV %s: cvtColor "
      "COLOR_BayerRG2BGR (bilinear), its pool = %s with %d threads here.\n"
      "ms per frame: mean +- SD (n frames), median and minimum, in blocks of 10 (after 2 uncounted) in alternating "
      "order. ratio = BenchScope / OpenCV of the same threads and depth, of the medians (the targets are "
      "judged on it: a shared machine's preemptions inflate means and SDs) and, in brackets, of the means.\n",
      engine.c_str(), CV_VERSION, opencv_parallel_framework().c_str(), all_threads);
  out << line << "load average before: " << load_average() << "\n\n";
  std::snprintf(line, sizeof line, "%-7s %-6s %-17s %-52s %-52s %-16s %s\n", "threads", "depth", "method",
                "BenchScope, ms/frame", "OpenCV bilinear, ms/frame", "ratio", "target");
  out << line;
  for (const int threads : {1, all_threads}) {
    cv::setNumThreads(threads);
    for (const int depth : {8, 16}) {
      const cv::Mat& raw = depth == 8 ? raw8 : raw16;
      std::vector<Timed> methods;
      methods.push_back({[&] { cv::cvtColor(raw, dst_ocv, cv::COLOR_BayerRG2BGR); }});
      // Into a kept buffer, as cvtColor writes into dst_ocv: neither pays for allocating and faulting in 4-8 MB.
      methods.push_back({[&] { demosaic(raw, BayerPattern::BGGR, DemosaicMethod::Bilinear, dst_ours); }});
      methods.push_back({[&] { demosaic(raw, BayerPattern::BGGR, DemosaicMethod::MalvarHeCutler, dst_ours); }});
      measure(methods, frames);
      for (int k = 1; k <= 2; ++k) {
        const double ratio = median(methods[k].ms) / median(methods[0].ms);
        const double ratio_of_means = summarize(methods[k].ms).mean / summarize(methods[0].ms).mean;
        const double limit = k == 1 ? 1.0 : 2.0;
        char ratios[40], target[48];
        std::snprintf(ratios, sizeof ratios, "%.2fx (%.2fx)", ratio, ratio_of_means);
        std::snprintf(target, sizeof target, "<= %.0fx: %s", limit, ratio <= limit ? "met" : "not met");
        std::snprintf(line, sizeof line, "%-7d %-6s %-17s %-52s %-52s %-16s %s\n", threads,
                      depth == 8 ? "8-bit" : "16-bit", k == 1 ? "bilinear" : "Malvar-He-Cutler",
                      figure(methods[k].ms).c_str(), figure(methods[0].ms).c_str(), ratios, target);
        out << line;
      }
    }
  }
  cv::setNumThreads(all_threads);
  out << "load average after: " << load_average() << '\n';
}

}  // namespace bs::cli
