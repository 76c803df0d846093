// SPDX-License-Identifier: GPL-3.0-or-later
#include "bench_vision.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <ostream>

#include <opencv2/core/utility.hpp>
#include <opencv2/imgproc.hpp>

#include "args.h"
#include "vision/fused.h"
#include "vision/lens.h"

namespace bs::cli {
namespace {

double median_ms(int frames, const std::function<void()>& work) {
  work();  // warm-up: first-touch page faults, thread start-up
  std::vector<double> ms;
  for (int i = 0; i < frames; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    work();
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
  std::sort(ms.begin(), ms.end());
  return ms[ms.size() / 2];
}

}  // namespace

int bench_vision(const std::vector<std::string>& arguments, std::ostream& out) {
  const ParsedArgs args = parse_args(arguments, {}, {"--frames"});
  const int frames = static_cast<int>(args.number("--frames", 100));
  if (frames < 1 || frames > 100000) throw UsageError("--frames must be between 1 and 100000");
  using namespace bs::vision;
  // The paper's setup: 1280x1024 BGGR from a 195 degree equidistant lens -> 1280x1024 rectilinear, 150 degrees.
  const Lens lens = Lens::paper();
  const View view;
  cv::Mat scene(1024, 1280, CV_8UC3);
  cv::randu(scene, cv::Scalar::all(0), cv::Scalar::all(255));
  cv::GaussianBlur(scene, scene, {0, 0}, 3);
  const cv::Mat raw = mosaic(scene, BayerPattern::BGGR);
  const cv::Mat map = build_reprojection_map(lens, view);
  cv::Mat map16, map_frac;
  cv::convertMaps(map, cv::noArray(), map16, map_frac, CV_16SC2);
  const FusedTable fused(map, raw.size(), BayerPattern::BGGR);
  cv::Mat rgb, view_img;

  const double ocv_demosaic = median_ms(frames, [&] { cv::cvtColor(raw, rgb, cv::COLOR_BayerRG2BGR); });
  const double ocv_both = median_ms(frames, [&] {
    cv::cvtColor(raw, rgb, cv::COLOR_BayerRG2BGR);
    cv::remap(rgb, view_img, map16, map_frac, cv::INTER_LINEAR);
  });
  const double ours_mhc = median_ms(std::max(1, frames / 10), [&] { rgb = demosaic(raw, BayerPattern::BGGR, DemosaicMethod::MalvarHeCutler); });
  const double ours_two_pass = median_ms(frames, [&] {
    rgb = demosaic(raw, BayerPattern::BGGR, DemosaicMethod::Bilinear);
    cv::remap(rgb, view_img, map16, map_frac, cv::INTER_LINEAR);
  });
  const double ours_fused = median_ms(frames, [&] { fused.run(raw, view_img); });

  char line[256];
  std::snprintf(line, sizeof line, "1280x1024 BGGR 8-bit -> 1280x1024 RGB, 150 deg from 195 deg equidistant; %d threads; "
                "median of %d frames\n\n", cv::getNumThreads(), frames);
  out << line;
  auto row = [&](const char* what, double ms) {
    std::snprintf(line, sizeof line, "%-52s %8.2f ms  %5.2fx vs OpenCV demosaic+remap\n", what, ms, ocv_both / ms);
    out << line;
  };
  row("OpenCV cvtColor(BayerRG2BGR) [reference, demosaic only]", ocv_demosaic);
  row("OpenCV cvtColor + remap (CV_16SC2 map) [reference]", ocv_both);
  row("BenchScope Malvar-He-Cutler demosaic only (1/10 frames)", ours_mhc);
  row("BenchScope bilinear demosaic + OpenCV remap", ours_two_pass);
  row("BenchScope fused demosaic+reprojection", ours_fused);
  return 0;
}

}  // namespace bs::cli
