// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/pipeline/dnn_architectures.h"

#include "vision/pipeline/dnn_decode.h"

#include <cmath>
#include <memory>
#include <mutex>
#include <random>
#include <stdexcept>
#include <vector>

namespace bs::vision {

const char* to_string(DnnArchitecture a) { return a == DnnArchitecture::MobileNetSsd ? "mobilenet-ssd" : "yolo-n"; }

std::optional<DnnArchitecture> architecture_from_string(std::string_view s) {
  if (s == "mobilenet-ssd") return DnnArchitecture::MobileNetSsd;
  if (s == "yolo-n") return DnnArchitecture::YoloN;
  return std::nullopt;
}

namespace {

// A layer's output: its id and output number, with the channel count the next layer needs for its weights.
struct Tensor {
  int layer = 0, pin = 0, channels = 0;
};

class Builder {
 public:
  explicit Builder(unsigned seed) : rng_(seed) { net_.setInputsNames({"data"}); }
  Tensor input(int channels) const { return {0, 0, channels}; }

  // Convolution (+ bias), optionally followed by an activation ("ReLU6", "Swish", "" for none).
  Tensor conv(const Tensor& in, int out_c, int k, int stride, int group, const std::string& act) {
    cv::dnn::LayerParams p;
    p.set("kernel_size", k);
    p.set("stride", stride);
    p.set("pad", k / 2);
    p.set("num_output", out_c);
    p.set("group", group);
    p.set("bias_term", true);
    const int in_per_group = in.channels / group;
    cv::Mat w(std::vector<int>{out_c, in_per_group, k, k}, CV_32F);
    std::normal_distribution<float> he(0.f, std::sqrt(2.f / static_cast<float>(in_per_group * k * k)));
    for (auto it = w.begin<float>(); it != w.end<float>(); ++it) *it = he(rng_);
    cv::Mat b(1, out_c, CV_32F);
    std::normal_distribution<float> small(0.f, 0.01f);
    for (auto it = b.begin<float>(); it != b.end<float>(); ++it) *it = small(rng_);
    p.blobs = {w, b};
    Tensor t = add("Convolution", p, {in});
    t.channels = out_c;
    if (act.empty()) return t;
    cv::dnn::LayerParams a;
    if (act == "ReLU6") a.set("min_value", 0.f), a.set("max_value", 6.f);
    Tensor r = add(act, a, {t});
    r.channels = out_c;
    return r;
  }
  Tensor add(const std::string& type, cv::dnn::LayerParams p, const std::vector<Tensor>& inputs) {
    const std::string name = type + "_" + std::to_string(++count_);
    p.name = name;
    p.type = type;
    const int id = net_.addLayer(name, type, p);
    for (std::size_t i = 0; i < inputs.size(); ++i)
      net_.connect(inputs[i].layer, inputs[i].pin, id, static_cast<int>(i));
    return {id, 0, inputs.empty() ? 0 : inputs.front().channels};
  }
  Tensor concat(const std::vector<Tensor>& in, int axis) {
    cv::dnn::LayerParams p;
    p.set("axis", axis);
    Tensor t = add("Concat", p, in);
    t.channels = 0;
    for (const Tensor& x : in) t.channels += x.channels;
    return t;
  }
  cv::dnn::Net take() { return std::move(net_); }
  cv::dnn::Net& net() { return net_; }

