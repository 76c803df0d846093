// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The paper's FLOPS kernel (rotation, the CPU SIMD backend, throughput variant) as a headroom load: W workers
// rotating D points N times, point after point, until stopped. Reports the GFLOPS it achieved (6 D N W / t summed
// over the points it ran), so "the 1 kHz loop beside 40 GFLOPS of compute" is one line.
#include <atomic>
#include <cstdint>
#include <string>
#include <thread>

#include "headroom/load.h"

namespace bs::headroom {

struct KernelLoadConfig {
  std::int64_t workers = 0;          // W; 0: this machine's hardware threads x 32 (a few OpenMP chunks per thread)
  int dims = 4;                      // D
  std::int64_t iterations = 40'000;  // N
};

class KernelLoad : public Load {
 public:
  explicit KernelLoad(KernelLoadConfig config);
  ~KernelLoad() override;
  std::string name() const override;  // "flops:W" (W as asked; "flops" for the default)
  LoadKind kind() const override { return LoadKind::Kernels; }
  std::string detail() const override;
  std::string rate_unit() const override { return "GFLOPS"; }
  void start() override;
  LoadReport stop() override;
  std::optional<double> work_done() const override { return gflop_done_.load(); }  // GFLOP of completed points

 private:
  KernelLoadConfig config_;
  bool default_workers_ = false;
  std::atomic<bool> stop_{false};
  std::thread thread_;
  double flops_ = 0, seconds_ = 0;
  std::int64_t points_ = 0;
  std::atomic<double> gflop_done_{0};  // flops_ / 1e9, published point by point for work_done()
  std::string backend_label_, error_;
};

}  // namespace bs::headroom
