// SPDX-License-Identifier: GPL-3.0-or-later
#include "kernels/cuda/ceilings_cuda.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

namespace bs::kernels::cuda {
namespace {

void check(cudaError_t e, const char* what) {
  if (e != cudaSuccess) throw std::runtime_error(std::string("CUDA: ") + what + ": " + cudaGetErrorString(e));
}

constexpr int kBlock = 256;
constexpr int kFmaChains = 8;
constexpr float kFmaStep = 1.0f / 1024.0f;  // 2^-10: acc0 + n * 2^-10 is exact below 2^14 (24-bit significand)
constexpr std::int64_t kFmaMaxSteps = std::int64_t{1} << 23;
constexpr std::int64_t kMixMaxSteps = 2'000'000;  // keeps the angle check's tolerance (2e-7 rad per step) < 0.5 rad
constexpr int kCopyPasses = 10;

// acc = acc * a + b with a = 1 (a kernel argument, so the multiply stays): 2 flops per FFMA.
__global__ void fma_kernel(float* out, int steps, float a, float b) {
  const unsigned t = blockIdx.x * blockDim.x + threadIdx.x;
  float acc[kFmaChains];
#pragma unroll
  for (int k = 0; k < kFmaChains; ++k) acc[k] = static_cast<float>(k + (t & 1023u));
    // Unrolled so the loop's counter, compare and branch take 3 of ~131 issue slots, not 3 of 35.
#pragma unroll 16
  for (int n = 0; n < steps; ++n) {
#pragma unroll
    for (int k = 0; k < kFmaChains; ++k) acc[k] = fmaf(acc[k], a, b);
  }
#pragma unroll
  for (int k = 0; k < kFmaChains; ++k) out[static_cast<std::size_t>(t) * kFmaChains + k] = acc[k];
}

// The rotation kernel's instructions on P independent points per thread; point p of thread t starts at angle
// 1e-3 * (t * P + p) on the unit circle.
template <int P>
__global__ void mix_kernel(float* xs, float* ys, int steps, float c, float s) {
  const unsigned t = blockIdx.x * blockDim.x + threadIdx.x;
  float x[P], y[P];
#pragma unroll
  for (int p = 0; p < P; ++p) sincosf(1e-3f * static_cast<float>(t * P + p), &y[p], &x[p]);
#pragma unroll(64 / P)
  for (int n = 0; n < steps; ++n) {
#pragma unroll
    for (int p = 0; p < P; ++p) {
      const float u = s * y[p];
      y[p] = fmaf(s, x[p], c * y[p]);
      x[p] = fmaf(c, x[p], -u);
    }
  }
#pragma unroll
  for (int p = 0; p < P; ++p) {
    xs[static_cast<std::size_t>(t) * P + p] = x[p];
    ys[static_cast<std::size_t>(t) * P + p] = y[p];
  }
}

__global__ void fill_kernel(float4* a, std::size_t n) {
  for (std::size_t i = blockIdx.x * static_cast<std::size_t>(blockDim.x) + threadIdx.x; i < n;
       i += static_cast<std::size_t>(gridDim.x) * blockDim.x) {
    const float v = static_cast<float>(i % 65521u);
    a[i] = make_float4(v, v + 0.25f, v + 0.5f, v + 0.75f);
  }
}

__global__ void copy_kernel(float4* __restrict__ dst, const float4* __restrict__ src, std::size_t n) {
  for (std::size_t i = blockIdx.x * static_cast<std::size_t>(blockDim.x) + threadIdx.x; i < n;
       i += static_cast<std::size_t>(gridDim.x) * blockDim.x)
    dst[i] = src[i];
}

__global__ void compare_kernel(const float4* a, const float4* b, std::size_t n, unsigned long long* wrong) {
  unsigned long long mine = 0;
  for (std::size_t i = blockIdx.x * static_cast<std::size_t>(blockDim.x) + threadIdx.x; i < n;
       i += static_cast<std::size_t>(gridDim.x) * blockDim.x) {
    const float4 p = a[i], q = b[i];
    mine += (p.x != q.x) + (p.y != q.y) + (p.z != q.z) + (p.w != q.w);
  }
  if (mine) atomicAdd(wrong, mine);
}

// Resident blocks per SM for a kernel at kBlock threads: the grid is one full wave of them.
template <class K>
int blocks_per_sm(K kernel) {
  int n = 0;
  check(cudaOccupancyMaxActiveBlocksPerMultiprocessor(&n, kernel, kBlock, 0), "cudaOccupancyMaxActiveBlocks");
  return std::max(n, 1);
}

class Events {
 public:
  Events() {
    check(cudaEventCreate(&start_), "cudaEventCreate");
    check(cudaEventCreate(&stop_), "cudaEventCreate");
  }
  ~Events() {
    cudaEventDestroy(start_);
    cudaEventDestroy(stop_);
  }
  void start() { check(cudaEventRecord(start_), "cudaEventRecord"); }
  double stop() {
    check(cudaEventRecord(stop_), "cudaEventRecord");
    check(cudaEventSynchronize(stop_), "cudaEventSynchronize");
    float ms = 0;
    check(cudaEventElapsedTime(&ms, start_, stop_), "cudaEventElapsedTime");
    return ms * 1e-3;
  }

