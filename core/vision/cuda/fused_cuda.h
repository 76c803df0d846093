// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Host interface of the CUDA preprocessing kernel (fused_cuda.cu): the fused demosaic + reprojection with one
// thread per output pixel, running fused_pixel.h's sample() (bit-identical to the CPU's FusedTable). Plain C++:
// callers need neither CUDA nor OpenCV headers.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

namespace bs::vision::cuda {

// The device the kernel runs on (the first one), or why there is none (no driver, no GPU).
struct DeviceStatus {
  bool available = false;
  std::string name;  // e.g. "NVIDIA H100 80GB HBM3 (cc 9.0)"
  std::string why;   // when not available
};
DeviceStatus device_status();

class FusedCuda {
 public:
  // map: out_width * out_height (x, y) float pairs, row-major (a CV_32FC2 lookup table); negative = no source.
  // layout: colour (0 B, 1 G, 2 R) at mosaic parity (row & 1) * 2 + (col & 1). Uploads the map once.
  // Throws std::runtime_error naming the failing CUDA call (no device, out of memory).
  FusedCuda(const float* map, int out_width, int out_height, int source_width, int source_height, const int layout[4],
            const std::uint8_t fill[3]);
  ~FusedCuda();
  FusedCuda(const FusedCuda&) = delete;
  FusedCuda& operator=(const FusedCuda&) = delete;

  // mosaic: source_height rows of `stride` bytes; bgr: out_width * out_height * 3 bytes, contiguous. Blocking:
  // upload(), compute(), download().
  void run(const std::uint8_t* mosaic, std::size_t stride, std::uint8_t* bgr);
  // The three steps of run(), so a benchmark can time the kernel alone and the transfers apart.
  void upload(const std::uint8_t* mosaic, std::size_t stride);
  void compute();  // the kernel on the uploaded mosaic; blocking
  void download(std::uint8_t* bgr);
  // Device time (CUDA events) of `launches` back-to-back kernels on the uploaded mosaic, per launch, in seconds.
  double kernel_seconds(int launches);
  // Bytes one kernel reads and writes at the least: the map (8 per output pixel), the BGR output (3 per output
  // pixel) and every mosaic byte once; over kernel_seconds() this is the device-memory bandwidth it reaches.
  double kernel_bytes() const;
  const std::string& device_name() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace bs::vision::cuda
