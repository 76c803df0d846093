// SPDX-License-Identifier: GPL-3.0-or-later
#define CL_TARGET_OPENCL_VERSION 120
#include "vision/reproject/opencl_preprocess.h"

#include <CL/cl.h>

#include <mutex>
#include <stdexcept>
#include <vector>

namespace bs::vision {
namespace {

// Kernel 1: bilinear demosaic of one pixel, integer arithmetic rounded half up, borders reflected without
// repeating the edge (as bayer_pixel.h). cells: colour index (0 B, 1 G, 2 R) of the pattern's top-left 2x2 cell.
// Kernel 2: sample the BGR image at the LUT position on OpenCV's 1/32-pixel grid (round to nearest), bilinear
// weights, zero for neighbours outside the image (remap's BORDER_CONSTANT with fill 0).
constexpr const char* kSource = R"CLC(
int reflect1(int i, int n) { return i < 0 ? -i : (i >= n ? 2 * n - 2 - i : i); }
__kernel void demosaic_bilinear(__global const uchar* raw, __global uchar* bgr, int cols, int rows, int4 cells) {
  const int c = get_global_id(0), r = get_global_id(1);
  if (c >= cols || r >= rows) return;
  #define AT(dr, dc) ((int)raw[reflect1(r + (dr), rows) * cols + reflect1(c + (dc), cols)])
  const int cell[4] = {cells.x, cells.y, cells.z, cells.w};
  const int here = cell[(r & 1) * 2 + (c & 1)], row_colour = cell[(r & 1) * 2 + ((c + 1) & 1)];
  const int v = AT(0, 0), e = AT(0, 1), w = AT(0, -1), n = AT(-1, 0), s = AT(1, 0);
  int ch[3];
  ch[here] = v;
  if (here == 1) {
    ch[row_colour] = (w + e + 1) >> 1;
    ch[2 - row_colour] = (n + s + 1) >> 1;
  } else {
    ch[1] = (n + s + w + e + 2) >> 2;
    ch[2 - here] = (AT(-1, -1) + AT(-1, 1) + AT(1, -1) + AT(1, 1) + 2) >> 2;
  }
  __global uchar* d = bgr + 3 * (r * cols + c);
  d[0] = (uchar)ch[0]; d[1] = (uchar)ch[1]; d[2] = (uchar)ch[2];
}
__kernel void reproject(__global const uchar* bgr, int cols, int rows, __global const float2* map,
                        __global uchar* out, int out_cols, int out_rows) {
  const int x = get_global_id(0), y = get_global_id(1);
  if (x >= out_cols || y >= out_rows) return;
  const float2 p = map[y * out_cols + x];
  const int ix = (int)rint(p.x * 32.0f), iy = (int)rint(p.y * 32.0f);
  const int x0 = ix >> 5, y0 = iy >> 5;
  const float fx = (float)(ix & 31) / 32.0f, fy = (float)(iy & 31) / 32.0f;
  const float w[4] = {(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy};
  float acc[3] = {0, 0, 0};
  for (int k = 0; k < 4; ++k) {
    const int sx = x0 + (k & 1), sy = y0 + (k >> 1);
    if (sx < 0 || sy < 0 || sx >= cols || sy >= rows) continue;
    __global const uchar* s = bgr + 3 * (sy * cols + sx);
    acc[0] += w[k] * s[0]; acc[1] += w[k] * s[1]; acc[2] += w[k] * s[2];
  }
  __global uchar* d = out + 3 * (y * out_cols + x);
  d[0] = convert_uchar_sat_rte(acc[0]); d[1] = convert_uchar_sat_rte(acc[1]); d[2] = convert_uchar_sat_rte(acc[2]);
}
)CLC";

void check(cl_int err, const char* what) {
  if (err != CL_SUCCESS)
    throw std::runtime_error(std::string("OpenCL: ") + what + " failed (error " + std::to_string(err) + ")");
}

// Owns every OpenCL object of one preprocessor; released in reverse order.
struct ClState {
  cl_device_id device = nullptr;
  cl_context context = nullptr;
  cl_command_queue queue = nullptr;
  cl_program program = nullptr;
  cl_kernel demosaic = nullptr, reproject = nullptr;
  cl_mem raw = nullptr, bgr = nullptr, map = nullptr, out = nullptr;
  cv::Size source, view;
  cl_int4 cells{};
  std::mutex mutex;

