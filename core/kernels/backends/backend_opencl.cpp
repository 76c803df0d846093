// SPDX-License-Identifier: GPL-3.0-or-later
#define CL_TARGET_OPENCL_VERSION 120
#include "kernels/backends/backend_opencl.h"
#include "kernels/ceilings/ceilings_opencl.h"
#include "kernels/opencl_device_value.h"
#include "kernels/step_chunker.h"

#include <CL/cl.h>

#include <chrono>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>

namespace bs::kernels {
namespace {

const char* kSource = R"CL(
// VEC is float, float2 or float4 (-DVEC=...): D = 1, 2, 4 points per work-item, as in the paper.
__kernel void rotate_paper(__global VEC* xs, __global VEC* ys, const int steps, const float c, const float s) {
  const size_t w = get_global_id(0);
  VEC x = xs[w], y = ys[w];
  for (int n = 0; n < steps; ++n) {
    const VEC nx = c * x - s * y;
    y = s * x + c * y;
    x = nx;
  }
  xs[w] = x;
  ys[w] = y;
}

// Four independent float16 chains per work-item: 64 points, enough independent work to hide FMA latency. y is
// updated before x (t keeps s * y): the new x then reuses the old x's register, so the loop is 2 mul + 2 mad per
// point-step with no copies. The paper kernel's "nx = c x - s y; y = ...; x = nx" kept nx and the old x alive
// together, which cost NVIDIA's compiler a MOV per component and step in the CUDA twin (docs/gpu-check.md).
__kernel void rotate_throughput(__global float16* xs, __global float16* ys, const int steps, const float c,
                                const float s) {
  const size_t i = get_global_id(0) * 4;
  float16 x0 = xs[i], x1 = xs[i + 1], x2 = xs[i + 2], x3 = xs[i + 3];
  float16 y0 = ys[i], y1 = ys[i + 1], y2 = ys[i + 2], y3 = ys[i + 3];
  for (int n = 0; n < steps; ++n) {  // 256 FP32 instructions per step: the loop's own 3 need no unrolling
    const float16 t0 = s * y0, t1 = s * y1, t2 = s * y2, t3 = s * y3;
    y0 = mad(s, x0, c * y0); y1 = mad(s, x1, c * y1); y2 = mad(s, x2, c * y2); y3 = mad(s, x3, c * y3);
    x0 = mad(c, x0, -t0); x1 = mad(c, x1, -t1); x2 = mad(c, x2, -t2); x3 = mad(c, x3, -t3);
  }
  xs[i] = x0; xs[i + 1] = x1; xs[i + 2] = x2; xs[i + 3] = x3;
  ys[i] = y0; ys[i + 1] = y1; ys[i + 2] = y2; ys[i + 3] = y3;
}
)CL";

void check(cl_int err, const char* what) {
  if (err != CL_SUCCESS)
    throw std::runtime_error(std::string("OpenCL: ") + what + " failed (error " + std::to_string(err) + ")");
}

std::string device_string(cl_device_id d, cl_device_info what) {
  std::size_t size = 0;
  if (clGetDeviceInfo(d, what, 0, nullptr, &size) != CL_SUCCESS || size == 0) return {};
  std::string s(size, '\0');
  clGetDeviceInfo(d, what, size, s.data(), nullptr);
  while (!s.empty() && s.back() == '\0') s.pop_back();
  return s;
}

// A device with its context, queue and one built program per VEC width, shared by the Backend's closures.
class Device {
 public:
  explicit Device(cl_device_id id) : id_(id) {
    cl_int err = CL_SUCCESS;
    context_ = clCreateContext(nullptr, 1, &id_, nullptr, nullptr, &err);
    check(err, "clCreateContext");
    queue_ = clCreateCommandQueue(context_, id_, 0, &err);
    check(err, "clCreateCommandQueue");
  }
  ~Device() {
    if (triad_kernel_) clReleaseKernel(triad_kernel_);
    if (triad_program_) clReleaseProgram(triad_program_);
    for (auto& [key, k] : kernels_) clReleaseKernel(k);
    for (auto& [key, p] : programs_) clReleaseProgram(p);
    if (queue_) clReleaseCommandQueue(queue_);
    if (context_) clReleaseContext(context_);
  }
  Device(const Device&) = delete;
  Device& operator=(const Device&) = delete;

