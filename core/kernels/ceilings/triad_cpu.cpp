// SPDX-License-Identifier: GPL-3.0-or-later
#include "kernels/ceilings/triad_cpu.h"

#include <chrono>
#include <cmath>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>

#include <omp.h>

namespace bs::kernels {
namespace {

struct FreeDeleter {
  void operator()(float* p) const noexcept { std::free(p); }
};
using Buffer = std::unique_ptr<float[], FreeDeleter>;

Buffer allocate(std::size_t elements) {
  // 64-byte alignment: whole cache lines, aligned vector loads.
  const std::size_t bytes = (elements * sizeof(float) + 63) / 64 * 64;
  auto* p = static_cast<float*>(std::aligned_alloc(64, bytes));
  if (!p) throw std::invalid_argument("cannot allocate " + std::to_string(bytes >> 20) + " MiB for the triad");
  return Buffer(p);
}

}  // namespace

double cpu_triad_seconds(std::size_t elements, bool all_threads, const CancelToken& cancel) {
  if (elements == 0) throw std::invalid_argument("triad needs at least one element");
  Buffer a = allocate(elements), b = allocate(elements), c = allocate(elements);
  const auto n = static_cast<std::int64_t>(elements);
  const int threads = all_threads ? omp_get_max_threads() : 1;
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::int64_t i = 0; i < n; ++i) {
    a[i] = 0.0f;
    b[i] = 1.0f + static_cast<float>(i % 7);
    c[i] = 2.0f;
  }
  cancel.throw_if_cancelled();
  const float q = 3.0f;
  const auto t0 = std::chrono::steady_clock::now();
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::int64_t i = 0; i < n; ++i) a[i] = b[i] + q * c[i];
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  // Verified, so a compiler cannot drop the loop and a broken build cannot report a bandwidth.
  for (std::int64_t i = 0; i < n; i += 4093)
    if (a[i] != 1.0f + static_cast<float>(i % 7) + 6.0f) throw std::runtime_error("triad: wrong result");
  return seconds;
}

}  // namespace bs::kernels
