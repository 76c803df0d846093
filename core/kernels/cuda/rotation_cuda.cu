// SPDX-License-Identifier: GPL-3.0-or-later
#include <chrono>
#include <stdexcept>
#include <string>

#include "kernels/cuda/rotation_cuda.h"

namespace bs::kernels::cuda {
namespace {

constexpr double kPointStepsPerLaunch = 3e9;  // ~1-10 ms on a current GPU: cancel is seen between launches

void check(cudaError_t e, const char* what) {
  if (e != cudaSuccess) throw std::runtime_error(std::string("CUDA: ") + what + ": " + cudaGetErrorString(e));
}

__device__ inline float2 operator*(float a, float2 v) { return make_float2(a * v.x, a * v.y); }
__device__ inline float2 operator-(float2 a, float2 b) { return make_float2(a.x - b.x, a.y - b.y); }
__device__ inline float2 operator+(float2 a, float2 b) { return make_float2(a.x + b.x, a.y + b.y); }
__device__ inline float4 operator*(float a, float4 v) { return make_float4(a * v.x, a * v.y, a * v.z, a * v.w); }
__device__ inline float4 operator-(float4 a, float4 b) { return make_float4(a.x - b.x, a.y - b.y, a.z - b.z, a.w - b.w); }
__device__ inline float4 operator+(float4 a, float4 b) { return make_float4(a.x + b.x, a.y + b.y, a.z + b.z, a.w + b.w); }

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

// Throughput: four independent points per thread (instruction-level parallelism hides FMA latency).
__global__ void rotate_throughput(float4* xs, float4* ys, long long items, int steps, float c, float s) {
  const long long i = blockIdx.x * static_cast<long long>(blockDim.x) + threadIdx.x;
  if (i >= items) return;
  float4 x = xs[i], y = ys[i];
  for (int n = 0; n < steps; ++n) {
    const float4 nx = c * x - s * y;
    y = s * x + c * y;
    x = nx;
  }
  xs[i] = x;
  ys[i] = y;
}

int lanes_for(int major, int minor) {
  if (major >= 8 && !(major == 8 && minor == 0)) return 128;  // GA10x, Ada, Hopper, Blackwell
  return 64;                                                  // Turing, A100
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
  const long long floats = paper ? points : (points + 3) / 4 * 4;
  std::vector<float> xs(static_cast<std::size_t>(floats), 1.0f), ys(static_cast<std::size_t>(floats), 0.0f);
  float *dx = nullptr, *dy = nullptr;
  const std::size_t bytes = xs.size() * sizeof(float);
  check(cudaMalloc(&dx, bytes), "cudaMalloc");
  struct Free {
    float** a;
    float** b;
    ~Free() { cudaFree(*a); cudaFree(*b); }
  } release{&dx, &dy};
  check(cudaMalloc(&dy, bytes), "cudaMalloc");
  check(cudaMemcpy(dx, xs.data(), bytes, cudaMemcpyHostToDevice), "cudaMemcpy");
  check(cudaMemcpy(dy, ys.data(), bytes, cudaMemcpyHostToDevice), "cudaMemcpy");
  const float c = static_cast<float>(std::cos(2.0)), s = static_cast<float>(std::sin(2.0));
  const long long threads = paper ? workers : floats / 4;
  const int block = 256;
  const unsigned grid = static_cast<unsigned>((threads + block - 1) / block);
  const long long chunk = std::max<long long>(1, std::min<long long>(1 << 30, static_cast<long long>(kPointStepsPerLaunch / static_cast<double>(points))));
  check(cudaDeviceSynchronize(), "cudaDeviceSynchronize");
  const auto t0 = std::chrono::steady_clock::now();
  for (long long done = 0; done < iterations; done += chunk) {
    cancel.throw_if_cancelled();
    const int steps = static_cast<int>(std::min<long long>(chunk, iterations - done));
    if (!paper) rotate_throughput<<<grid, block>>>(reinterpret_cast<float4*>(dx), reinterpret_cast<float4*>(dy), threads, steps, c, s);
    else if (dims == 1) rotate_paper<float><<<grid, block>>>(dx, dy, workers, steps, c, s);
    else if (dims == 2) rotate_paper<float2><<<grid, block>>>(reinterpret_cast<float2*>(dx), reinterpret_cast<float2*>(dy), workers, steps, c, s);
    else rotate_paper<float4><<<grid, block>>>(reinterpret_cast<float4*>(dx), reinterpret_cast<float4*>(dy), workers, steps, c, s);
    check(cudaGetLastError(), "kernel launch");
    check(cudaDeviceSynchronize(), "kernel");
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
