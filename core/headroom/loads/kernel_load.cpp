// SPDX-License-Identifier: GPL-3.0-or-later
#include "headroom/loads/kernel_load.h"

#include <stdexcept>
#include <thread>
#include <vector>

#include "analysis/peaks/flops.h"
#include "headroom/loads/worker_thread.h"
#include "kernels/backends/backend.h"
#include "kernels/cpu/cpu_info.h"
#include "kernels/rotation/rotation.h"
#include "kernels/rotation/rotation_simd.h"

namespace bs::headroom {

KernelLoad::KernelLoad(KernelLoadConfig config) : config_(config) {
  default_workers_ = config_.workers == 0;
  if (default_workers_) config_.workers = std::max(1u, std::thread::hardware_concurrency()) * 32;
  if (config_.workers < 1 || config_.workers > (std::int64_t{1} << 24))
    throw std::invalid_argument("flops load: workers must be 1 .. 16777216");
  kernels::check_problem_size({config_.dims, config_.iterations}, config_.workers);  // throws std::invalid_argument
}

KernelLoad::~KernelLoad() {
  stop_ = true;
  if (thread_.joinable()) thread_.join();
}

std::string KernelLoad::name() const {
  return default_workers_ ? std::string("flops") : "flops:" + std::to_string(config_.workers);
}

std::string KernelLoad::detail() const {
  return "rotation kernel, CPU SIMD backend, throughput variant: W = " + std::to_string(config_.workers) +
         " workers, D = " + std::to_string(config_.dims) + ", N = " + std::to_string(config_.iterations) +
         (backend_label_.empty() ? std::string() : " (" + backend_label_ + ")");
}

void KernelLoad::start() {
  stop_ = false;
  gflop_done_ = 0;
  // Without clock calibration: a load needs the kernel, not the peak (calibrating would take 0.2 s per phase).
  const kernels::CpuInfo cpu = kernels::detect_cpu(false);
  const std::vector<kernels::Backend> backends = kernels::cpu_backends(cpu);
  const kernels::Backend& backend = kernels::find_backend(backends, "cpu-simd");
  backend_label_ = backend.label;
  thread_ = std::thread([this, backend] {
    try {
      CancelToken never;
      std::vector<float> outputs;
      const kernels::RotationParams params{config_.dims, config_.iterations};
      while (!stop_) {
        const double s = backend.run_point(params, config_.workers, kernels::Variant::Throughput, outputs, never);
        seconds_ += s;
        flops_ += rotation_flops(config_.dims, config_.iterations, config_.workers, s) * s;
        gflop_done_.store(flops_ / 1e9);
        ++points_;
      }
    } catch (const std::exception& e) {
      error_ = e.what();
    }
  });
}

LoadReport KernelLoad::stop() {
  stop_ = true;
  if (auto failed = join_worker(thread_, error_, "kernel")) return *failed;
  LoadReport r;
  if (seconds_ > 0) r.achieved_rate = flops_ / seconds_ / 1e9;
  r.notes.push_back(std::to_string(points_) + " kernel points");
  return r;
}

}  // namespace bs::headroom
