// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Empirical ceilings of a CUDA GPU (ceilings_cuda.cu), the device twins of the CPU's (kernels/ceilings.h): pure FMA,
// the rotation kernel's instruction mix, and device-memory copy bandwidth, each timed on the device (CUDA events)
// over a grid that fills every SM as far as the kernel's registers allow, and each checked:
//  - FMA: acc = acc * 1 + 2^-10 on 8 chains per thread, every value exactly representable, so every thread's
//    final accumulators must equal start + steps * 2^-10 exactly (a skipped step is a wrong value);
//  - rotation mix: t = s y; y = fma(s, x, c y); x = fma(c, x, -t) (2 MUL + 2 FMA = 6 counted flops per
//    point-step) on 4, 8 or 16 independent points per thread, the fastest count kept; every point's final angle
//    and norm must be those of the counted steps;
//  - copy: one kernel copying float4s between two buffers of `mib` MiB (2 x mib MiB moved per pass), the target
//    cleared before and compared with the source on the device after.
// Plain C++: callers need no CUDA headers. Throws std::runtime_error naming the CUDA call or the failed check.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

namespace bs::kernels::cuda {

struct CeilingRun {
  double work = 0;     // flops or bytes
  double seconds = 0;  // device time of the timed launches (CUDA events)
  double rate() const { return seconds > 0 ? work / seconds : 0; }
};

class CeilingKernels {
 public:
  // Sizes each FLOP kernel's steps to about `target_seconds` per repetition (probing first) and allocates the copy
  // buffers (`copy_mib` each, 0: 256 MiB, at most an eighth of the free device memory).
  CeilingKernels(int device, double target_seconds = 0.1, std::size_t copy_mib = 0);
  ~CeilingKernels();
  CeilingKernels(const CeilingKernels&) = delete;
  CeilingKernels& operator=(const CeilingKernels&) = delete;

  CeilingRun fma();
  CeilingRun rotation_mix();  // the fastest of the chain counts, each run once
  CeilingRun copy();
  int last_mix_points() const { return last_mix_points_; }  // points per thread of the last fastest count
  std::string fma_how() const;
  std::string mix_how() const;
  std::string copy_how() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  int last_mix_points_ = 0;
};

}  // namespace bs::kernels::cuda
