// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The rotation kernel on this CPU's best vector unit (AVX-512, AVX2+FMA, SSE4.1, or 128-bit generic = NEON on
// ARM), chosen at run time, with OpenMP threads. State lives in arrays so a long point can run in chunks and
// be cancelled between them.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "kernels/rotation/rotation.h"
#include "util/cancel.h"

namespace bs::kernels {

enum class Isa { Generic, Sse4, Avx2, Avx512 };
enum class Variant { Paper, Throughput };
std::string variant_name(Variant v);  // "paper", "throughput"

struct SimdTarget {
  Isa isa = Isa::Generic;
  std::string name;  // "AVX-512", "AVX2+FMA", "SSE4.1", "NEON" / "generic 128-bit"
  int lanes = 4;     // floats per vector
  bool fma = false;
};
SimdTarget best_simd_target();                     // the widest this CPU supports
std::vector<SimdTarget> available_simd_targets();  // best first
// Short ids for forcing the dispatch (`--isa`): "avx512", "avx2", "sse4", "generic".
std::string isa_id(Isa isa);
// The target with that id if this CPU supports it; std::invalid_argument naming the ids this CPU has otherwise.
SimdTarget simd_target_by_id(const std::string& id);

class SimdRotation {
 public:
  SimdRotation(const SimdTarget& target, Variant variant, const RotationParams& params, std::int64_t workers);
  void advance(std::int64_t steps);  // all points, `steps` more rotations
  // The same, polling `cancel` at least every ~40 ms of work; throws Cancelled (the state is then unusable).
  // Throughput: one parallel region for all steps; paper: one task per worker and chunk of steps.
  void run(std::int64_t steps, const CancelToken& cancel);
  void outputs(std::span<float> out) const;  // one per worker: sum over its D points of (x + y)

 private:
  struct Aligned {
    float* p = nullptr;
    ~Aligned();
  };
  SimdTarget target_;
  Variant variant_;
  RotationParams params_;
  std::int64_t workers_;
  std::int64_t stride_ = 0;   // paper: floats per worker (D rounded up to 4)
  std::int64_t vectors_ = 0;  // throughput: vectors of state, a multiple of the chain count
  Aligned xs_, ys_;
};

}  // namespace bs::kernels
