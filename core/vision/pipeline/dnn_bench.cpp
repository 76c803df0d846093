// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/pipeline/dnn_bench.h"

#include <chrono>
#include <cstdlib>
#include <functional>
#include <stdexcept>

#include <opencv2/core/ocl.hpp>
#include <opencv2/dnn/shape_utils.hpp>

namespace bs::vision {

DnnFlops count_flops(const cv::dnn::Net& net, const cv::dnn::MatShape& input_shape) {
  DnnFlops f;
  f.opencv = net.getFLOPS(input_shape);
  // Net::getLayerId and getLayer only read, but OpenCV 4.5 (Ubuntu 22.04, JetPack 5) declares them non-const.
  cv::dnn::Net& queried = const_cast<cv::dnn::Net&>(net);
  for (const std::string& name : net.getLayerNames()) {
    const int id = queried.getLayerId(name);
    const cv::Ptr<cv::dnn::Layer> layer = queried.getLayer(id);
    const std::int64_t theirs = net.getFLOPS(id, input_shape);
    if (layer->type != "Convolution" || layer->blobs.empty() || layer->blobs[0].dims != 4) {
      f.counted += theirs;
      continue;
    }
    std::vector<cv::dnn::MatShape> in, out;
    net.getLayerShapes(input_shape, id, in, out);
    const cv::Mat& w = layer->blobs[0];  // out_c x (in_c / group) x kh x kw
    const std::int64_t macs_per_output = static_cast<std::int64_t>(w.size[1]) * w.size[2] * w.size[3];
    for (const cv::dnn::MatShape& o : out)
      f.counted +=
          static_cast<std::int64_t>(cv::dnn::total(o)) * (2 * macs_per_output + (layer->blobs.size() > 1 ? 1 : 0));
  }
  return f;
}

namespace {

bool has_target(cv::dnn::Backend b, cv::dnn::Target t) {
  for (const cv::dnn::Target x : cv::dnn::getAvailableTargets(b))
    if (x == t) return true;
  return false;
}

}  // namespace

DnnTarget dnn_target(const std::string& id) {
  DnnTarget t;
  t.id = id;
  if (id == "cpu") {
    t.backend = cv::dnn::DNN_BACKEND_OPENCV;
    t.target = cv::dnn::DNN_TARGET_CPU;
    t.device = "CPU (" + std::to_string(cv::getNumThreads()) + " OpenCV threads)";
    t.available = true;
    return t;
  }
  if (id == "opencl") {
    t.backend = cv::dnn::DNN_BACKEND_OPENCV;
    t.target = cv::dnn::DNN_TARGET_OPENCL;
    if (!cv::ocl::haveOpenCL()) {
      t.why_not = "OpenCV finds no OpenCL platform";
      return t;
    }
    const cv::ocl::Device& d = cv::ocl::Device::getDefault();
    t.device = d.available() ? d.name() + " (OpenCL)" : std::string();
    if (!has_target(cv::dnn::DNN_BACKEND_OPENCV, cv::dnn::DNN_TARGET_OPENCL) || !d.available()) {
      // OpenCV picks its device by OPENCV_OPENCL_DEVICE, GPUs only by default: name what the platforms hold.
      std::vector<cv::ocl::PlatformInfo> platforms;
      cv::ocl::getPlatfomsInfo(platforms);
      std::string devices;
      for (const cv::ocl::PlatformInfo& p : platforms)
        for (int i = 0; i < p.deviceNumber(); ++i) {
          cv::ocl::Device dev;
          p.getDevice(dev, i);
          devices += (devices.empty() ? "" : ", ") + dev.name() +
                     (dev.type() == cv::ocl::Device::TYPE_GPU ? " (GPU, " : " (not a GPU, ") + p.name() + ")";
        }
      t.why_not = "OpenCV selected no OpenCL device (by default it takes GPUs only; OpenCL devices here: " +
                  (devices.empty() ? std::string("none") : devices) +
                  "); OPENCV_OPENCL_DEVICE=:CPU: selects a CPU device";
      return t;
    }
    // OpenCV's dnn silently runs an OpenCL target on the CPU path unless the device is an Intel GPU or the user
    // allows every device; say so rather than time the CPU under the OpenCL name.
    const char* allow = std::getenv("OPENCV_DNN_OPENCL_ALLOW_ALL_DEVICES");
    const bool allowed = allow && std::string(allow) != "0" && std::string(allow) != "";
    if (!(d.isIntel() && d.type() == cv::ocl::Device::TYPE_GPU) && !allowed) {
      t.why_not = "OpenCV " CV_VERSION "'s dnn uses OpenCL only on Intel GPUs and would fall back to the CPU on '" +
                  d.name() + "' (" + d.vendorName() +
                  "); set OPENCV_DNN_OPENCL_ALLOW_ALL_DEVICES=1 to time that device anyway";
      return t;
    }
    t.available = true;
    return t;
  }
  if (id == "cuda") {
    t.backend = cv::dnn::DNN_BACKEND_CUDA;
    t.target = cv::dnn::DNN_TARGET_CUDA;
    if (!has_target(cv::dnn::DNN_BACKEND_CUDA, cv::dnn::DNN_TARGET_CUDA)) {
      t.why_not = "this OpenCV (" CV_VERSION ") was built without CUDA in its dnn module (Debian's never has it)";
      return t;
    }
    t.device = "CUDA GPU";
    t.available = true;
    return t;
  }
  throw std::invalid_argument("unknown dnn target '" + id + "' (expected cpu, opencl or cuda)");
}

std::vector<DnnTarget> dnn_targets() { return {dnn_target("cpu"), dnn_target("opencl"), dnn_target("cuda")}; }

std::vector<double> time_forward(cv::dnn::Net& net, const DnnTarget& t, const cv::Mat& blob, int warmup, int runs,
                                 const CancelToken& cancel, const std::function<void()>& on_timed_start) {
  if (!t.available) throw std::runtime_error("dnn target " + t.id + " is not available: " + t.why_not);
  net.setPreferableBackend(t.backend);
  net.setPreferableTarget(t.target);
  std::vector<cv::Mat> outs;
  const std::vector<std::string> names = net.getUnconnectedOutLayersNames();
  for (int i = 0; i < warmup && !cancel.cancelled(); ++i) {
    net.setInput(blob);
    net.forward(outs, names);
  }
  if (on_timed_start) on_timed_start();
  std::vector<double> seconds;
  for (int i = 0; i < runs && !cancel.cancelled(); ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    net.setInput(blob);
    net.forward(outs, names);
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  return seconds;
}

}  // namespace bs::vision