 private:
  cv::dnn::Net net_;
  std::mt19937 rng_;
  int count_ = 0;
};

cv::dnn::DictValue ints(std::initializer_list<int> v) {
  const std::vector<int> a(v);
  return cv::dnn::DictValue::arrayInt(a.data(), static_cast<int>(a.size()));
}
cv::dnn::DictValue reals(std::initializer_list<float> v) {
  const std::vector<double> a(v.begin(), v.end());
  return cv::dnn::DictValue::arrayReal(a.data(), static_cast<int>(a.size()));
}

// NCHW -> NHWC, then flattened from axis 1: SSD's layout for concatenating the predictions of every map.
Tensor permute_flatten(Builder& b, const Tensor& in) {
  cv::dnn::LayerParams perm;
  perm.set("order", ints({0, 2, 3, 1}));
  const Tensor t = b.add("Permute", perm, {in});
  cv::dnn::LayerParams flat;
  flat.set("axis", 1);
  return b.add("Flatten", flat, {t});
}

BuiltNetwork mobilenet_ssd(cv::Size input, unsigned seed) {
  Builder b(seed);
  constexpr int kClasses = 91;  // COCO as in the TensorFlow model zoo: 90 + background
  Tensor x = b.conv(b.input(3), 32, 3, 2, 1, "ReLU6");
  // MobileNet v1: (output channels, stride) of each depthwise-separable block.
  const int blocks[13][2] = {{64, 1},  {128, 2}, {128, 1}, {256, 2}, {256, 1},  {512, 2}, {512, 1},
                             {512, 1}, {512, 1}, {512, 1}, {512, 1}, {1024, 2}, {1024, 1}};
  std::vector<Tensor> maps;
  for (int i = 0; i < 13; ++i) {
    x = b.conv(x, x.channels, 3, blocks[i][1], x.channels, "ReLU6");  // depthwise
    x = b.conv(x, blocks[i][0], 1, 1, 1, "ReLU6");                    // pointwise
    if (i == 10 || i == 12) maps.push_back(x);                        // conv11 (19x19), conv13 (10x10)
  }
  // Extra feature layers: 1x1 to half the depth, then 3x3 stride 2 (5x5, 3x3, 2x2, 1x1 at 300x300).
  for (const int depth : {512, 256, 256, 128}) {
    x = b.conv(x, depth / 2, 1, 1, 1, "ReLU6");
    x = b.conv(x, depth, 3, 2, 1, "ReLU6");
    maps.push_back(x);
  }
  // Prior boxes as in SSD: scales from 0.2 to 0.95 of the image; 3 priors on the first map, 6 on the others.
  const float side = static_cast<float>(std::min(input.width, input.height));
  std::vector<Tensor> locs, confs, priors;
  for (std::size_t m = 0; m < maps.size(); ++m) {
    const bool first = m == 0;
    const int n_priors = first ? 3 : 6;
    locs.push_back(permute_flatten(b, b.conv(maps[m], n_priors * 4, 1, 1, 1, "")));
    confs.push_back(permute_flatten(b, b.conv(maps[m], n_priors * kClasses, 1, 1, 1, "")));
    const float s_k = first ? 0.1f : 0.2f + 0.15f * static_cast<float>(m - 1);
    const float s_next = 0.2f + 0.15f * static_cast<float>(m);
    cv::dnn::LayerParams p;
    p.set("min_size", s_k * side);
    if (!first) p.set("max_size", s_next * side);
    p.set("aspect_ratio", first ? reals({2.f}) : reals({2.f, 3.f}));
    p.set("flip", true);
    p.set("clip", false);
    p.set("variance", reals({0.1f, 0.1f, 0.2f, 0.2f}));
    p.set("offset", 0.5f);
    priors.push_back(b.add("PriorBox", p, {maps[m], b.input(3)}));
  }
  const Tensor loc = b.concat(locs, 1), conf_raw = b.concat(confs, 1), prior = b.concat(priors, 2);
  cv::dnn::LayerParams reshape;
  reshape.set("dim", ints({0, -1, kClasses}));
  const Tensor conf_rows = b.add("Reshape", reshape, {conf_raw});
  cv::dnn::LayerParams softmax;
  softmax.set("axis", 2);
  const Tensor conf_soft = b.add("Softmax", softmax, {conf_rows});
  cv::dnn::LayerParams flat;
  flat.set("axis", 1);
  const Tensor conf = b.add("Flatten", flat, {conf_soft});
  cv::dnn::LayerParams det;
  det.set("num_classes", kClasses);
  det.set("share_location", true);
  det.set("background_label_id", 0);
  det.set("nms_threshold", 0.6f);
  det.set("top_k", 100);
  det.set("keep_top_k", 100);
  det.set("code_type", "CENTER_SIZE");
  det.set("confidence_threshold", 0.3f);
  b.add("DetectionOutput", det, {loc, conf, prior});
  BuiltNetwork out;
  out.net = b.take();
  out.name = "mobilenet-ssd (SSD300 MobileNet v1, COCO layout, random weights)";
  out.default_input = {300, 300};
  out.published_gflops = 2.4;
  out.published_note =
      "1.2 billion multiply-adds (MobileNets paper, Howard et al. 2017, table 13: SSD 300 MobileNet "
      "on COCO) = 2.4 GFLOPs at 2 FLOPs per multiply-add";
  return out;
}

// YOLOv8's Conv: convolution (batch norm folded) + SiLU.
Tensor yconv(Builder& b, const Tensor& in, int out_c, int k, int stride) {
  return b.conv(in, out_c, k, stride, 1, "Swish");
}

// C2f: 1x1 conv to 2c, split in halves, n bottlenecks on the second half each adding its output to the list,
// concatenation of all, 1x1 conv to out_c.
Tensor c2f(Builder& b, const Tensor& in, int out_c, int n, bool shortcut) {
  const int c = out_c / 2;
  const Tensor y = yconv(b, in, 2 * c, 1, 1);
  cv::dnn::LayerParams split;
  split.set("axis", 1);
  split.set("slice_point", ints({c}));
  const Tensor s = b.add("Slice", split, {y});
  std::vector<Tensor> parts{{s.layer, 0, c}, {s.layer, 1, c}};
  Tensor last = parts.back();
  for (int i = 0; i < n; ++i) {
    Tensor t = yconv(b, yconv(b, last, c, 3, 1), c, 3, 1);
    if (shortcut) {
      cv::dnn::LayerParams sum;
      sum.set("operation", "sum");
      t = b.add("Eltwise", sum, {last, t});
      t.channels = c;
    }
    parts.push_back(t);
    last = t;
  }
  return yconv(b, b.concat(parts, 1), out_c, 1, 1);
}

Tensor maxpool5(Builder& b, const Tensor& in) {
  cv::dnn::LayerParams p;
  p.set("pool", "max");
  p.set("kernel_size", 5);
  p.set("stride", 1);
  p.set("pad", 2);
  return b.add("Pooling", p, {in});
}

Tensor upsample2(Builder& b, const Tensor& in) {
  cv::dnn::LayerParams p;
  p.set("interpolation", "nearest");
  p.set("zoom_factor", 2);
  return b.add("Resize", p, {in});
}

BuiltNetwork yolo_n(cv::Size input, unsigned seed) {
  if (input.width % 32 != 0 || input.height % 32 != 0 || input.width < 64 || input.height < 64)
    throw std::invalid_argument("yolo-n needs an input whose sides are multiples of 32 of at least 64 px (got " +
                                std::to_string(input.width) + "x" + std::to_string(input.height) + ")");
  Builder b(seed);
  constexpr int kClasses = 80, kRegMax = 16;
  Tensor x = yconv(b, b.input(3), 16, 3, 2);
  x = yconv(b, x, 32, 3, 2);
  x = c2f(b, x, 32, 1, true);
  x = yconv(b, x, 64, 3, 2);
  const Tensor p3 = c2f(b, x, 64, 2, true);
  x = yconv(b, p3, 128, 3, 2);
  const Tensor p4 = c2f(b, x, 128, 2, true);
  x = yconv(b, p4, 256, 3, 2);
  x = c2f(b, x, 256, 1, true);
  // SPPF: three chained 5x5 max pools, concatenated with their input.
  const Tensor s0 = yconv(b, x, 128, 1, 1);
  const Tensor s1 = maxpool5(b, s0), s2 = maxpool5(b, s1), s3 = maxpool5(b, s2);
  const Tensor p5 = yconv(b, b.concat({s0, s1, s2, s3}, 1), 256, 1, 1);
  // PAN neck.
  const Tensor h4 = c2f(b, b.concat({upsample2(b, p5), p4}, 1), 128, 1, false);
  const Tensor out3 = c2f(b, b.concat({upsample2(b, h4), p3}, 1), 64, 1, false);
  const Tensor out4 = c2f(b, b.concat({yconv(b, out3, 64, 3, 2), h4}, 1), 128, 1, false);
  const Tensor out5 = c2f(b, b.concat({yconv(b, out4, 128, 3, 2), p5}, 1), 256, 1, false);
  // Decoupled head per level: box branch to 4 x reg_max, class branch to the class scores (sigmoid).
  const int c_box = std::max({16, 64 / 4, 4 * kRegMax}), c_cls = std::max(64, std::min(kClasses, 100));
  std::vector<Tensor> levels;
  for (const Tensor& f : {out3, out4, out5}) {
    const Tensor box = b.conv(yconv(b, yconv(b, f, c_box, 3, 1), c_box, 3, 1), 4 * kRegMax, 1, 1, 1, "");
    const Tensor cls = b.conv(yconv(b, yconv(b, f, c_cls, 3, 1), c_cls, 3, 1), kClasses, 1, 1, 1, "Sigmoid");
    cv::dnn::LayerParams flat;
    flat.set("axis", 2);  // 1 x C x H x W -> 1 x C x HW
    levels.push_back(b.add("Flatten", flat, {b.concat({box, cls}, 1)}));
  }
  b.concat(levels, 2);
  BuiltNetwork out;
  out.net = b.take();
  out.name = "yolo-n (YOLOv8n layout, random weights)";
  out.default_input = {640, 640};
  out.published_gflops = 8.7;
  out.published_note =
      "8.7 GFLOPs at 640x640 (Ultralytics YOLOv8n model card; FLOPs = 2 x multiply-adds, as "
      "counted by thop)";
  return out;
}

}  // namespace

BuiltNetwork build_architecture(DnnArchitecture a, cv::Size input, unsigned seed) {
  if (input.width < 32 || input.height < 32 || input.width > 4096 || input.height > 4096)
    throw std::invalid_argument("network input must be 32 to 4096 px per side (got " + std::to_string(input.width) +
                                "x" + std::to_string(input.height) + ")");
  return a == DnnArchitecture::MobileNetSsd ? mobilenet_ssd(input, seed) : yolo_n(input, seed);
}

Detector architecture_timing_detector(DnnArchitecture a) {
  const cv::Size input = a == DnnArchitecture::MobileNetSsd ? cv::Size(300, 300) : cv::Size(640, 640);
  auto net = std::make_shared<cv::dnn::Net>(build_architecture(a, input).net);
  auto mutex = std::make_shared<std::mutex>();  // one Net, forward() is not reentrant
  const bool yolo = a == DnnArchitecture::YoloN;
  return [net, mutex, input, yolo](const cv::Mat& bgr) {
    // Preprocessed as a trained network of the family would be: YOLO letterboxed, SSD stretched.
    const cv::Mat blob =
        cv::dnn::blobFromImage(yolo ? letterbox_image(bgr, input) : bgr, yolo ? 1.0 / 255 : 1.0 / 127.5, input,
                               yolo ? cv::Scalar::all(0) : cv::Scalar::all(127.5), true, false);
    std::lock_guard lock(*mutex);
    net->setInput(blob);
    net->forward();
    return std::vector<Detection>{};
  };
}

std::string architecture_detector_name(DnnArchitecture a) {
  return std::string(to_string(a)) + " (" + kArchitectureTimingLabel + ")";
}

}  // namespace bs::vision
