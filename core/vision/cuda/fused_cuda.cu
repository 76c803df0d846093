// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/cuda/fused_cuda.h"

#include <stdexcept>
#include <string>

#include "vision/reproject/fused_pixel.h"

namespace bs::vision::cuda {
namespace {

void check(cudaError_t e, const char* what) {
  if (e != cudaSuccess) throw std::runtime_error(std::string("CUDA: ") + what + ": " + cudaGetErrorString(e));
}

// One thread per output pixel. The map is read once, coalesced (8 bytes per thread); the 4x4 mosaic window of
// neighbouring threads overlaps, so the mosaic reads hit L1/L2 and no intermediate RGB frame is written.
__global__ void fused_kernel(fused_pixel::Mosaic m, const float2* __restrict__ map, int out_width, int out_height,
                             uchar3 fill, std::uint8_t* __restrict__ bgr) {
  const int x = blockIdx.x * blockDim.x + threadIdx.x, y = blockIdx.y * blockDim.y + threadIdx.y;
  if (x >= out_width || y >= out_height) return;
  const std::size_t i = static_cast<std::size_t>(y) * out_width + x;
  const float2 p = map[i];
  const std::uint8_t f[3] = {fill.x, fill.y, fill.z};
  std::uint8_t out[3];
  fused_pixel::sample(m, p.x, p.y, f, out);
  bgr[3 * i] = out[0];
  bgr[3 * i + 1] = out[1];
  bgr[3 * i + 2] = out[2];
}

}  // namespace

DeviceStatus device_status() {
  DeviceStatus s;
  int count = 0;
  const cudaError_t e = cudaGetDeviceCount(&count);
  if (e != cudaSuccess) {
    s.why = std::string("the CUDA runtime found no usable device (") + cudaGetErrorString(e) + ")";
    cudaGetLastError();  // clear the sticky error for later calls
    return s;
  }
  if (count == 0) {
    s.why = "the CUDA runtime sees no GPU";
    return s;
  }
  cudaDeviceProp prop{};
  if (cudaGetDeviceProperties(&prop, 0) != cudaSuccess) {
    s.why = "cudaGetDeviceProperties failed";
    return s;
  }
  s.available = true;
  s.name = std::string(prop.name) + " (cc " + std::to_string(prop.major) + "." + std::to_string(prop.minor) + ")";
  return s;
}

struct FusedCuda::Impl {
  fused_pixel::Mosaic mosaic{};
  int out_width = 0, out_height = 0;
  uchar3 fill{};
  float2* map = nullptr;
  std::uint8_t* raw = nullptr;
  std::uint8_t* bgr = nullptr;
  std::string name;
  ~Impl() {
    cudaFree(map);
    cudaFree(raw);
    cudaFree(bgr);
  }
};

FusedCuda::FusedCuda(const float* map, int out_width, int out_height, int source_width, int source_height,
                     const int layout[4], const std::uint8_t fill[3])
    : impl_(std::make_unique<Impl>()) {
  const DeviceStatus status = device_status();
  if (!status.available) throw std::runtime_error("CUDA: " + status.why);
  check(cudaSetDevice(0), "cudaSetDevice");
  Impl& d = *impl_;
  d.name = status.name;
  d.out_width = out_width;
  d.out_height = out_height;
  d.fill = make_uchar3(fill[0], fill[1], fill[2]);
  const std::size_t out_px = static_cast<std::size_t>(out_width) * out_height;
  const std::size_t src_px = static_cast<std::size_t>(source_width) * source_height;
  check(cudaMalloc(&d.map, out_px * sizeof(float2)), "cudaMalloc(map)");
  check(cudaMalloc(&d.raw, src_px), "cudaMalloc(mosaic)");
  check(cudaMalloc(&d.bgr, 3 * out_px), "cudaMalloc(bgr)");
  check(cudaMemcpy(d.map, map, out_px * sizeof(float2), cudaMemcpyHostToDevice), "cudaMemcpy(map)");
  d.mosaic.data = d.raw;
  d.mosaic.width = source_width;
  d.mosaic.height = source_height;
  d.mosaic.stride = source_width;
  for (int k = 0; k < 4; ++k) d.mosaic.layout[k] = layout[k];
}

FusedCuda::~FusedCuda() = default;

const std::string& FusedCuda::device_name() const { return impl_->name; }

void FusedCuda::run(const std::uint8_t* mosaic, std::size_t stride, std::uint8_t* bgr) {
  upload(mosaic, stride);
  compute();
  download(bgr);
}

void FusedCuda::upload(const std::uint8_t* mosaic, std::size_t stride) {
  Impl& d = *impl_;
  const std::size_t row = static_cast<std::size_t>(d.mosaic.width);
  check(
      cudaMemcpy2D(d.raw, row, mosaic, stride, row, static_cast<std::size_t>(d.mosaic.height), cudaMemcpyHostToDevice),
      "cudaMemcpy2D(mosaic)");
}

namespace {
void launch(const fused_pixel::Mosaic& m, const float2* map, int w, int h, uchar3 fill, std::uint8_t* bgr) {
  const dim3 block(32, 8);
  const dim3 grid((w + block.x - 1) / block.x, (h + block.y - 1) / block.y);
  fused_kernel<<<grid, block>>>(m, map, w, h, fill, bgr);
  check(cudaGetLastError(), "fused_kernel launch");
}
}  // namespace

void FusedCuda::compute() {
  Impl& d = *impl_;
  launch(d.mosaic, d.map, d.out_width, d.out_height, d.fill, d.bgr);
  check(cudaDeviceSynchronize(), "fused_kernel");
}

void FusedCuda::download(std::uint8_t* bgr) {
  Impl& d = *impl_;
  check(cudaMemcpy(bgr, d.bgr, 3 * static_cast<std::size_t>(d.out_width) * d.out_height, cudaMemcpyDeviceToHost),
        "cudaMemcpy(bgr)");
}

double FusedCuda::kernel_seconds(int launches) {
  Impl& d = *impl_;
  if (launches < 1) throw std::invalid_argument("kernel_seconds needs at least one launch");
  cudaEvent_t start{}, stop{};
  check(cudaEventCreate(&start), "cudaEventCreate");
  check(cudaEventCreate(&stop), "cudaEventCreate");
  struct Destroy {
    cudaEvent_t a, b;
    ~Destroy() {
      cudaEventDestroy(a);
      cudaEventDestroy(b);
    }
  } destroy{start, stop};
  check(cudaDeviceSynchronize(), "cudaDeviceSynchronize");
  check(cudaEventRecord(start), "cudaEventRecord");
  for (int i = 0; i < launches; ++i) launch(d.mosaic, d.map, d.out_width, d.out_height, d.fill, d.bgr);
  check(cudaEventRecord(stop), "cudaEventRecord");
  check(cudaEventSynchronize(stop), "fused_kernel");
  float ms = 0;
  check(cudaEventElapsedTime(&ms, start, stop), "cudaEventElapsedTime");
  return ms * 1e-3 / launches;
}

double FusedCuda::kernel_bytes() const {
  const Impl& d = *impl_;
  const double out_px = static_cast<double>(d.out_width) * d.out_height;
  return out_px * (sizeof(float2) + 3) + static_cast<double>(d.mosaic.width) * d.mosaic.height;
}

}  // namespace bs::vision::cuda
