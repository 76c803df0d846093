// SPDX-License-Identifier: GPL-3.0-or-later
#include <stdexcept>

#include "kernels/backend.h"
#include "kernels/backend_opencl.h"
#if BENCHSCOPE_WITH_CUDA
#include "kernels/cuda/rotation_cuda.h"
#endif

namespace bs::kernels {

std::vector<Backend> available_backends(const CpuInfo& cpu) {
  std::vector<Backend> all = cpu_backends(cpu);
  for (Backend& b : opencl_backends(cpu)) all.push_back(std::move(b));
#if BENCHSCOPE_WITH_CUDA
  for (const cuda::DeviceInfo& d : cuda::devices()) {
    Backend b;
    b.id = "cuda:" + std::to_string(d.index);
    b.label = "CUDA";
    b.device_name = d.name;
    b.kind = DeviceKind::Gpu;
    b.variants = {Variant::Throughput, Variant::Paper};
    b.throughput_label = "float4x4";
    b.paper_dims = {1, 2, 4};
    // One FMA per lane per cycle; a rotation step is 4 ops for 6 counted flops.
    b.theoretical_peak_flops =
        d.multiprocessors * static_cast<double>(d.fp32_lanes_per_sm) * d.clock_khz * 1e3 * 6.0 / 4.0;
    b.details = std::to_string(d.multiprocessors) + " SMs x " + std::to_string(d.fp32_lanes_per_sm) + " lanes, " +
                std::to_string(d.clock_khz / 1000) + " MHz, compute capability " + std::to_string(d.cc_major) + "." +
                std::to_string(d.cc_minor);
    const int index = d.index;
    b.run_point = [index](const RotationParams& p, std::int64_t w, Variant v, std::vector<float>& out,
                          const CancelToken& cancel) {
      check_problem_size(p, w);
      return cuda::run_point(index, p.dims, p.iterations, w, v == Variant::Paper, out, cancel);
    };
    all.push_back(std::move(b));
  }
#endif
  return all;
}

std::vector<std::string> unavailable_backends() {
  std::vector<std::string> out;
  if (const std::string why = opencl_unavailable_reason(); !why.empty()) out.push_back("opencl: " + why);
#if BENCHSCOPE_WITH_CUDA
  std::string why;
  if (cuda::devices(&why).empty()) out.push_back("cuda: compiled, no CUDA device (" + why + ")");
#else
  out.push_back("cuda: this build has no CUDA (nvcc was not found at configure time)");
#endif
  return out;
}

const Backend& find_backend(const std::vector<Backend>& backends, const std::string& id) {
  const std::string wanted = id == "cpu" ? "cpu-simd" : id == "opencl" ? "opencl:0" : id == "cuda" ? "cuda:0" : id;
  for (const Backend& b : backends)
    if (b.id == wanted) return b;
  std::string known;
  for (const Backend& b : backends) known += " " + b.id;
  std::string missing;
  for (const std::string& why : unavailable_backends()) missing += "; " + why;
  throw std::invalid_argument("no backend '" + id + "' on this machine (available:" + known + missing + ")");
}

}  // namespace bs::kernels
