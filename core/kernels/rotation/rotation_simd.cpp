// SPDX-License-Identifier: GPL-3.0-or-later
#include "kernels/rotation/rotation_simd.h"

#include "kernels/step_chunker.h"

#include <chrono>
#include <cstdlib>
#include <new>
#include <stdexcept>

namespace bs::kernels {

// Per-ISA entry points (rotation_simd_<isa>.cpp).
#define BS_DECLARE_ISA(ns)                                                                                          \
  namespace ns {                                                                                                    \
  int lanes();                                                                                                      \
  int chains();                                                                                                     \
  bool advance_throughput(float* xs, float* ys, std::int64_t nvec, std::int64_t steps, float c, float s,            \
                          bool (*cancelled)(const void*), const void* token);                                       \
  void advance_paper(float* xs, float* ys, std::int64_t workers, int stride, std::int64_t steps, float c, float s); \
  }
BS_DECLARE_ISA(generic)
#if BENCHSCOPE_X86_SIMD
BS_DECLARE_ISA(sse4)
BS_DECLARE_ISA(avx2)
BS_DECLARE_ISA(avx512)
#endif
#undef BS_DECLARE_ISA

namespace {

struct IsaFunctions {
  int (*chains)();
  bool (*throughput)(float*, float*, std::int64_t, std::int64_t, float, float, bool (*)(const void*), const void*);
  void (*paper)(float*, float*, std::int64_t, int, std::int64_t, float, float);
};

IsaFunctions functions_for(Isa isa) {
  switch (isa) {
#if BENCHSCOPE_X86_SIMD
    case Isa::Avx512:
      return {avx512::chains, avx512::advance_throughput, avx512::advance_paper};
    case Isa::Avx2:
      return {avx2::chains, avx2::advance_throughput, avx2::advance_paper};
    case Isa::Sse4:
      return {sse4::chains, sse4::advance_throughput, sse4::advance_paper};
#endif
    default:
      return {generic::chains, generic::advance_throughput, generic::advance_paper};
  }
}

// Called from inside the per-ISA kernels (which must not instantiate library templates such as std::atomic).
bool token_cancelled(const void* token) { return static_cast<const CancelToken*>(token)->cancelled(); }

float* aligned_floats(std::int64_t count) {
  const std::size_t bytes = ((static_cast<std::size_t>(count) * sizeof(float) + 63) / 64) * 64;
  void* p = std::aligned_alloc(64, bytes > 0 ? bytes : 64);
  if (!p) throw std::bad_alloc();
  return static_cast<float*>(p);
}

}  // namespace

std::string variant_name(Variant v) { return v == Variant::Paper ? "paper" : "throughput"; }

std::vector<SimdTarget> available_simd_targets() {
  std::vector<SimdTarget> out;
#if BENCHSCOPE_X86_SIMD
  __builtin_cpu_init();
  if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("fma"))
    out.push_back({Isa::Avx512, "AVX-512", 16, true});
  if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) out.push_back({Isa::Avx2, "AVX2+FMA", 8, true});
  if (__builtin_cpu_supports("sse4.1")) out.push_back({Isa::Sse4, "SSE4.1", 4, false});
  out.push_back({Isa::Generic, "generic 128-bit", 4, false});
#elif defined(__ARM_NEON)
  out.push_back({Isa::Generic, "NEON", 4, true});
#else
  out.push_back({Isa::Generic, "generic 128-bit", 4, false});
#endif
  return out;
}

SimdTarget best_simd_target() { return available_simd_targets().front(); }

std::string isa_id(Isa isa) {
  switch (isa) {
    case Isa::Avx512:
      return "avx512";
    case Isa::Avx2:
      return "avx2";
    case Isa::Sse4:
      return "sse4";
    default:
      return "generic";
  }
}

SimdTarget simd_target_by_id(const std::string& id) {
  std::string have;
  for (const SimdTarget& t : available_simd_targets()) {
    if (isa_id(t.isa) == id) return t;
    have += (have.empty() ? "" : ", ") + isa_id(t.isa);
  }
  const bool known = id == "avx512" || id == "avx2" || id == "sse4" || id == "generic";
  throw std::invalid_argument("--isa " + id + (known ? ": this CPU does not support it" : ": unknown instruction set") +
                              " (this CPU has: " + have + ")");
}

SimdRotation::Aligned::~Aligned() { std::free(p); }

SimdRotation::SimdRotation(const SimdTarget& target, Variant variant, const RotationParams& params,
                           std::int64_t workers)
    : target_(target), variant_(variant), params_(params), workers_(workers) {
  check_problem_size(params, workers);
  std::int64_t floats = 0;
  if (variant == Variant::Paper) {
    stride_ = (params.dims + 3) / 4 * 4;
    floats = workers * stride_;
  } else {
    const std::int64_t points = workers * params.dims;
    const std::int64_t per_block = static_cast<std::int64_t>(target.lanes) * functions_for(target.isa).chains();
    vectors_ = (points + per_block - 1) / per_block * functions_for(target.isa).chains();
    floats = vectors_ * target.lanes;
  }
  xs_.p = aligned_floats(floats);
  ys_.p = aligned_floats(floats);
  // Every lane starts at x0 = (1, 0); padding lanes rotate too and are simply not read back.
  for (std::int64_t i = 0; i < floats; ++i) {
    xs_.p[i] = 1.0f;
    ys_.p[i] = 0.0f;
  }
}

void SimdRotation::advance(std::int64_t steps) {
  const IsaFunctions f = functions_for(target_.isa);
  if (variant_ == Variant::Paper)
    f.paper(xs_.p, ys_.p, workers_, static_cast<int>(stride_), steps, rotation_cos(), rotation_sin());
  else
    f.throughput(xs_.p, ys_.p, vectors_, steps, rotation_cos(), rotation_sin(), nullptr, nullptr);
}

void SimdRotation::run(std::int64_t steps, const CancelToken& cancel) {
  if (variant_ == Variant::Throughput) {
    cancel.throw_if_cancelled();
    if (!functions_for(target_.isa)
             .throughput(xs_.p, ys_.p, vectors_, steps, rotation_cos(), rotation_sin(), token_cancelled, &cancel))
      throw Cancelled();
    return;
  }
  // Paper variant: one OpenMP task per worker and chunk; chunks of ~40 ms keep it cancellable.
  StepChunker chunks(steps, workers_ * params_.dims);
  while (!chunks.done()) {
    cancel.throw_if_cancelled();
    const std::int64_t n = chunks.next();
    const auto t0 = std::chrono::steady_clock::now();
    advance(n);
    chunks.completed(n, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
}

void SimdRotation::outputs(std::span<float> out) const {
  const std::int64_t stride = variant_ == Variant::Paper ? stride_ : params_.dims;
  for (std::int64_t w = 0; w < workers_ && w < static_cast<std::int64_t>(out.size()); ++w) {
    float sum = 0;
    for (int d = 0; d < params_.dims; ++d) sum += xs_.p[w * stride + d] + ys_.p[w * stride + d];
    out[static_cast<std::size_t>(w)] = sum;
  }
}

}  // namespace bs::kernels
