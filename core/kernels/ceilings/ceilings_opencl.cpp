// SPDX-License-Identifier: GPL-3.0-or-later
#define CL_TARGET_OPENCL_VERSION 120
#include "kernels/ceilings/ceilings_opencl.h"
#include "kernels/opencl_device_value.h"

#include <CL/cl.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

namespace bs::kernels {
namespace {

// VEC is float on a GPU (one point per lane, the work-items fill the SIMT lanes) and float16 on a CPU device, where
// PoCL and other CPU compilers vectorise explicit vector types but not the work-items of a kernel whose body is a
// long loop (-DW=1 or 16). Lane l of vector p of work-item t is float (t * P + p) * W + l of the buffers.
// FMA: 8 accumulators per work-item, acc = mad(acc, a, b) with a = 1 and b = 2^-10 (exact: see ceilings.h). mad,
// not fma(): fma() must round once, and a device without a fused unit (or a CPU compiler that will not vectorise
// the call) emulates it in software; mad is the FMA instruction wherever the device has one, as in the rotation
// kernel.
// Rotation mix: P vectors per work-item (mix4, mix8, mix16), the rotation kernel's own instructions (mad, as the
// rotation kernel is built with -cl-mad-enable): u = s y; y = mad(s, x, c y); x = mad(c, x, -u).
const char* kSource = R"CL(
#if W == 1
#define VEC float
#define LANES 0.0f
#define STORE(v, i, p) ((p)[i] = (v))
#else
#define VEC float16
#define LANES ((float16)(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15))
#define STORE(v, i, p) vstore16((v), (i), (p))
#endif

__kernel void fma8(__global float* out, const int steps, const float a, const float b) {
  const uint t = get_global_id(0);
  VEC acc[8];
  for (int k = 0; k < 8; ++k) acc[k] = (VEC)((float)(k + (t & 1023u)));
  for (int n = 0; n < steps; ++n) {
    for (int k = 0; k < 8; ++k) acc[k] = mad(acc[k], (VEC)a, (VEC)b);
  }
  for (int k = 0; k < 8; ++k) STORE(acc[k], t * 8 + k, out);
}

#define MIX(P)                                                                   \
  __kernel void mix##P(__global float* xs, __global float* ys, const int steps,  \
                       const float c, const float s) {                           \
    const uint t = get_global_id(0);                                             \
    VEC x[P], y[P];                                                              \
    for (int p = 0; p < P; ++p) {                                                \
      const VEC a = 1e-3f * ((float)((t * P + p) * W) + LANES);                  \
      x[p] = cos(a);                                                             \
      y[p] = sin(a);                                                             \
    }                                                                            \
    for (int n = 0; n < steps; ++n) {                                            \
      for (int p = 0; p < P; ++p) {                                              \
        const VEC u = s * y[p];                                                  \
        y[p] = mad((VEC)s, x[p], c * y[p]);                                      \
        x[p] = mad((VEC)c, x[p], -u);                                            \
      }                                                                          \
    }                                                                            \
    for (int p = 0; p < P; ++p) {                                                \
      STORE(x[p], t * P + p, xs);                                                \
      STORE(y[p], t * P + p, ys);                                                \
    }                                                                            \
  }
MIX(4)
MIX(8)
MIX(16)

__kernel void copy4(__global float4* dst, __global const float4* src) {
  const size_t i = get_global_id(0);
  dst[i] = src[i];
}
)CL";

constexpr int kFmaChains = 8;
constexpr float kFmaStep = 1.0f / 1024.0f;
constexpr std::int64_t kFmaMaxSteps = std::int64_t{1} << 23;  // start + steps * 2^-10 stays exact (< 2^14)
constexpr std::int64_t kMixMaxSteps = 2'000'000;              // the angle check's tolerance stays < 0.5 rad
constexpr int kMixPoints[] = {4, 8, 16};
constexpr int kCopyPasses = 10;