 private:
  cudaEvent_t start_{}, stop_{};
};

template <class T>
struct DeviceBuffer {
  T* p = nullptr;
  std::size_t n = 0;
  void allocate(std::size_t count, const char* what) {
    check(cudaMalloc(&p, count * sizeof(T)), what);
    n = count;
  }
  ~DeviceBuffer() { cudaFree(p); }
};

constexpr int kMixPoints[] = {4, 8, 16};

}  // namespace

struct CeilingKernels::Impl {
  int device = 0, sms = 0;
  std::string name;
  double target = 0.1;
  float c = 0, s = 0;  // cos(2), sin(2) as floats, the rotation kernel's constants
  int fma_blocks = 0, mix_blocks[3] = {};
  std::int64_t fma_steps = 0, mix_steps[3] = {};
  DeviceBuffer<float> fma_out, mix_x, mix_y;
  DeviceBuffer<float4> src, dst;
  DeviceBuffer<unsigned long long> wrong;
  int copy_blocks = 0;
  Events events;

  double launch_fma(std::int64_t steps) {
    events.start();
    fma_kernel<<<fma_blocks, kBlock>>>(fma_out.p, static_cast<int>(steps), 1.0f, kFmaStep);
    check(cudaGetLastError(), "fma_kernel launch");
    return events.stop();
  }
  double launch_mix(int which, std::int64_t steps) {
    const int n = static_cast<int>(steps);
    events.start();
    if (which == 0) mix_kernel<4><<<mix_blocks[0], kBlock>>>(mix_x.p, mix_y.p, n, c, s);
    if (which == 1) mix_kernel<8><<<mix_blocks[1], kBlock>>>(mix_x.p, mix_y.p, n, c, s);
    if (which == 2) mix_kernel<16><<<mix_blocks[2], kBlock>>>(mix_x.p, mix_y.p, n, c, s);
    check(cudaGetLastError(), "mix_kernel launch");
    return events.stop();
  }
  // Steps doubled from 1024 until a launch lasts >= 20 ms (or `cap`), then scaled to the target.
  template <class Launch>
  std::int64_t size_steps(Launch launch, std::int64_t cap) {
    for (std::int64_t steps = 1024;; steps *= 2) {
      const double t = launch(steps);
      if (t >= 0.02 || steps >= cap)
        return std::clamp<std::int64_t>(
            static_cast<std::int64_t>(static_cast<double>(steps) * target / std::max(t, 1e-9)), 1024, cap);
    }
  }
};

CeilingKernels::CeilingKernels(int device, double target_seconds, std::size_t copy_mib)
    : impl_(std::make_unique<Impl>()) {
  Impl& d = *impl_;
  d.device = device;
  d.target = target_seconds;
  check(cudaSetDevice(device), "cudaSetDevice");
  cudaDeviceProp prop{};
  check(cudaGetDeviceProperties(&prop, device), "cudaGetDeviceProperties");
  d.sms = prop.multiProcessorCount;
  d.name = prop.name;
  d.c = static_cast<float>(std::cos(2.0));
  d.s = static_cast<float>(std::sin(2.0));
  d.fma_blocks = d.sms * blocks_per_sm(fma_kernel);
  d.mix_blocks[0] = d.sms * blocks_per_sm(mix_kernel<4>);
  d.mix_blocks[1] = d.sms * blocks_per_sm(mix_kernel<8>);
  d.mix_blocks[2] = d.sms * blocks_per_sm(mix_kernel<16>);
  d.fma_out.allocate(static_cast<std::size_t>(d.fma_blocks) * kBlock * kFmaChains, "cudaMalloc(fma)");
  std::size_t mix_floats = 0;
  for (int i = 0; i < 3; ++i)
    mix_floats = std::max(mix_floats, static_cast<std::size_t>(d.mix_blocks[i]) * kBlock * kMixPoints[i]);
  d.mix_x.allocate(mix_floats, "cudaMalloc(mix)");
  d.mix_y.allocate(mix_floats, "cudaMalloc(mix)");
  std::size_t free_bytes = 0, total_bytes = 0;
  check(cudaMemGetInfo(&free_bytes, &total_bytes), "cudaMemGetInfo");
  std::size_t bytes = (copy_mib ? copy_mib : 256) << 20;
  if (copy_mib == 0) bytes = std::min(bytes, free_bytes / 8);  // a Jetson shares its memory with the CPU
  bytes = std::max<std::size_t>(bytes / sizeof(float4), 1024) * sizeof(float4);
  d.src.allocate(bytes / sizeof(float4), "cudaMalloc(copy source)");
  d.dst.allocate(bytes / sizeof(float4), "cudaMalloc(copy target)");
  d.wrong.allocate(1, "cudaMalloc(copy check)");
  d.copy_blocks = d.sms * blocks_per_sm(copy_kernel);
  fill_kernel<<<d.copy_blocks, kBlock>>>(d.src.p, d.src.n);
  check(cudaGetLastError(), "fill_kernel launch");
  check(cudaDeviceSynchronize(), "fill_kernel");
  // One untimed launch of each first: CUDA loads modules lazily, at a kernel's first launch, and the events of a
  // sizing probe would otherwise time the loading.
  d.launch_fma(1);
  for (int i = 0; i < 3; ++i) d.launch_mix(i, 1);
  d.fma_steps = d.size_steps([&](std::int64_t n) { return d.launch_fma(n); }, kFmaMaxSteps);
  for (int i = 0; i < 3; ++i) {
    // Each chain count gets a third of the target, so a repetition of the mix takes about `target_seconds`.
    const double keep = d.target;
    d.target = keep / 3;
    d.mix_steps[i] = d.size_steps([&](std::int64_t n) { return d.launch_mix(i, n); }, kMixMaxSteps);
    d.target = keep;
  }
}

CeilingKernels::~CeilingKernels() = default;

CeilingRun CeilingKernels::fma() {
  Impl& d = *impl_;
  const double seconds = d.launch_fma(d.fma_steps);
  std::vector<float> out(d.fma_out.n);
  check(cudaMemcpy(out.data(), d.fma_out.p, out.size() * sizeof(float), cudaMemcpyDeviceToHost), "cudaMemcpy(fma)");
  for (std::size_t i = 0; i < out.size(); ++i) {
    const std::size_t t = i / kFmaChains, k = i % kFmaChains;
    const double expected = static_cast<double>(k + (t & 1023u)) + static_cast<double>(d.fma_steps) * kFmaStep;
    if (static_cast<double>(out[i]) != expected)
      throw std::runtime_error("CUDA FMA ceiling: thread " + std::to_string(t) + " accumulator " + std::to_string(k) +
                               " is " + std::to_string(out[i]) + ", not " + std::to_string(expected) + " after " +
                               std::to_string(d.fma_steps) + " steps");
  }
  return {2.0 * kFmaChains * static_cast<double>(d.fma_steps) * static_cast<double>(out.size() / kFmaChains), seconds};
}

CeilingRun CeilingKernels::rotation_mix() {
  Impl& d = *impl_;
  CeilingRun best;
  const double phi = std::atan2(static_cast<double>(d.s), static_cast<double>(d.c));
  const double per_step_log_norm = std::log(static_cast<double>(d.c) * d.c + static_cast<double>(d.s) * d.s);
  for (int i = 0; i < 3; ++i) {
    const std::int64_t steps = d.mix_steps[i];
    const double seconds = d.launch_mix(i, steps);
    const std::size_t points = static_cast<std::size_t>(d.mix_blocks[i]) * kBlock * kMixPoints[i];
    std::vector<float> x(points), y(points);
    check(cudaMemcpy(x.data(), d.mix_x.p, points * sizeof(float), cudaMemcpyDeviceToHost), "cudaMemcpy(mix)");
    check(cudaMemcpy(y.data(), d.mix_y.p, points * sizeof(float), cudaMemcpyDeviceToHost), "cudaMemcpy(mix)");
    // The float matrix turns by phi = atan2(s, c) per step (not exactly 2 rad) and scales the norm by
    // sqrt(c^2 + s^2); rounding adds up to about 1.2e-7 rad per step.
    const double tolerance = 2e-7 * static_cast<double>(steps) + 1e-3;
    for (std::size_t j = 0; j < points; ++j) {
      const double start = static_cast<double>(1e-3f * static_cast<float>(j));  // as the kernel computes it
      double error = std::remainder(std::atan2(y[j], x[j]) - (start + phi * static_cast<double>(steps)), 2 * M_PI);
      const double log_norm = std::log(static_cast<double>(x[j]) * x[j] + static_cast<double>(y[j]) * y[j]);
      if (!(std::fabs(error) < tolerance) || !(std::fabs(log_norm - per_step_log_norm * steps) < 0.1))
        throw std::runtime_error("CUDA rotation-mix ceiling: point " + std::to_string(j) + " of the " +
                                 std::to_string(kMixPoints[i]) + "-point kernel is not where " + std::to_string(steps) +
                                 " steps put it (angle off by " + std::to_string(error) + " rad)");
    }
    const CeilingRun run{6.0 * static_cast<double>(points) * static_cast<double>(steps), seconds};
    if (run.rate() > best.rate()) best = run, last_mix_points_ = kMixPoints[i];
  }
  return best;
}

CeilingRun CeilingKernels::copy() {
  Impl& d = *impl_;
  check(cudaMemset(d.dst.p, 0, d.dst.n * sizeof(float4)), "cudaMemset(copy target)");
  check(cudaMemset(d.wrong.p, 0, sizeof(unsigned long long)), "cudaMemset(copy check)");
  check(cudaDeviceSynchronize(), "cudaMemset");
  d.events.start();
  for (int pass = 0; pass < kCopyPasses; ++pass) copy_kernel<<<d.copy_blocks, kBlock>>>(d.dst.p, d.src.p, d.src.n);
  check(cudaGetLastError(), "copy_kernel launch");
  const double seconds = d.events.stop();
  compare_kernel<<<d.copy_blocks, kBlock>>>(d.dst.p, d.src.p, d.src.n, d.wrong.p);
  check(cudaGetLastError(), "compare_kernel launch");
  unsigned long long wrong = 0;
  check(cudaMemcpy(&wrong, d.wrong.p, sizeof wrong, cudaMemcpyDeviceToHost), "cudaMemcpy(copy check)");
  if (wrong) throw std::runtime_error("CUDA copy ceiling: " + std::to_string(wrong) + " floats differ after the copy");
  return {2.0 * kCopyPasses * static_cast<double>(d.src.n * sizeof(float4)), seconds};
}

std::string CeilingKernels::fma_how() const {
  const Impl& d = *impl_;
  char text[300];
  std::snprintf(text, sizeof text,
                "FMA: %d blocks x %d threads (one full wave on %d SMs), %d independent accumulators acc = acc * a + b "
                "per thread, %lld steps, 2 flops per FFMA, CUDA events; every accumulator checked exactly",
                d.fma_blocks, kBlock, d.sms, kFmaChains, static_cast<long long>(d.fma_steps));
  return text;
}

std::string CeilingKernels::mix_how() const {
  const Impl& d = *impl_;
  char text[400];
  std::snprintf(text, sizeof text,
                "rotation mix: 4/8/16 independent points per thread (per repetition the fastest; last: %d), one full "
                "wave of %d-thread blocks on %d SMs, ~%lld steps, 2 FMUL + 2 FFMA per point-step, 6 flops, no memory "
                "traffic, CUDA events; every point's final angle and norm checked",
                last_mix_points_, kBlock, d.sms, static_cast<long long>(d.mix_steps[1]));
  return text;
}

std::string CeilingKernels::copy_how() const {
  const Impl& d = *impl_;
  char text[300];
  std::snprintf(text, sizeof text,
                "device memory copy: float4 kernel between two buffers of %zu MiB, %d passes, 2 x %zu MiB moved per "
                "pass, CUDA events; the target cleared before and compared with the source after",
                d.src.n * sizeof(float4) >> 20, kCopyPasses, d.src.n * sizeof(float4) >> 20);
  return text;
}

}  // namespace bs::kernels::cuda
