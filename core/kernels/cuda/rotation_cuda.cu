// SPDX-License-Identifier: GPL-3.0-or-later
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include "kernels/cuda/rotation_cuda.h"
#include "kernels/step_chunker.h"

namespace bs::kernels::cuda {
namespace {

void check(cudaError_t e, const char* what) {
  if (e != cudaSuccess) throw std::runtime_error(std::string("CUDA: ") + what + ": " + cudaGetErrorString(e));
}

__device__ inline float2 operator*(float a, float2 v) { return make_float2(a * v.x, a * v.y); }
__device__ inline float2 operator-(float2 a, float2 b) { return make_float2(a.x - b.x, a.y - b.y); }
__device__ inline float2 operator+(float2 a, float2 b) { return make_float2(a.x + b.x, a.y + b.y); }
__device__ inline float4 operator*(float a, float4 v) { return make_float4(a * v.x, a * v.y, a * v.z, a * v.w); }
__device__ inline float4 operator-(float4 a, float4 b) {
  return make_float4(a.x - b.x, a.y - b.y, a.z - b.z, a.w - b.w);
}
__device__ inline float4 operator+(float4 a, float4 b) {
  return make_float4(a.x + b.x, a.y + b.y, a.z + b.z, a.w + b.w);
}

// The paper's kernel: one thread per worker, its D points in one float/float2/float4.
template <class V>
__global__ void rotate_paper(V* xs, V* ys, long long workers, int steps, float c, float s) {
  const long long w = blockIdx.x * static_cast<long long>(blockDim.x) + threadIdx.x;
  if (w >= workers) return;
  V x = xs[w], y = ys[w];
  for (int n = 0; n < steps; ++n) {
    const V nx = c * x - s * y;
    y = s * x + c * y;
    x = nx;
  }
  xs[w] = x;
  ys[w] = y;
}

// Throughput ("float4x4"): 16 points per thread, loaded as four float4 chains, so every thread has
// instruction-level parallelism beside the warps the scheduler switches between. Written point by point with
// explicit fmaf, and y updated before x: the new x then takes the old x's register (nothing reads the old x after
// it), so the loop is exactly 2 FMUL + 2 FFMA per point-step with no MOV. The float4 form of the paper kernel
// (nx = c * x - s * y; y = ...; x = nx) made nvcc keep nx and the old x alive together and copy nx back at the end
// of every step: 16 MOVs beside 64 FP32 instructions, 19 % of the issue slots lost, and no unrolling of the step
// loop to amortise them (docs/gpu-check.md). Chain k of thread i is float4 k * items + i, so the loads and stores
// of a warp are coalesced.
__global__ void rotate_throughput(float4* xs, float4* ys, long long items, int steps, float c, float s) {
  const long long i = blockIdx.x * static_cast<long long>(blockDim.x) + threadIdx.x;
  if (i >= items) return;
  float x[16], y[16];
#pragma unroll
  for (int k = 0; k < 4; ++k) {
    const float4 a = xs[k * items + i], b = ys[k * items + i];
    x[4 * k] = a.x, x[4 * k + 1] = a.y, x[4 * k + 2] = a.z, x[4 * k + 3] = a.w;
    y[4 * k] = b.x, y[4 * k + 1] = b.y, y[4 * k + 2] = b.z, y[4 * k + 3] = b.w;
  }
#pragma unroll 4
  for (int n = 0; n < steps; ++n) {
#pragma unroll
    for (int p = 0; p < 16; ++p) {
      const float t = s * y[p];
      y[p] = fmaf(s, x[p], c * y[p]);
      x[p] = fmaf(c, x[p], -t);
    }
  }
#pragma unroll
  for (int k = 0; k < 4; ++k) {
    xs[k * items + i] = make_float4(x[4 * k], x[4 * k + 1], x[4 * k + 2], x[4 * k + 3]);
    ys[k * items + i] = make_float4(y[4 * k], y[4 * k + 1], y[4 * k + 2], y[4 * k + 3]);
  }
}

// FP32 lanes per SM: 64 on GP100, Volta, Turing and A100; 128 on Pascal consumer parts, GA10x, Ada, Hopper,
// Blackwell.
int lanes_for(int major, int minor) {
  if (major == 7 || (major == 8 && minor == 0) || (major == 6 && minor == 0)) return 64;
  return 128;
}

}  // namespace

std::vector<DeviceInfo> devices(std::string* why_none) {
  std::vector<DeviceInfo> out;
  int n = 0;
  const cudaError_t e = cudaGetDeviceCount(&n);
  if (e != cudaSuccess) {
    if (why_none) *why_none = cudaGetErrorString(e);
    return out;
  }
  for (int i = 0; i < n; ++i) {
    cudaDeviceProp p{};
    if (cudaGetDeviceProperties(&p, i) != cudaSuccess) continue;
    int clock = 0;
    cudaDeviceGetAttribute(&clock, cudaDevAttrClockRate, i);
    out.push_back({i, p.name, p.multiProcessorCount, clock, p.major, p.minor, lanes_for(p.major, p.minor)});
  }
  if (out.empty() && why_none) *why_none = "no CUDA device";
  return out;
}

double run_point(int device, int dims, std::int64_t iterations, std::int64_t workers, bool paper,
                 std::vector<float>& outputs, const CancelToken& cancel) {
  if (paper && dims != 1 && dims != 2 && dims != 4)
    throw std::invalid_argument("the CUDA paper kernel runs D = 1, 2 or 4 (float, float2, float4)");
  check(cudaSetDevice(device), "cudaSetDevice");
  const long long points = workers * dims;
  const long long floats = paper ? points : (points + 15) / 16 * 16;
  std::vector<float> xs(static_cast<std::size_t>(floats), 1.0f), ys(static_cast<std::size_t>(floats), 0.0f);
  float *dx = nullptr, *dy = nullptr;
  const std::size_t bytes = xs.size() * sizeof(float);
  check(cudaMalloc(&dx, bytes), "cudaMalloc");
  struct Free {
    float** a;
    float** b;
    ~Free() {
      cudaFree(*a);
      cudaFree(*b);
    }
  } release{&dx, &dy};
  check(cudaMalloc(&dy, bytes), "cudaMalloc");
  check(cudaMemcpy(dx, xs.data(), bytes, cudaMemcpyHostToDevice), "cudaMemcpy");
  check(cudaMemcpy(dy, ys.data(), bytes, cudaMemcpyHostToDevice), "cudaMemcpy");
  const float c = static_cast<float>(std::cos(2.0)), s = static_cast<float>(std::sin(2.0));
  const long long threads = paper ? workers : floats / 16;
  const int block = 256;
  const unsigned grid = static_cast<unsigned>((threads + block - 1) / block);
  check(cudaDeviceSynchronize(), "cudaDeviceSynchronize");
  // Launches of ~40 ms (StepChunker), each synchronised, so a cancel is seen between them.
  StepChunker chunks(iterations, points);
  const auto t0 = std::chrono::steady_clock::now();
  while (!chunks.done()) {
    cancel.throw_if_cancelled();
    const int steps = static_cast<int>(chunks.next());
    const auto c0 = std::chrono::steady_clock::now();
    if (!paper)
      rotate_throughput<<<grid, block>>>(reinterpret_cast<float4*>(dx), reinterpret_cast<float4*>(dy), threads, steps,
                                         c, s);
    else if (dims == 1)
      rotate_paper<float><<<grid, block>>>(dx, dy, workers, steps, c, s);
    else if (dims == 2)
      rotate_paper<float2>
          <<<grid, block>>>(reinterpret_cast<float2*>(dx), reinterpret_cast<float2*>(dy), workers, steps, c, s);
    else
      rotate_paper<float4>
          <<<grid, block>>>(reinterpret_cast<float4*>(dx), reinterpret_cast<float4*>(dy), workers, steps, c, s);
    check(cudaGetLastError(), "kernel launch");
    check(cudaDeviceSynchronize(), "kernel");
    chunks.completed(steps, std::chrono::duration<double>(std::chrono::steady_clock::now() - c0).count());
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  check(cudaMemcpy(xs.data(), dx, bytes, cudaMemcpyDeviceToHost), "cudaMemcpy");
  check(cudaMemcpy(ys.data(), dy, bytes, cudaMemcpyDeviceToHost), "cudaMemcpy");
  outputs.assign(static_cast<std::size_t>(workers), 0.0f);
  for (long long w = 0; w < workers; ++w)
    for (int d = 0; d < dims; ++d) outputs[static_cast<std::size_t>(w)] += xs[w * dims + d] + ys[w * dims + d];
  return seconds;
}

}  // namespace bs::kernels::cuda