void check(cl_int err, const char* what) {
  if (err != CL_SUCCESS)
    throw std::runtime_error(std::string("OpenCL ceilings: ") + what + " failed (error " + std::to_string(err) + ")");
}

struct Mem {
  cl_mem m = nullptr;
  Mem() = default;
  Mem(const Mem&) = delete;
  Mem& operator=(const Mem&) = delete;
  ~Mem() {
    if (m) clReleaseMemObject(m);
  }
};

class OpenClCeilings final : public DeviceCeilingKernels {
 public:
  OpenClCeilings(cl_device_id id, const CeilingSpec& spec) : id_(id), target_(spec.device_target_seconds) {
    cl_int err = CL_SUCCESS;
    context_ = clCreateContext(nullptr, 1, &id_, nullptr, nullptr, &err);
    check(err, "clCreateContext");
    queue_ = clCreateCommandQueue(context_, id_, CL_QUEUE_PROFILING_ENABLE, &err);
    check(err, "clCreateCommandQueue");
    program_ = clCreateProgramWithSource(context_, 1, &kSource, nullptr, &err);
    check(err, "clCreateProgramWithSource");
    const auto type = device_value<cl_device_type>(id_, CL_DEVICE_TYPE);
    width_ = (type & CL_DEVICE_TYPE_CPU) ? 16 : 1;
    const std::string options = "-cl-mad-enable -DW=" + std::to_string(width_);
    if (const cl_int built = clBuildProgram(program_, 1, &id_, options.c_str(), nullptr, nullptr);
        built != CL_SUCCESS) {
      std::size_t size = 0;
      clGetProgramBuildInfo(program_, id_, CL_PROGRAM_BUILD_LOG, 0, nullptr, &size);
      std::string log(size, '\0');
      clGetProgramBuildInfo(program_, id_, CL_PROGRAM_BUILD_LOG, size, log.data(), nullptr);
      throw std::runtime_error("OpenCL ceilings: clBuildProgram failed (error " + std::to_string(built) + "):\n" + log);
    }
    fma_ = kernel("fma8");
    for (int i = 0; i < 3; ++i) mix_[i] = kernel(("mix" + std::to_string(kMixPoints[i])).c_str());
    copy_ = kernel("copy4");
    // Work-items: enough to fill a GPU (2048 per compute unit, as many as an NVIDIA SM holds), far fewer on a CPU
    // device, where each work-group runs on one core.
    units_ = static_cast<int>(device_value<cl_uint>(id_, CL_DEVICE_MAX_COMPUTE_UNITS));
    items_ = static_cast<std::size_t>(std::max(units_, 1)) * ((type & CL_DEVICE_TYPE_GPU) ? 2048 : 256);
    const cl_float c = static_cast<float>(std::cos(2.0)), s = static_cast<float>(std::sin(2.0));
    c_ = c, s_ = s;
    fma_out_.m = buffer(items_ * kFmaChains * width_ * sizeof(float));
    mix_x_.m = buffer(items_ * 16 * width_ * sizeof(float));
    mix_y_.m = buffer(items_ * 16 * width_ * sizeof(float));
    // Copy buffers: the spec's size, else 256 MiB on a GPU and 64 MiB elsewhere, within the largest allocation and
    // an eighth of the device's memory (a Jetson or an integrated GPU shares it with the CPU).
    std::size_t bytes = (spec.device_copy_mib ? spec.device_copy_mib : (type & CL_DEVICE_TYPE_GPU) ? 256 : 64) << 20;
    bytes = std::min<std::size_t>(bytes, device_value<cl_ulong>(id_, CL_DEVICE_MAX_MEM_ALLOC_SIZE));
    if (!spec.device_copy_mib)
      bytes = std::min<std::size_t>(bytes, device_value<cl_ulong>(id_, CL_DEVICE_GLOBAL_MEM_SIZE) / 8);
    copy_floats4_ = std::max<std::size_t>(bytes / 16, 1024);
    std::vector<float> pattern(copy_floats4_ * 4);
    for (std::size_t i = 0; i < pattern.size(); ++i) pattern[i] = static_cast<float>(i % 65521) + 0.25f;
    src_.m = buffer(pattern.size() * sizeof(float), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, pattern.data());
    dst_.m = buffer(pattern.size() * sizeof(float));
    // One untimed launch of each first: a driver may finish compiling a kernel at its first launch.
    launch_fma(1);
    for (int i = 0; i < 3; ++i) launch_mix(i, 1);
    fma_steps_ = size_steps([&](std::int64_t n) { return launch_fma(n); }, kFmaMaxSteps, target_);
    for (int i = 0; i < 3; ++i)
      mix_steps_[i] = size_steps([&](std::int64_t n) { return launch_mix(i, n); }, kMixMaxSteps, target_ / 3);
  }

