// SPDX-License-Identifier: GPL-3.0-or-later
// The built-in architectures: they run, their outputs have the layout of the network they follow, their FLOPs
// (recounted per grouped convolution) are within 10 % of the published counts, and OpenCV's own count is kept
// beside it. Also the FLOPs recount on a network small enough to count by hand, and the target report.
#include <QTest>

#include "vision/pipeline/dnn_architectures.h"
#include "vision/pipeline/dnn_bench.h"
#include "vision/pipeline/dnn_decode.h"

using namespace bs::vision;

class TestDnnArchitectures : public QObject {
  Q_OBJECT
 private slots:
  void mobilenet_ssd_runs_and_costs_what_is_published() {
    BuiltNetwork b = build_architecture(DnnArchitecture::MobileNetSsd, {300, 300});
    QCOMPARE(b.default_input, cv::Size(300, 300));
    const cv::dnn::MatShape shape{1, 3, 300, 300};
    const DnnFlops f = count_flops(b.net, shape);
    QVERIFY2(std::fabs(f.counted / 1e9 - b.published_gflops) < 0.1 * b.published_gflops,
             std::to_string(f.counted).c_str());
    QVERIFY(f.opencv > 5 * f.counted);  // OpenCV 4.6 counts each depthwise convolution as a full one
    cv::Mat blob(shape, CV_32F);
    cv::randu(blob, -1, 1);
    b.net.setInput(blob);
    const cv::Mat out = b.net.forward();
    QCOMPARE(detect_output_family({out}).family, DnnOutputFamily::Ssd);
    // 1917 priors as in SSD MobileNet (19x19x3 + (10x10 + 5x5 + 3x3 + 2x2 + 1) x 6): the priors' blob says so.
    const std::vector<std::string> names = b.net.getLayerNames();
    int prior_concat = -1;
    for (const std::string& n : names)
      if (n.starts_with("Concat")) prior_concat = b.net.getLayerId(n);  // the last Concat joins the priors
    std::vector<cv::dnn::MatShape> in, outs;
    b.net.getLayerShapes(shape, prior_concat, in, outs);
    QCOMPARE(outs.at(0).at(2), 1917 * 4);
  }

  void yolo_n_has_the_yolov8n_head_and_cost() {
    BuiltNetwork b = build_architecture(DnnArchitecture::YoloN, {640, 640});
    const cv::dnn::MatShape shape{1, 3, 640, 640};
    const DnnFlops f = count_flops(b.net, shape);
    QVERIFY2(std::fabs(f.counted / 1e9 - b.published_gflops) < 0.1 * b.published_gflops,
             std::to_string(f.counted).c_str());
    QCOMPARE(f.opencv, f.counted);  // no grouped convolutions
    cv::Mat blob(shape, CV_32F);
    cv::randu(blob, 0, 1);
    b.net.setInput(blob);
    const cv::Mat out = b.net.forward();
    // 64 DFL box channels + 80 classes over 80x80 + 40x40 + 20x20 = 8400 anchors.
    QCOMPARE(out.dims, 3);
    QCOMPARE(out.size[1], 144);
    QCOMPARE(out.size[2], 8400);
    // Another input size scales the anchors; one that is not a multiple of 32 is refused.
    BuiltNetwork small = build_architecture(DnnArchitecture::YoloN, {320, 256});
    small.net.setInput(cv::Mat(std::vector<int>{1, 3, 256, 320}, CV_32F, cv::Scalar(0.5)));
    QCOMPARE(small.net.forward().size[2], 40 * 32 + 20 * 16 + 10 * 8);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, build_architecture(DnnArchitecture::YoloN, {300, 300}));
  }

  void flops_recount_by_hand() {
    // 8x8x4 input, depthwise 3x3 (group 4) then pointwise 4 -> 6, both with bias:
    // depthwise 8*8*4 outputs x (2*9 + 1), pointwise 8*8*6 x (2*4 + 1).
    cv::dnn::Net net;
    net.setInputsNames({"data"});
    int prev = 0;
    for (const auto& [out_c, k, group] : {std::tuple{4, 3, 4}, std::tuple{6, 1, 1}}) {
      cv::dnn::LayerParams p;
      p.set("kernel_size", k);
      p.set("pad", k / 2);
      p.set("num_output", out_c);
      p.set("group", group);
      p.set("bias_term", true);
      p.blobs = {cv::Mat(std::vector<int>{out_c, 4 / group, k, k}, CV_32F, cv::Scalar(0.1)),
                 cv::Mat(1, out_c, CV_32F, cv::Scalar(0))};
      const int id = net.addLayer("conv" + std::to_string(out_c), "Convolution", p);
      net.connect(prev, 0, id, 0);
      prev = id;
    }
    const DnnFlops f = count_flops(net, {1, 4, 8, 8});
    QCOMPARE(f.counted, std::int64_t{8 * 8 * 4 * (2 * 9 + 1) + 8 * 8 * 6 * (2 * 4 + 1)});
  }

  void targets_say_why_not() {
    const auto targets = dnn_targets();
    QCOMPARE(targets.size(), std::size_t{3});
    QVERIFY(targets[0].available);  // the CPU always is
    for (const DnnTarget& t : targets) QVERIFY2(t.available || !t.why_not.empty(), t.id.c_str());
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, dnn_target("tpu"));
  }
};

QTEST_GUILESS_MAIN(TestDnnArchitectures)
#include "test_dnn_architectures.moc"
