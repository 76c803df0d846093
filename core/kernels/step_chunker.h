// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Splits one sweep point's N rotation steps into chunks of about `target_seconds` each, so a cancel is seen between
// chunks whatever the device's speed: a fixed chunk size cannot serve both a latency-bound paper kernel on PoCL
// (~4 GFLOPS) and a GPU (~10 TFLOPS). The first chunk is small; after each one the measured rate sizes the next.
// Header-only so the CUDA translation unit (compiled by nvcc, linked below the kernels library) can use it.
#include <algorithm>
#include <cstdint>

namespace bs::kernels {

class StepChunker {
 public:
  // `points` = W * D 2D points advanced per step; the first chunk is ~1e6 point-steps (well under 10 ms on any
  // device that runs this kernel at >= 0.6 GFLOPS).
  StepChunker(std::int64_t total_steps, std::int64_t points, double target_seconds = 0.04)
      : remaining_(total_steps), target_(target_seconds) {
    next_ = std::clamp<std::int64_t>(kFirstPointSteps / std::max<std::int64_t>(points, 1), 1, kMaxChunk);
  }

  bool done() const { return remaining_ <= 0; }
  std::int64_t next() const { return std::min(next_, remaining_); }

  // Records that `steps` steps took `seconds`; sizes the next chunk to the target at that rate, growing at most
  // 8x at a time (a first chunk too short to time well must not jump past the target).
  void completed(std::int64_t steps, double seconds) {
    remaining_ -= steps;
    std::int64_t wanted = next_ * kMaxGrowth;
    if (seconds > 0) {
      const double at_rate = static_cast<double>(steps) * target_ / seconds;
      wanted = std::min<std::int64_t>(
          wanted, at_rate >= static_cast<double>(kMaxChunk) ? kMaxChunk : static_cast<std::int64_t>(at_rate));
    }
    next_ = std::clamp<std::int64_t>(wanted, 1, kMaxChunk);
  }

  static constexpr std::int64_t kFirstPointSteps = 1'000'000;
  static constexpr std::int64_t kMaxGrowth = 8;
  static constexpr std::int64_t kMaxChunk = std::int64_t{1} << 30;  // fits the kernels' int step argument

 private:
  std::int64_t remaining_;
  std::int64_t next_ = 1;
  double target_;
};

}  // namespace bs::kernels