  ~OpenClCeilings() override {
    for (cl_kernel k : {fma_, mix_[0], mix_[1], mix_[2], copy_})
      if (k) clReleaseKernel(k);
    if (program_) clReleaseProgram(program_);
    // The buffers (members) are released after the context: OpenCL keeps a context alive while its objects are.
    if (queue_) clReleaseCommandQueue(queue_);
    if (context_) clReleaseContext(context_);
  }

  CeilingSample fma() override {
    const double seconds = launch_fma(fma_steps_);
    std::vector<float> out(items_ * kFmaChains * width_);
    check(clEnqueueReadBuffer(queue_, fma_out_.m, CL_TRUE, 0, out.size() * sizeof(float), out.data(), 0, nullptr,
                              nullptr),
          "clEnqueueReadBuffer");
    for (std::size_t i = 0; i < out.size(); ++i) {
      const std::size_t t = i / (kFmaChains * width_), k = i / width_ % kFmaChains;
      const double expected = static_cast<double>(k + (t & 1023u)) + static_cast<double>(fma_steps_) * kFmaStep;
      if (static_cast<double>(out[i]) != expected)
        throw std::runtime_error("OpenCL FMA ceiling: work-item " + std::to_string(t) + " accumulator " +
                                 std::to_string(k) + " is " + std::to_string(out[i]) + ", not " +
                                 std::to_string(expected) + " after " + std::to_string(fma_steps_) + " steps");
    }
    return {2.0 * kFmaChains * width_ * static_cast<double>(fma_steps_) * static_cast<double>(items_), seconds, 0};
  }

  CeilingSample rotation_mix() override {
    CeilingSample best;
    const double phi = std::atan2(static_cast<double>(s_), static_cast<double>(c_));
    const double log_norm_step = std::log(static_cast<double>(c_) * c_ + static_cast<double>(s_) * s_);
    for (int i = 0; i < 3; ++i) {
      const std::int64_t steps = mix_steps_[i];
      const double seconds = launch_mix(i, steps);
      const std::size_t points = items_ * kMixPoints[i] * width_;
      std::vector<float> x(points), y(points);
      check(clEnqueueReadBuffer(queue_, mix_x_.m, CL_TRUE, 0, points * sizeof(float), x.data(), 0, nullptr, nullptr),
            "clEnqueueReadBuffer");
      check(clEnqueueReadBuffer(queue_, mix_y_.m, CL_TRUE, 0, points * sizeof(float), y.data(), 0, nullptr, nullptr),
            "clEnqueueReadBuffer");
      const double tolerance = 2e-7 * static_cast<double>(steps) + 1e-3;
      for (std::size_t j = 0; j < points; ++j) {
        const double start = static_cast<double>(1e-3f * static_cast<float>(j));  // as the kernel computes it
        const double error =
            std::remainder(std::atan2(y[j], x[j]) - (start + phi * static_cast<double>(steps)), 2 * M_PI);
        const double log_norm = std::log(static_cast<double>(x[j]) * x[j] + static_cast<double>(y[j]) * y[j]);
        if (!(std::fabs(error) < tolerance) ||
            !(std::fabs(log_norm - log_norm_step * static_cast<double>(steps)) < 0.1))
          throw std::runtime_error("OpenCL rotation-mix ceiling: point " + std::to_string(j) + " of mix" +
                                   std::to_string(kMixPoints[i]) + " is not where " + std::to_string(steps) +
                                   " steps put it (angle off by " + std::to_string(error) + " rad)");
      }
      const CeilingSample run{6.0 * static_cast<double>(points) * static_cast<double>(steps), seconds, 0};
      if (run.rate() > best.rate()) best = run, last_points_ = kMixPoints[i];
    }
    return best;
  }

