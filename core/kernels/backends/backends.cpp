// SPDX-License-Identifier: GPL-3.0-or-later
#include <stdexcept>

#include "kernels/backends/backend.h"
#include "kernels/backends/backend_opencl.h"
#if BENCHSCOPE_WITH_CUDA
#include "kernels/cuda/ceilings_cuda.h"
#include "kernels/cuda/rotation_cuda.h"
#endif

namespace bs::kernels {

#if BENCHSCOPE_WITH_CUDA
namespace {

// cuda::CeilingKernels (ceilings_cuda.cu) behind the DeviceCeilingKernels interface.
class CudaCeilings final : public DeviceCeilingKernels {
 public:
  CudaCeilings(int device, const CeilingSpec& spec) : k_(device, spec.device_target_seconds, spec.device_copy_mib) {}
  CeilingSample fma() override { return sample(k_.fma()); }
  CeilingSample rotation_mix() override { return sample(k_.rotation_mix()); }
  CeilingSample bandwidth() override { return sample(k_.copy()); }
  std::string fma_how() const override { return k_.fma_how(); }
  std::string mix_how() const override { return k_.mix_how(); }
  std::string bandwidth_how() const override { return k_.copy_how(); }

 private:
  static CeilingSample sample(const cuda::CeilingRun& r) { return {r.work, r.seconds, 0}; }
  cuda::CeilingKernels k_;
};

}  // namespace
#endif

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
    b.ceiling_kernels = [index](const CeilingSpec& spec) -> std::unique_ptr<DeviceCeilingKernels> {
      return std::make_unique<CudaCeilings>(index, spec);
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