  ~ClState() {
    for (cl_mem m : {raw, bgr, map, out})
      if (m) clReleaseMemObject(m);
    if (demosaic) clReleaseKernel(demosaic);
    if (reproject) clReleaseKernel(reproject);
    if (program) clReleaseProgram(program);
    if (queue) clReleaseCommandQueue(queue);
    if (context) clReleaseContext(context);
  }
};

cl_device_id pick_device(std::string& name) {
  cl_uint np = 0;
  check(clGetPlatformIDs(0, nullptr, &np), "clGetPlatformIDs");
  if (np == 0) throw std::runtime_error("OpenCL: no platform installed");
  std::vector<cl_platform_id> platforms(np);
  check(clGetPlatformIDs(np, platforms.data(), nullptr), "clGetPlatformIDs");
  cl_device_id chosen = nullptr;
  for (cl_device_type type : {cl_device_type{CL_DEVICE_TYPE_GPU}, cl_device_type{CL_DEVICE_TYPE_ALL}}) {
    for (cl_platform_id p : platforms) {
      cl_device_id d = nullptr;
      cl_uint nd = 0;
      if (clGetDeviceIDs(p, type, 1, &d, &nd) == CL_SUCCESS && nd > 0) {
        chosen = d;
        break;
      }
    }
    if (chosen) break;
  }
  if (!chosen) throw std::runtime_error("OpenCL: no device found");
  char buf[256] = {};
  clGetDeviceInfo(chosen, CL_DEVICE_NAME, sizeof buf - 1, buf, nullptr);
  name = buf;
  return chosen;
}

}  // namespace

Preprocessor make_opencl_preprocessor(const Lens& lens, const View& view, BayerPattern pattern,
                                      OpenClPreprocessorInfo* info) {
  const ReprojectionLut lut(lens, view);  // validates lens and view
  auto st = std::make_shared<ClState>();
  std::string name;
  st->device = pick_device(name);
  if (info) info->device = name;
  cl_int err = CL_SUCCESS;
  st->context = clCreateContext(nullptr, 1, &st->device, nullptr, nullptr, &err);
  check(err, "clCreateContext");
  st->queue = clCreateCommandQueue(st->context, st->device, 0, &err);
  check(err, "clCreateCommandQueue");
  const char* src = kSource;
  st->program = clCreateProgramWithSource(st->context, 1, &src, nullptr, &err);
  check(err, "clCreateProgramWithSource");
  if (clBuildProgram(st->program, 1, &st->device, "", nullptr, nullptr) != CL_SUCCESS) {
    char log[4096] = {};
    clGetProgramBuildInfo(st->program, st->device, CL_PROGRAM_BUILD_LOG, sizeof log - 1, log, nullptr);
    throw std::runtime_error(std::string("OpenCL: the preprocessing kernels do not build: ") + log);
  }
  st->demosaic = clCreateKernel(st->program, "demosaic_bilinear", &err);
  check(err, "clCreateKernel(demosaic_bilinear)");
  st->reproject = clCreateKernel(st->program, "reproject", &err);
  check(err, "clCreateKernel(reproject)");
  st->source = lut.source_size();
  st->view = lut.map().size();
  const std::size_t src_px = static_cast<std::size_t>(st->source.area()),
                    view_px = static_cast<std::size_t>(st->view.area());
  st->raw = clCreateBuffer(st->context, CL_MEM_READ_ONLY, src_px, nullptr, &err);
  check(err, "clCreateBuffer(raw)");
  st->bgr = clCreateBuffer(st->context, CL_MEM_READ_WRITE, 3 * src_px, nullptr, &err);
  check(err, "clCreateBuffer(bgr)");
  const cv::Mat map = lut.map().isContinuous() ? lut.map() : lut.map().clone();
  st->map = clCreateBuffer(st->context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, view_px * 2 * sizeof(float),
                           const_cast<uchar*>(map.data), &err);
  check(err, "clCreateBuffer(map)");
  st->out = clCreateBuffer(st->context, CL_MEM_WRITE_ONLY, 3 * view_px, nullptr, &err);
  check(err, "clCreateBuffer(out)");
  st->cells = {{bayer_channel(pattern, 0, 0), bayer_channel(pattern, 0, 1), bayer_channel(pattern, 1, 0),
                bayer_channel(pattern, 1, 1)}};
  const cl_int cols = st->source.width, rows = st->source.height, ocols = st->view.width, orows = st->view.height;
  check(clSetKernelArg(st->demosaic, 0, sizeof(cl_mem), &st->raw), "clSetKernelArg");
  check(clSetKernelArg(st->demosaic, 1, sizeof(cl_mem), &st->bgr), "clSetKernelArg");
  check(clSetKernelArg(st->demosaic, 2, sizeof(cl_int), &cols), "clSetKernelArg");
  check(clSetKernelArg(st->demosaic, 3, sizeof(cl_int), &rows), "clSetKernelArg");
  check(clSetKernelArg(st->demosaic, 4, sizeof(cl_int4), &st->cells), "clSetKernelArg");
  check(clSetKernelArg(st->reproject, 0, sizeof(cl_mem), &st->bgr), "clSetKernelArg");
  check(clSetKernelArg(st->reproject, 1, sizeof(cl_int), &cols), "clSetKernelArg");
  check(clSetKernelArg(st->reproject, 2, sizeof(cl_int), &rows), "clSetKernelArg");
  check(clSetKernelArg(st->reproject, 3, sizeof(cl_mem), &st->map), "clSetKernelArg");
  check(clSetKernelArg(st->reproject, 4, sizeof(cl_mem), &st->out), "clSetKernelArg");
  check(clSetKernelArg(st->reproject, 5, sizeof(cl_int), &ocols), "clSetKernelArg");
  check(clSetKernelArg(st->reproject, 6, sizeof(cl_int), &orows), "clSetKernelArg");

  return [st](const cv::Mat& mosaic) -> cv::Mat {
    if (mosaic.type() != CV_8UC1 || mosaic.size() != st->source)
      throw std::invalid_argument("OpenCL preprocessing needs an 8-bit mosaic of " + std::to_string(st->source.width) +
                                  "x" + std::to_string(st->source.height));
    const cv::Mat in = mosaic.isContinuous() ? mosaic : mosaic.clone();
    cv::Mat out(st->view, CV_8UC3);
    const std::lock_guard lock(st->mutex);
    const std::size_t src_global[2] = {static_cast<std::size_t>(st->source.width),
                                       static_cast<std::size_t>(st->source.height)};
    const std::size_t view_global[2] = {static_cast<std::size_t>(st->view.width),
                                        static_cast<std::size_t>(st->view.height)};
    // Upload, both kernels and the read-back in order on one in-order queue; the blocking read waits for all.
    check(clEnqueueWriteBuffer(st->queue, st->raw, CL_FALSE, 0, in.total(), in.data, 0, nullptr, nullptr),
          "clEnqueueWriteBuffer");
    check(clEnqueueNDRangeKernel(st->queue, st->demosaic, 2, nullptr, src_global, nullptr, 0, nullptr, nullptr),
          "clEnqueueNDRangeKernel(demosaic)");
    check(clEnqueueNDRangeKernel(st->queue, st->reproject, 2, nullptr, view_global, nullptr, 0, nullptr, nullptr),
          "clEnqueueNDRangeKernel(reproject)");
    check(clEnqueueReadBuffer(st->queue, st->out, CL_TRUE, 0, out.total() * 3, out.data, 0, nullptr, nullptr),
          "clEnqueueReadBuffer");
    return out;
  };
}

}  // namespace bs::vision