  CeilingSample bandwidth() override {
    const cl_float zero = 0;
    const std::size_t bytes = copy_floats4_ * 16;
    check(clEnqueueFillBuffer(queue_, dst_.m, &zero, sizeof zero, 0, bytes, 0, nullptr, nullptr),
          "clEnqueueFillBuffer");
    check(clFinish(queue_), "clFinish");
    check(clSetKernelArg(copy_, 0, sizeof(cl_mem), &dst_.m), "clSetKernelArg");
    check(clSetKernelArg(copy_, 1, sizeof(cl_mem), &src_.m), "clSetKernelArg");
    double seconds = 0;
    for (int pass = 0; pass < kCopyPasses; ++pass) seconds += run(copy_, copy_floats4_);
    std::vector<float> a(copy_floats4_ * 4);
    check(clEnqueueReadBuffer(queue_, dst_.m, CL_TRUE, 0, bytes, a.data(), 0, nullptr, nullptr), "clEnqueueReadBuffer");
    for (std::size_t i = 0; i < a.size(); ++i)
      if (a[i] != static_cast<float>(i % 65521) + 0.25f)
        throw std::runtime_error("OpenCL copy ceiling: float " + std::to_string(i) + " differs after the copy");
    return {2.0 * kCopyPasses * static_cast<double>(bytes), seconds, 0};
  }

  std::string fma_how() const override {
    char text[300];
    std::snprintf(
        text, sizeof text,
        "FMA: %zu work-items (%d compute units), %d independent accumulators acc = mad(acc, a, b) of %s "
        "each, %lld steps, 2 flops per lane and mad, OpenCL event profiling; every accumulator checked exactly",
        items_, units_, kFmaChains, width_ == 1 ? "float" : "float16", static_cast<long long>(fma_steps_));
    return text;
  }
  std::string mix_how() const override {
    char text[300];
    std::snprintf(text, sizeof text,
                  "rotation mix: %zu work-items with 4/8/16 independent %s each (per repetition the fastest; last: "
                  "%d), ~%lld steps, 2 mul + 2 mad per point-step, 6 flops, OpenCL event profiling; every point's "
                  "final angle and norm checked",
                  items_, width_ == 1 ? "points" : "float16 vectors", last_points_,
                  static_cast<long long>(mix_steps_[1]));
    return text;
  }
  std::string bandwidth_how() const override {
    char text[300];
    std::snprintf(text, sizeof text,
                  "device memory copy: float4 kernel between two buffers of %zu MiB, %d passes, 2 x %zu MiB moved per "
                  "pass, OpenCL event profiling; the target cleared before and compared with the source after",
                  copy_floats4_ * 16 >> 20, kCopyPasses, copy_floats4_ * 16 >> 20);
    return text;
  }