  double run(const RotationParams& p, std::int64_t workers, Variant variant, std::vector<float>& outputs,
             const CancelToken& cancel) {
    check_problem_size(p, workers);
    std::lock_guard lock(mutex_);
    int width = 16;  // floats per vector element of the state buffers
    std::int64_t items = 0, floats = 0;
    if (variant == Variant::Paper) {
      if (p.dims != 1 && p.dims != 2 && p.dims != 4)
        throw std::invalid_argument("the OpenCL paper kernel runs D = 1, 2 or 4 (float, float2, float4)");
      width = p.dims;
      items = workers;
      floats = workers * p.dims;
    } else {
      const std::int64_t points = workers * p.dims;
      items = (points + 63) / 64;
      floats = items * 64;
    }
    cl_kernel kernel = kernel_for(variant == Variant::Paper ? width : 0);
    std::vector<float> xs(static_cast<std::size_t>(floats), 1.0f), ys(static_cast<std::size_t>(floats), 0.0f);
    cl_int err = CL_SUCCESS;
    const std::size_t bytes = xs.size() * sizeof(float);
    cl_mem bx = clCreateBuffer(context_, CL_MEM_READ_WRITE | CL_MEM_COPY_HOST_PTR, bytes, xs.data(), &err);
    check(err, "clCreateBuffer");
    cl_mem by = clCreateBuffer(context_, CL_MEM_READ_WRITE | CL_MEM_COPY_HOST_PTR, bytes, ys.data(), &err);
    if (err != CL_SUCCESS) clReleaseMemObject(bx);
    check(err, "clCreateBuffer");
    struct Release {
      cl_mem a, b;
      ~Release() {
        clReleaseMemObject(a);
        clReleaseMemObject(b);
      }
    } release{bx, by};
    const float c = rotation_cos(), s = rotation_sin();
    check(clSetKernelArg(kernel, 0, sizeof bx, &bx), "clSetKernelArg");
    check(clSetKernelArg(kernel, 1, sizeof by, &by), "clSetKernelArg");
    check(clSetKernelArg(kernel, 3, sizeof c, &c), "clSetKernelArg");
    check(clSetKernelArg(kernel, 4, sizeof s, &s), "clSetKernelArg");
    const std::size_t global = static_cast<std::size_t>(items);
    check(clFinish(queue_), "clFinish");
    // Launches of ~40 ms (StepChunker) so a cancel is seen between them; each launch ends in clFinish.
    StepChunker chunks(p.iterations, workers * p.dims);
    const auto t0 = std::chrono::steady_clock::now();
    while (!chunks.done()) {
      cancel.throw_if_cancelled();
      const cl_int steps = static_cast<cl_int>(chunks.next());
      const auto c0 = std::chrono::steady_clock::now();
      check(clSetKernelArg(kernel, 2, sizeof steps, &steps), "clSetKernelArg");
      check(clEnqueueNDRangeKernel(queue_, kernel, 1, nullptr, &global, nullptr, 0, nullptr, nullptr),
            "clEnqueueNDRangeKernel");
      check(clFinish(queue_), "clFinish");
      chunks.completed(steps, std::chrono::duration<double>(std::chrono::steady_clock::now() - c0).count());
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    check(clEnqueueReadBuffer(queue_, bx, CL_TRUE, 0, bytes, xs.data(), 0, nullptr, nullptr), "clEnqueueReadBuffer");
    check(clEnqueueReadBuffer(queue_, by, CL_TRUE, 0, bytes, ys.data(), 0, nullptr, nullptr), "clEnqueueReadBuffer");
    // out = sum over the worker's points of (x + y), as the paper's kernel stores it.
    outputs.assign(static_cast<std::size_t>(workers), 0.0f);
    for (std::int64_t w = 0; w < workers; ++w)
      for (int d = 0; d < p.dims; ++d) outputs[static_cast<std::size_t>(w)] += xs[w * p.dims + d] + ys[w * p.dims + d];
    return seconds;
  }

  // One STREAM triad pass on the device: a = b + q * c over `elements` floats in device buffers.
  double triad(std::size_t elements, const CancelToken& cancel) {
    std::lock_guard lock(mutex_);
    if (elements == 0) throw std::invalid_argument("triad needs at least one element");
    const std::size_t bytes = elements * sizeof(float);
    if (bytes > device_value<cl_ulong>(id_, CL_DEVICE_MAX_MEM_ALLOC_SIZE))
      throw std::invalid_argument("the triad arrays exceed the device's largest allocation");
    cl_int err = CL_SUCCESS;
    if (!triad_kernel_) {
      static const char* src =
          "__kernel void triad(__global float* a, __global const float* b, __global const float* c, float q) {\n"
          "  size_t i = get_global_id(0); a[i] = b[i] + q * c[i]; }\n";
      triad_program_ = clCreateProgramWithSource(context_, 1, &src, nullptr, &err);
      check(err, "clCreateProgramWithSource");
      check(clBuildProgram(triad_program_, 1, &id_, "", nullptr, nullptr), "clBuildProgram (triad)");
      triad_kernel_ = clCreateKernel(triad_program_, "triad", &err);
      check(err, "clCreateKernel");
    }
    std::vector<float> host_b(elements), host_c(elements, 2.0f), host_a(elements, 0.0f);
    for (std::size_t i = 0; i < elements; ++i) host_b[i] = 1.0f + static_cast<float>(i % 7);
    cl_mem buf[3] = {};
    struct Release {
      cl_mem* m;
      ~Release() {
        for (int i = 0; i < 3; ++i)
          if (m[i]) clReleaseMemObject(m[i]);
      }
    } release{buf};
    buf[0] = clCreateBuffer(context_, CL_MEM_READ_WRITE | CL_MEM_COPY_HOST_PTR, bytes, host_a.data(), &err);
    check(err, "clCreateBuffer");
    buf[1] = clCreateBuffer(context_, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, bytes, host_b.data(), &err);
    check(err, "clCreateBuffer");
    buf[2] = clCreateBuffer(context_, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, bytes, host_c.data(), &err);
    check(err, "clCreateBuffer");
    const float q = 3.0f;
    for (cl_uint i = 0; i < 3; ++i) check(clSetKernelArg(triad_kernel_, i, sizeof(cl_mem), &buf[i]), "clSetKernelArg");
    check(clSetKernelArg(triad_kernel_, 3, sizeof q, &q), "clSetKernelArg");
    const std::size_t global = elements;
    // An untimed pass first: drivers move buffers to the device lazily, on first use.
    check(clEnqueueNDRangeKernel(queue_, triad_kernel_, 1, nullptr, &global, nullptr, 0, nullptr, nullptr), "triad");
    check(clFinish(queue_), "clFinish");
    cancel.throw_if_cancelled();
    const auto t0 = std::chrono::steady_clock::now();
    check(clEnqueueNDRangeKernel(queue_, triad_kernel_, 1, nullptr, &global, nullptr, 0, nullptr, nullptr), "triad");
    check(clFinish(queue_), "clFinish");
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    check(clEnqueueReadBuffer(queue_, buf[0], CL_TRUE, 0, bytes, host_a.data(), 0, nullptr, nullptr), "read");
    for (std::size_t i = 0; i < elements; i += 4093)
      if (host_a[i] != host_b[i] + 6.0f) throw std::runtime_error("OpenCL triad: wrong result");
    return seconds;
  }

 private:
  cl_program triad_program_ = nullptr;
  cl_kernel triad_kernel_ = nullptr;
  // width 1/2/4: paper kernel with that VEC; 0: the throughput kernel.
  cl_kernel kernel_for(int width) {
    if (auto it = kernels_.find(width); it != kernels_.end()) return it->second;
    cl_int err = CL_SUCCESS;
    cl_program program = clCreateProgramWithSource(context_, 1, &kSource, nullptr, &err);
    check(err, "clCreateProgramWithSource");
    programs_[width] = program;
    const std::string vec = width <= 1 ? "float" : "float" + std::to_string(width);
    // -cl-mad-enable lets c*x - s*y become mul + FMA, as the CPU SIMD code does; results stay within the
    // closed-form tolerance, which every run checks.
    const std::string options = "-DVEC=" + vec + " -cl-mad-enable";
    if (const cl_int built = clBuildProgram(program, 1, &id_, options.c_str(), nullptr, nullptr); built != CL_SUCCESS) {
      std::size_t size = 0;
      clGetProgramBuildInfo(program, id_, CL_PROGRAM_BUILD_LOG, 0, nullptr, &size);
      std::string log(size, '\0');
      clGetProgramBuildInfo(program, id_, CL_PROGRAM_BUILD_LOG, size, log.data(), nullptr);
      while (!log.empty() && log.back() == '\0') log.pop_back();
      throw std::runtime_error("OpenCL: clBuildProgram failed (error " + std::to_string(built) + ") with options '" +
                               options + "'; build log:\n" + log);
    }
    cl_kernel k = clCreateKernel(program, width == 0 ? "rotate_throughput" : "rotate_paper", &err);
    check(err, "clCreateKernel");
    kernels_[width] = k;
    return k;
  }

  cl_device_id id_;
  cl_context context_ = nullptr;
  cl_command_queue queue_ = nullptr;
  std::map<int, cl_program> programs_;
  std::map<int, cl_kernel> kernels_;
  std::mutex mutex_;
};

struct GpuLanes {
  int lanes = 32;
  std::string why;
};

// Intel Gen9-Xe: a compute unit is one EU with 8 FP32 lanes (2 x SIMD-4); AMD GCN/RDNA: 64 lanes per CU; NVIDIA: a
// compute unit is an SM, 64 lanes up to Turing and A100, 128 on Pascal consumer parts, GA10x, Ada, Hopper and later
// (compute capability from cl_nv_device_attribute_query). Others: 32, a guess the details say is one.
GpuLanes gpu_lanes_per_compute_unit(cl_device_id id, const std::string& vendor) {
  constexpr cl_device_info kComputeCapabilityMajorNv = 0x4000, kComputeCapabilityMinorNv = 0x4001;
  if (vendor.find("Intel") != std::string::npos) return {8, "Intel EU"};
  if (vendor.find("Advanced Micro Devices") != std::string::npos || vendor.find("AMD") != std::string::npos)
    return {64, "AMD CU"};
  if (vendor.find("NVIDIA") != std::string::npos) {
    cl_uint major = 0, minor = 0;
    if (clGetDeviceInfo(id, kComputeCapabilityMajorNv, sizeof major, &major, nullptr) == CL_SUCCESS &&
        clGetDeviceInfo(id, kComputeCapabilityMinorNv, sizeof minor, &minor, nullptr) == CL_SUCCESS) {
      const bool narrow = major == 7 || (major == 8 && minor == 0) || (major == 6 && minor == 0);
      return {narrow ? 64 : 128,
              "NVIDIA SM, compute capability " + std::to_string(major) + "." + std::to_string(minor)};
    }
    return {128, "NVIDIA SM, compute capability unknown"};
  }
  return {32, "unknown architecture, assumed"};
}

}  // namespace

std::string opencl_unavailable_reason() {
  cl_uint nplatforms = 0;
  const cl_int err = clGetPlatformIDs(0, nullptr, &nplatforms);
  if (err != CL_SUCCESS || nplatforms == 0)
    return "no OpenCL platform installed (error " + std::to_string(err) + "; install an ICD such as pocl-opencl-icd)";
  std::vector<cl_platform_id> platforms(nplatforms);
  clGetPlatformIDs(nplatforms, platforms.data(), nullptr);
  for (cl_platform_id platform : platforms) {
    cl_uint ndevices = 0;
    if (clGetDeviceIDs(platform, CL_DEVICE_TYPE_ALL, 0, nullptr, &ndevices) == CL_SUCCESS && ndevices > 0) return {};
  }
  return "no device on any of the " + std::to_string(nplatforms) + " OpenCL platform(s)";
}

std::vector<Backend> opencl_backends(const CpuInfo& cpu) {
  std::vector<Backend> out;
  cl_uint nplatforms = 0;
  if (clGetPlatformIDs(0, nullptr, &nplatforms) != CL_SUCCESS || nplatforms == 0) return out;
  std::vector<cl_platform_id> platforms(nplatforms);
  clGetPlatformIDs(nplatforms, platforms.data(), nullptr);
  int index = 0;
  for (cl_platform_id platform : platforms) {
    cl_uint ndevices = 0;
    if (clGetDeviceIDs(platform, CL_DEVICE_TYPE_ALL, 0, nullptr, &ndevices) != CL_SUCCESS || ndevices == 0) continue;
    std::vector<cl_device_id> devices(ndevices);
    clGetDeviceIDs(platform, CL_DEVICE_TYPE_ALL, ndevices, devices.data(), nullptr);
    for (cl_device_id id : devices) {
      const auto type = device_value<cl_device_type>(id, CL_DEVICE_TYPE);
      const auto units = device_value<cl_uint>(id, CL_DEVICE_MAX_COMPUTE_UNITS);
      const auto mhz = device_value<cl_uint>(id, CL_DEVICE_MAX_CLOCK_FREQUENCY);
      Backend b;
      b.id = "opencl:" + std::to_string(index++);
      b.label = "OpenCL";
      b.device_name = device_string(id, CL_DEVICE_NAME);
      b.kind = (type & CL_DEVICE_TYPE_GPU)   ? DeviceKind::Gpu
               : (type & CL_DEVICE_TYPE_CPU) ? DeviceKind::Cpu
                                             : DeviceKind::Other;
      b.variants = {Variant::Throughput, Variant::Paper};
      b.throughput_label = "float16x4";
      b.paper_dims = {1, 2, 4};
      b.details = device_string(id, CL_DEVICE_VENDOR) + ", driver " + device_string(id, CL_DRIVER_VERSION) + ", " +
                  std::to_string(units) + " compute units, " + std::to_string(mhz) + " MHz";
      if (b.kind == DeviceKind::Cpu) {
        b.theoretical_peak_flops = cpu.peak_flops;  // a CPU device runs on the cores measured above
      } else {
        // FP32 lanes per compute unit from the vendor's architecture (OpenCL does not report it); one FMA per
        // lane per cycle, and a rotation step is 4 ops (2 mul + 2 FMA) for 6 counted flops.
        const GpuLanes lanes = gpu_lanes_per_compute_unit(id, device_string(id, CL_DEVICE_VENDOR));
        b.theoretical_peak_flops = units * static_cast<double>(lanes.lanes) * mhz * 1e6 * 6.0 / 4.0;
        b.details +=
            ", peak approximate (" + std::to_string(lanes.lanes) + " FP32 lanes per compute unit: " + lanes.why + ")";
      }
      auto device = std::make_shared<Device>(id);
      b.run_point = [device](const RotationParams& p, std::int64_t w, Variant v, std::vector<float>& outputs,
                             const CancelToken& cancel) { return device->run(p, w, v, outputs, cancel); };
      b.run_triad = [device](std::size_t n, const CancelToken& cancel) { return device->triad(n, cancel); };
      b.ceiling_kernels = [id](const CeilingSpec& spec) { return make_opencl_ceiling_kernels(id, spec); };
      out.push_back(std::move(b));
    }
  }
  return out;
}

}  // namespace bs::kernels
