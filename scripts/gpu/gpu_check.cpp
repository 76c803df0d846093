// SPDX-License-Identifier: GPL-3.0-or-later
// gpu-check: BenchScope's CUDA kernels on this machine's GPU, with nothing but the CUDA runtime (no Qt, OpenCV,
// SQLite or JSON library), so a lab can trust BenchScope's CUDA numbers on its Jetson or desktop GPU. Built and run
// by scripts/gpu-check; docs/gpu-check.md explains every section.
//   gpu-check all    correctness (closed form, fused kernel byte for byte), then ceilings and performance
//   gpu-check small  the correctness checks on small sizes only (what compute-sanitizer runs)
// Exit status: 0 every value right; 1 a wrong value (or a CUDA error); 2 no usable GPU; 64 bad usage.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "kernels/cuda/ceilings_cuda.h"
#include "kernels/cuda/rotation_cuda.h"
#include "kernels/rotation/rotation.h"
#include "vision/cuda/fused_cuda.h"
#include "vision/reproject/fused_pixel.h"

#if GPU_CHECK_GPUREF
// ../shared/tools/gpuref/ceilings.cu, an independent measuring stick linked beside this driver when present.
double fma_ceiling_gflops(int sms);
double rot_ceiling_gflops(int sms);
#endif

namespace {

using bs::kernels::RotationParams;

int failures = 0;

void verdict(bool ok, const std::string& what) {
  std::printf("  [%s] %s\n", ok ? "ok" : "WRONG", what.c_str());
  if (!ok) ++failures;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n == 0 ? 0 : n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

struct Spread {
  double median, mean, sd;
  std::size_t n;
};

Spread spread(const std::vector<double>& v) {
  double mean = 0, sq = 0;
  for (double x : v) mean += x;
  mean /= static_cast<double>(v.size());
  for (double x : v) sq += (x - mean) * (x - mean);
  return {median(v), mean, v.size() > 1 ? std::sqrt(sq / static_cast<double>(v.size() - 1)) : 0.0, v.size()};
}

// ---- the rotation kernel against the closed form D (cos 2N + sin 2N) ----

void check_rotation(int device, bool small) {
  std::printf("\n== rotation kernel: every output against the closed form D (cos 2N + sin 2N)\n");
  const std::vector<std::int64_t> workers =
      small ? std::vector<std::int64_t>{1, 7, 33} : std::vector<std::int64_t>{1, 7, 33, 1000, 4099, 100000};
  const std::vector<std::int64_t> steps =
      small ? std::vector<std::int64_t>{1, 5} : std::vector<std::int64_t>{1, 3, 40000, 40001};
  bs::CancelToken never;
  int right = 0, total = 0;
  for (bool paper : {true, false})
    for (int dims : {1, 2, 4}) {
      int right_here = 0, total_here = 0;
      std::string first_wrong;
      for (std::int64_t w : workers)
        for (std::int64_t n : steps) {
          const RotationParams p{dims, n};
          std::vector<float> out;
          bs::kernels::cuda::run_point(device, dims, n, w, paper, out, never);
          const std::int64_t bad = bs::kernels::first_wrong_output(out, p);
          ++total_here;
          if (bad < 0 && static_cast<std::int64_t>(out.size()) == w) {
            ++right_here;
          } else if (first_wrong.empty()) {
            char text[200];
            std::snprintf(text, sizeof text, "; first wrong: W = %lld, N = %lld, output %lld = %.6f, expected %.6f",
                          static_cast<long long>(w), static_cast<long long>(n), static_cast<long long>(bad),
                          bad >= 0 ? out[static_cast<std::size_t>(bad)] : 0.0f, bs::kernels::closed_form_output(p));
            first_wrong = text;
          }
        }
      right += right_here, total += total_here;
      verdict(right_here == total_here, std::string(paper ? "paper" : "float4x4 (throughput)") +
                                            ", D = " + std::to_string(dims) + ": " + std::to_string(right_here) +
                                            " of " + std::to_string(total_here) + " (W, N) cases right" + first_wrong);
    }
  std::printf("  closed form: %d of %d variant/D/W/N cases right\n", right, total);
}

// ---- the fused demosaic + reprojection kernel against the host reference ----

// A lookup table as a lens would give: a rotation, a zoom and a barrel distortion of the source, positions outside
// marked -1 (no source), plus every 97th entry marked -1 so the fill path runs in the middle of the image too.
std::vector<float> make_map(int ow, int oh, int sw, int sh) {
  std::vector<float> map(2 * static_cast<std::size_t>(ow) * oh);
  const double cx = 0.5 * (sw - 1), cy = 0.5 * (sh - 1), ocx = 0.5 * (ow - 1), ocy = 0.5 * (oh - 1);
  const double zoom = 1.1 * std::max(static_cast<double>(sw) / ow, static_cast<double>(sh) / oh);
  const double a = 0.05, ca = std::cos(a), sa = std::sin(a), rmax = std::hypot(ocx, ocy) + 1;
  for (int v = 0; v < oh; ++v)
    for (int u = 0; u < ow; ++u) {
      const double dx = u - ocx, dy = v - ocy, r = std::hypot(dx, dy) / rmax, k = zoom * (1 - 0.15 * r * r);
      double sx = cx + k * (ca * dx - sa * dy), sy = cy + k * (sa * dx + ca * dy);
      const std::size_t i = static_cast<std::size_t>(v) * ow + u;
      if (sx < 0 || sy < 0 || sx > sw - 1 || sy > sh - 1 || i % 97 == 0) sx = sy = -1;
      map[2 * i] = static_cast<float>(sx);
      map[2 * i + 1] = static_cast<float>(sy);
    }
  return map;
}

std::vector<std::uint8_t> make_mosaic(int sw, int sh, unsigned seed) {
  std::vector<std::uint8_t> m(static_cast<std::size_t>(sw) * sh);
  unsigned x = seed;
  for (std::size_t i = 0; i < m.size(); ++i) {
    x = x * 1664525u + 1013904223u;
    const int row = static_cast<int>(i / sw), col = static_cast<int>(i % sw);
    m[i] = static_cast<std::uint8_t>((row * 3 + col * 5 + (x >> 27)) & 255);  // gradients plus noise
  }
  return m;
}

struct FusedCase {
  int sw, sh, ow, oh;
  int layout[4];
};

void check_fused(bool small) {
  std::printf("\n== fused demosaic + reprojection: the CUDA kernel against the host reference, byte for byte\n");
  std::vector<FusedCase> cases = {{17, 13, 31, 29, {2, 1, 1, 0}}, {64, 48, 63, 47, {0, 1, 1, 2}}};
  if (!small) {
    cases.push_back({1280, 1024, 1280, 1024, {2, 1, 1, 0}});
    cases.push_back({641, 479, 333, 251, {1, 2, 0, 1}});
    cases.push_back({1001, 999, 1283, 721, {1, 0, 2, 1}});
    cases.push_back({3840, 2160, 3840, 2160, {0, 1, 1, 2}});
  }
  const std::uint8_t fill[3] = {7, 11, 13};
  for (const FusedCase& c : cases) {
    const std::vector<float> map = make_map(c.ow, c.oh, c.sw, c.sh);
    const std::vector<std::uint8_t> mosaic = make_mosaic(c.sw, c.sh, static_cast<unsigned>(c.sw * 31 + c.oh));
    bs::vision::cuda::FusedCuda gpu(map.data(), c.ow, c.oh, c.sw, c.sh, c.layout, fill);
    std::vector<std::uint8_t> out(3 * static_cast<std::size_t>(c.ow) * c.oh, 0xA5), ref(out.size());
    gpu.run(mosaic.data(), static_cast<std::size_t>(c.sw), out.data());
    bs::vision::fused_pixel::Mosaic m{mosaic.data(), c.sw, c.sh, c.sw, {}};
    std::memcpy(m.layout, c.layout, sizeof m.layout);
    for (std::size_t i = 0; i < static_cast<std::size_t>(c.ow) * c.oh; ++i)
      bs::vision::fused_pixel::sample(m, map[2 * i], map[2 * i + 1], fill, &ref[3 * i]);
    std::size_t differ = 0, first = 0;
    for (std::size_t i = 0; i < out.size(); ++i)
      if (out[i] != ref[i] && differ++ == 0) first = i;
    char text[200];
    std::snprintf(text, sizeof text, "%dx%d mosaic -> %dx%d BGR: %zu of %zu bytes differ%s", c.sw, c.sh, c.ow, c.oh,
                  differ, out.size(), differ ? (", first at byte " + std::to_string(first)).c_str() : "");
    verdict(differ == 0, text);
  }
}

// ---- performance against ceilings measured in this process ----

double rotation_gflops(int device, bool paper, std::int64_t workers, int runs, std::vector<double>& all) {
  const RotationParams p{4, 40000};
  bs::CancelToken never;
  std::vector<float> out;
  bs::kernels::cuda::run_point(device, 4, p.iterations, workers, paper, out, never);  // warm-up
  for (int r = 0; r < runs; ++r) {
    const double s = bs::kernels::cuda::run_point(device, 4, p.iterations, workers, paper, out, never);
    if (bs::kernels::first_wrong_output(out, p) >= 0) {
      verdict(false, std::string(paper ? "paper" : "float4x4") + " at W = " + std::to_string(workers) +
                         ": output differs from the closed form");
      return 0;
    }
    all.push_back(6.0 * 4 * static_cast<double>(p.iterations) * static_cast<double>(workers) / s / 1e9);
  }
  return median(all);
}

void performance(int device, const bs::kernels::cuda::DeviceInfo& info) {
  std::printf("\n== ceilings measured now (BenchScope's CUDA micro-kernels, core/kernels/cuda/ceilings_cuda.cu)\n");
  bs::kernels::cuda::CeilingKernels meter(device);
  std::vector<double> fma, mix, copy;
  for (int r = 0; r < 5; ++r) {  // alternating, as BenchScope does
    fma.push_back(meter.fma().rate() / 1e9);
    mix.push_back(meter.rotation_mix().rate() / 1e9);
    copy.push_back(meter.copy().rate() / 1e9);
  }
  verdict(true, "every ceiling's work checked (FMA accumulators exact, rotation-mix angles and norms, copy target)");
  const double lanes_peak = info.multiprocessors * static_cast<double>(info.fp32_lanes_per_sm) * info.clock_khz * 1e3;
  const Spread f = spread(fma), m = spread(mix), c = spread(copy);
  std::printf(
      "  FMA:          %9.1f GFLOPS median (%.1f +- %.1f, n = %zu) = %.1f %% of the FP32 peak %.1f GFLOPS "
      "(%d SMs x %d lanes x 2 x %.0f MHz)\n     how: %s\n",
      f.median, f.mean, f.sd, f.n, 100 * f.median / (2 * lanes_peak / 1e9), 2 * lanes_peak / 1e9, info.multiprocessors,
      info.fp32_lanes_per_sm, info.clock_khz / 1e3, meter.fma_how().c_str());
  std::printf(
      "  rotation mix: %9.1f GFLOPS median (%.1f +- %.1f, n = %zu) = %.1f %% of BenchScope's model 6/4 x "
      "lanes x clock = %.1f GFLOPS\n     how: %s\n",
      m.median, m.mean, m.sd, m.n, 100 * m.median / (1.5 * lanes_peak / 1e9), 1.5 * lanes_peak / 1e9,
      meter.mix_how().c_str());
  std::printf("  copy:         %9.1f GB/s median (%.1f +- %.1f, n = %zu)\n     how: %s\n", c.median, c.mean, c.sd, c.n,
              meter.copy_how().c_str());
#if GPU_CHECK_GPUREF
  const double ref_fma = fma_ceiling_gflops(info.multiprocessors), ref_mix = rot_ceiling_gflops(info.multiprocessors);
  std::printf(
      "  independent stick (shared/tools/gpuref): FMA %.1f GFLOPS, rotation mix %.1f GFLOPS; BenchScope's "
      "are %.1f %% and %.1f %% of these\n",
      ref_fma, ref_mix, 100 * f.median / ref_fma, 100 * m.median / ref_mix);
#endif
  std::printf(
      "\n== rotation kernel GFLOPS (D = 4, N = 40,000, 5 runs after a warm-up, median) against the "
      "rotation-mix ceiling\n");
  const std::int64_t full = static_cast<std::int64_t>(info.multiprocessors) * 2048;  // workers filling every SM
  for (bool paper : {true, false})
    for (std::int64_t w : {full / 8, full, 4 * full}) {
      std::vector<double> all;
      const double g = rotation_gflops(device, paper, w, 5, all);
      const Spread s = spread(all);
      std::printf("  %-9s W = %8lld: %9.1f GFLOPS (%.1f +- %.1f, n = %zu) = %5.1f %% of the rotation-mix ceiling%s\n",
                  paper ? "paper" : "float4x4", static_cast<long long>(w), g, s.mean, s.sd, s.n, 100 * g / m.median,
                  w == 4 * full ? (g >= 0.95 * m.median ? "  (>= 95 %: MET)" : "  (>= 95 %: NOT MET)") : "");
    }

  std::printf("\n== fused kernel time (median of 20) with and without transfers, bandwidth against the copy ceiling\n");
  for (const FusedCase& fc :
       {FusedCase{1280, 1024, 1280, 1024, {2, 1, 1, 0}}, FusedCase{3840, 2160, 3840, 2160, {2, 1, 1, 0}}}) {
    const std::vector<float> map = make_map(fc.ow, fc.oh, fc.sw, fc.sh);
    const std::vector<std::uint8_t> mosaic = make_mosaic(fc.sw, fc.sh, 5);
    const std::uint8_t fill[3] = {0, 0, 0};
    bs::vision::cuda::FusedCuda gpu(map.data(), fc.ow, fc.oh, fc.sw, fc.sh, fc.layout, fill);
    std::vector<std::uint8_t> out(3 * static_cast<std::size_t>(fc.ow) * fc.oh);
    gpu.run(mosaic.data(), static_cast<std::size_t>(fc.sw), out.data());  // warm-up
    std::vector<double> whole, up, down, kernel;
    for (int r = 0; r < 20; ++r) {
      using clock = std::chrono::steady_clock;
      const auto t0 = clock::now();
      gpu.upload(mosaic.data(), static_cast<std::size_t>(fc.sw));
      const auto t1 = clock::now();
      gpu.compute();
      const auto t2 = clock::now();
      gpu.download(out.data());
      const auto t3 = clock::now();
      whole.push_back(std::chrono::duration<double>(t3 - t0).count() * 1e3);
      up.push_back(std::chrono::duration<double>(t1 - t0).count() * 1e3);
      down.push_back(std::chrono::duration<double>(t3 - t2).count() * 1e3);
      kernel.push_back(gpu.kernel_seconds(10) * 1e3);
    }
    const double k = median(kernel), bw = gpu.kernel_bytes() / (k * 1e-3) / 1e9;
    std::printf(
        "  %dx%d: with transfers %.3f ms (upload %.3f, download %.3f); kernel alone %.3f ms (CUDA events); "
        "%.1f GB/s at least (%.1f MB per frame) = %.1f %% of the copy ceiling\n",
        fc.ow, fc.oh, median(whole), median(up), median(down), k, bw, gpu.kernel_bytes() / 1e6, 100 * bw / c.median);
  }
}

}  // namespace

int main(int argc, char** argv) {
  const std::string mode = argc > 1 ? argv[1] : "all";
  if (mode != "all" && mode != "small") {
    std::fprintf(stderr, "usage: gpu-check [all|small]\n");
    return 64;
  }
  std::string why;
  const auto devices = bs::kernels::cuda::devices(&why);
  if (devices.empty()) {
    std::printf("gpu-check: no usable CUDA GPU here (%s); nothing was checked.\n", why.c_str());
    return 2;
  }
  const auto& d = devices.front();
  std::printf("device 0: %s, compute capability %d.%d, %d SMs x %d FP32 lanes, %d MHz\n", d.name.c_str(), d.cc_major,
              d.cc_minor, d.multiprocessors, d.fp32_lanes_per_sm, d.clock_khz / 1000);
  try {
    check_rotation(d.index, mode == "small");
    check_fused(mode == "small");
    if (mode == "all") performance(d.index, d);
  } catch (const std::exception& e) {
    std::printf("  [WRONG] %s\n", e.what());
    ++failures;
  }
  std::printf("\ngpu-check %s: %s\n", mode.c_str(),
              failures ? (std::to_string(failures) + " check(s) WRONG").c_str() : "every value right");
  return failures ? 1 : 0;
}