 private:
  cl_kernel kernel(const char* name) {
    cl_int err = CL_SUCCESS;
    cl_kernel k = clCreateKernel(program_, name, &err);
    check(err, "clCreateKernel");
    return k;
  }
  cl_mem buffer(std::size_t bytes, cl_mem_flags flags = CL_MEM_READ_WRITE, void* host = nullptr) {
    cl_int err = CL_SUCCESS;
    cl_mem m = clCreateBuffer(context_, flags, bytes, host, &err);
    check(err, "clCreateBuffer");
    return m;
  }
  // One launch over `global` work-items; its device time from the event's profiling counters.
  double run(cl_kernel k, std::size_t global) {
    cl_event e = nullptr;
    check(clEnqueueNDRangeKernel(queue_, k, 1, nullptr, &global, nullptr, 0, nullptr, &e), "clEnqueueNDRangeKernel");
    const cl_int waited = clWaitForEvents(1, &e);
    cl_ulong t0 = 0, t1 = 0;
    const cl_int a = clGetEventProfilingInfo(e, CL_PROFILING_COMMAND_START, sizeof t0, &t0, nullptr);
    const cl_int b = clGetEventProfilingInfo(e, CL_PROFILING_COMMAND_END, sizeof t1, &t1, nullptr);
    clReleaseEvent(e);
    check(waited, "clWaitForEvents");
    check(a != CL_SUCCESS ? a : b, "clGetEventProfilingInfo");
    return static_cast<double>(t1 - t0) * 1e-9;
  }
  double launch_fma(std::int64_t steps) {
    const cl_int n = static_cast<cl_int>(steps);
    const cl_float a = 1.0f, b = kFmaStep;
    check(clSetKernelArg(fma_, 0, sizeof(cl_mem), &fma_out_.m), "clSetKernelArg");
    check(clSetKernelArg(fma_, 1, sizeof n, &n), "clSetKernelArg");
    check(clSetKernelArg(fma_, 2, sizeof a, &a), "clSetKernelArg");
    check(clSetKernelArg(fma_, 3, sizeof b, &b), "clSetKernelArg");
    return run(fma_, items_);
  }
  double launch_mix(int i, std::int64_t steps) {
    const cl_int n = static_cast<cl_int>(steps);
    check(clSetKernelArg(mix_[i], 0, sizeof(cl_mem), &mix_x_.m), "clSetKernelArg");
    check(clSetKernelArg(mix_[i], 1, sizeof(cl_mem), &mix_y_.m), "clSetKernelArg");
    check(clSetKernelArg(mix_[i], 2, sizeof n, &n), "clSetKernelArg");
    check(clSetKernelArg(mix_[i], 3, sizeof c_, &c_), "clSetKernelArg");
    check(clSetKernelArg(mix_[i], 4, sizeof s_, &s_), "clSetKernelArg");
    return run(mix_[i], items_);
  }
  // Steps doubled from 256 until a launch lasts >= a fifth of the target (or `cap`), then scaled to the target.
  template <class Launch>
  static std::int64_t size_steps(Launch launch, std::int64_t cap, double target) {
    for (std::int64_t steps = 256;; steps *= 2) {
      const double t = launch(steps);
      if (t >= target / 5 || steps >= cap)
        return std::clamp<std::int64_t>(
            static_cast<std::int64_t>(static_cast<double>(steps) * target / std::max(t, 1e-9)), 64, cap);
    }
  }

  cl_device_id id_;
  double target_;
  cl_context context_ = nullptr;
  cl_command_queue queue_ = nullptr;
  cl_program program_ = nullptr;
  cl_kernel fma_ = nullptr, mix_[3] = {}, copy_ = nullptr;
  int units_ = 0, last_points_ = 0, width_ = 1;  // width_: floats per VEC (1 on a GPU, 16 on a CPU device)
  std::size_t items_ = 0, copy_floats4_ = 0;
  cl_float c_ = 0, s_ = 0;
  Mem fma_out_, mix_x_, mix_y_, src_, dst_;
  std::int64_t fma_steps_ = 0, mix_steps_[3] = {};
};

}  // namespace

std::unique_ptr<DeviceCeilingKernels> make_opencl_ceiling_kernels(cl_device_id device, const CeilingSpec& spec) {
  return std::make_unique<OpenClCeilings>(device, spec);
}

}  // namespace bs::kernels
