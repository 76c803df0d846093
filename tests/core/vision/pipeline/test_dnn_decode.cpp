// SPDX-License-Identifier: GPL-3.0-or-later
// Decoding of the three detection output families on blobs whose content is written here (so every expected box
// is known), and the same decoders behind the cv::dnn detector on networks built here whose outputs are set by
// the painted image: a 1x1 convolution maps the pixel colours to box coordinates and class scores.
#include <QTest>

#include <opencv2/dnn.hpp>

#include "vision/pipeline/detector.h"
#include "vision/pipeline/dnn_decode.h"

using namespace bs::vision;

namespace {

cv::Mat blob3(int a, int b) { return cv::Mat(std::vector<int>{1, a, b}, CV_32F, cv::Scalar(0)); }

DecodeOptions opts(cv::Size input, cv::Size image) {
  DecodeOptions o;
  o.input_size = input;
  o.image_size = image;
  o.min_confidence = 0.5f;
  o.nms_threshold = 0.45f;
  return o;
}

// A network with one 1x1 convolution from the 3 input channels to `weights.rows` outputs, then flattened to
// 1 x K x (H W): the YOLOv8 layout, or transposed (Permute) to 1 x (H W) x K, the YOLOv5 layout.
cv::dnn::Net conv_net(const cv::Mat& weights, const cv::Mat& bias, bool yolov5) {
  cv::dnn::Net net;
  net.setInputsNames({"data"});
  cv::dnn::LayerParams c;
  c.set("kernel_size", 1);
  c.set("num_output", weights.rows);
  c.set("bias_term", true);
  c.blobs = {weights.reshape(1, std::vector<int>{weights.rows, 3, 1, 1}).clone(), bias.clone()};
  const int conv = net.addLayer("conv", "Convolution", c);
  net.connect(0, 0, conv, 0);
  cv::dnn::LayerParams f;
  f.set("axis", 2);
  const int flat = net.addLayer("flat", "Flatten", f);
  net.connect(conv, 0, flat, 0);
  if (yolov5) {
    cv::dnn::LayerParams p;
    const int order[] = {0, 2, 1};
    p.set("order", cv::dnn::DictValue::arrayInt(order, 3));
    const int perm = net.addLayer("perm", "Permute", p);
    net.connect(flat, 0, perm, 0);
  }
  return net;
}

}  // namespace

class TestDnnDecode : public QObject {
  Q_OBJECT
 private slots:
  void ssd_rows_scale_to_the_image() {
    cv::Mat out(std::vector<int>{1, 1, 3, 7}, CV_32F, cv::Scalar(0));
    const float rows[3][7] = {
        {0, 1, 0.9f, 0.1f, 0.2f, 0.5f, 0.8f}, {0, 2, 0.4f, 0, 0, 1, 1}, {-1, 1, 0.99f, 0, 0, 1, 1}};
    std::memcpy(out.ptr<float>(), rows, sizeof rows);
    QCOMPARE(detect_output_family({out}).family, DnnOutputFamily::Ssd);
    const auto d = decode_detections({out}, opts({300, 300}, {200, 100}));
    QCOMPARE(d.size(), std::size_t{1});  // the second is below 0.5, the third has no image
    QCOMPARE(d[0].box, cv::Rect(cv::Point(20, 20), cv::Point(100, 80)));
    QCOMPARE(d[0].class_id, 1);
  }

  void yolov5_objectness_times_class_then_nms() {
    // 8 anchors x (5 + 2 classes), input 64x32, image 640x320: boxes scale by 10.
    cv::Mat out = blob3(8, 7);
    auto row = [&](int i, std::initializer_list<float> v) { std::copy(v.begin(), v.end(), out.ptr<float>(0, i)); };
    row(0, {20, 10, 8, 4, 0.9f, 0.1f, 1.0f});    // class 1, score 0.9
    row(1, {21, 10, 8, 4, 0.8f, 0.2f, 1.0f});    // overlaps row 0 (IoU 0.78), class 1, 0.8: suppressed
    row(2, {21, 10, 8, 4, 0.8f, 0.9f, 0.1f});    // same place, class 0, 0.72: kept (NMS is per class)
    row(3, {40, 20, 10, 10, 0.6f, 0.5f, 0.5f});  // 0.6 x 0.5 = 0.3: below threshold though objectness is 0.6
    row(4, {50, 16, 100, 40, 0.95f, 1.0f, 0});   // class 0, 0.95, reaches past the image: clipped
    QCOMPARE(detect_output_family({out}).family, DnnOutputFamily::YoloV5);
    const auto d = decode_detections({out}, opts({64, 32}, {640, 320}));
    QCOMPARE(d.size(), std::size_t{3});
    QCOMPARE(d[0].class_id, 0);  // sorted by score: 0.95, 0.9, 0.72
    QCOMPARE(d[0].box, cv::Rect(cv::Point(0, 0), cv::Point(640, 320)));
    QVERIFY(std::fabs(d[0].score - 0.95) < 1e-6);
    QCOMPARE(d[1].class_id, 1);
    QCOMPARE(d[1].box, cv::Rect(cv::Point(160, 80), cv::Point(240, 120)));
    QCOMPARE(d[2].class_id, 0);
    QCOMPARE(d[2].box, cv::Rect(cv::Point(170, 80), cv::Point(250, 120)));
    QVERIFY(std::fabs(d[2].score - 0.72) < 1e-6);
  }

  void yolov8_attribute_major_no_objectness() {
    // (4 + 3 classes) x 10 anchors: column i holds anchor i.
    cv::Mat out = blob3(7, 10);
    auto col = [&](int i, std::initializer_list<float> v) {
      int a = 0;
      for (float x : v) out.at<float>(0, a++, i) = x;
    };
    col(2, {32, 32, 16, 16, 0.1f, 0.7f, 0.2f});  // class 1, 0.7
    col(5, {33, 32, 16, 16, 0.1f, 0.6f, 0.2f});  // class 1, overlaps: suppressed
    col(7, {10, 50, 4, 8, 0.3f, 0.2f, 0.55f});   // class 2, 0.55
    col(9, {50, 50, 4, 4, 0.49f, 0, 0});         // below 0.5
    QCOMPARE(detect_output_family({out}).family, DnnOutputFamily::YoloV8);
    const auto d = decode_detections({out}, opts({64, 64}, {128, 64}));  // x scales by 2, y by 1
    QCOMPARE(d.size(), std::size_t{2});
    QCOMPARE(d[0].class_id, 1);
    QCOMPARE(d[0].box, cv::Rect(cv::Point(48, 24), cv::Point(80, 40)));
    QCOMPARE(d[1].class_id, 2);
    QCOMPARE(d[1].box, cv::Rect(cv::Point(16, 46), cv::Point(24, 54)));
  }

  void unknown_family_names_the_shapes() {
    const cv::Mat five(std::vector<int>{1, 3, 80, 80, 85}, CV_32F, cv::Scalar(0));
    const cv::Mat flat(1, 1000, CV_32F, cv::Scalar(0));
    try {
      detect_output_family({five, flat});
      QFAIL("no error for unknown outputs");
    } catch (const std::runtime_error& e) {
      const std::string m = e.what();
      QVERIFY2(m.find("1x3x80x80x85") != std::string::npos && m.find("1x1000") != std::string::npos, e.what());
    }
    // A decoder given the wrong family's blob says what it expected.
    QVERIFY_THROWS_EXCEPTION(std::runtime_error, decode_yolov8(blob3(8, 7), opts({64, 32}, {64, 32})));
  }

  // A real ONNX file through the same path as `--detector MODEL`: tests/data/dnn/yolov8-known.onnx (written by
  // scripts/make-onnx-fixture.py, see SOURCES there) outputs the same 1x6x8 YOLOv8 tensor for every image, so the
  // boxes are known: anchor 0 (class 0, 0.9) at x 256..384, y 288..352 and anchor 2 (class 1, 0.75) at
  // x 80..120, y 180..260 of the 640x640 input; anchor 1 overlaps anchor 0 (IoU 0.855), anchor 3 scores 0.4.
  // The 1280x640 image is letterboxed: scaled by 0.5 to 640x320 at y = 160, so x doubles and y = (y - 160) x 2.
  void onnx_fixture_file_gives_the_known_boxes() {
    DnnOptions o;
    o.model = BENCHSCOPE_TEST_DATA_DIR "/dnn/yolov8-known.onnx";
    DnnDetectorInfo info;
    Detector detect = dnn_detector(o, &info);
    QCOMPARE(QString::fromStdString(info.family), QString("YOLOv8"));
    QCOMPARE(info.input_size, cv::Size(640, 640));  // runs at 300x300 too, but a YOLO family takes 640x640
    QCOMPARE(info.scale, 1.0 / 255);
    QVERIFY(info.letterbox);  // the YOLO default
    const cv::Mat img(640, 1280, CV_8UC3, cv::Scalar(30, 60, 90));
    auto d = detect(img);
    QCOMPARE(d.size(), std::size_t{2});
    QCOMPARE(d[0].class_id, 0);
    QVERIFY(std::fabs(d[0].score - 0.9) < 1e-6);
    QCOMPARE(d[0].box, cv::Rect(cv::Point(512, 256), cv::Point(768, 384)));
    QCOMPARE(d[1].class_id, 1);
    QVERIFY(std::fabs(d[1].score - 0.75) < 1e-6);
    QCOMPARE(d[1].box, cv::Rect(cv::Point(160, 40), cv::Point(240, 200)));
    // The thresholds reach the decoder: at 0.85 only anchor 0 is left; with NMS at IoU 0.9 anchor 1 survives.
    o.min_confidence = 0.85f;
    QCOMPARE(dnn_detector(o)(img).size(), std::size_t{1});
    o.min_confidence = 0.5f;
    o.nms_threshold = 0.9f;
    d = dnn_detector(o)(img);
    QCOMPARE(d.size(), std::size_t{3});
    QCOMPARE(d[1].box, cv::Rect(cv::Point(532, 256), cv::Point(788, 384)));  // anchor 1: x 266..394
    QVERIFY(std::fabs(d[1].score - 0.8) < 1e-6);
    // Stretched instead (letterbox off): x doubles, y stays.
    o.nms_threshold = 0.45f;
    o.letterbox = false;
    d = dnn_detector(o)(img);
    QCOMPARE(d.size(), std::size_t{2});
    QCOMPARE(d[0].box, cv::Rect(cv::Point(512, 288), cv::Point(768, 352)));
    QCOMPARE(d[1].box, cv::Rect(cv::Point(160, 180), cv::Point(240, 260)));
  }

  // The letterbox itself: geometry (Ultralytics' rounding: the odd pixel of padding right and bottom), the padded
  // image, and boxes mapped back exactly.
  void letterbox_geometry_image_and_mapping() {
    QCOMPARE(letterbox_geometry({1280, 640}, {640, 640}).content, cv::Rect(0, 160, 640, 320));
    QCOMPARE(letterbox_geometry({1280, 1024}, {640, 640}).content, cv::Rect(0, 64, 640, 512));
    QCOMPARE(letterbox_geometry({480, 640}, {640, 640}).content, cv::Rect(80, 0, 480, 640));
    // 100x37 into 64x64: x 0.64, 37 x 0.64 = 23.68 -> 24 rows, 40 rows of padding: 20 above, 20 below.
    QCOMPARE(letterbox_geometry({100, 37}, {64, 64}).content, cv::Rect(0, 20, 64, 24));
    QCOMPARE(letterbox_geometry({100, 36}, {64, 64}).content, cv::Rect(0, 20, 64, 23));  // 23.04: 41 rows, 20 + 21
    QCOMPARE(letterbox_geometry({10, 10}, {64, 32}).content, cv::Rect(16, 0, 32, 32));   // smaller image: scaled up
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, letterbox_geometry({0, 10}, {64, 64}));

    // 40x20, left half blue, right half red, into 16x16: scaled by 0.4 to 16x8 at y = 4; rows 0-3 and 12-15 grey.
    cv::Mat img(20, 40, CV_8UC3, cv::Scalar(255, 0, 0));
    img(cv::Rect(20, 0, 20, 20)).setTo(cv::Scalar(0, 0, 255));
    const cv::Mat lb = letterbox_image(img, {16, 16});
    QCOMPARE(lb.size(), cv::Size(16, 16));
    for (int y : {0, 3, 12, 15}) QCOMPARE(lb.at<cv::Vec3b>(y, 5), cv::Vec3b(114, 114, 114));
    for (int y : {4, 11}) {
      QCOMPARE(lb.at<cv::Vec3b>(y, 2), cv::Vec3b(255, 0, 0));
      QCOMPARE(lb.at<cv::Vec3b>(y, 13), cv::Vec3b(0, 0, 255));
    }

    // A YOLOv8 box in the 16x16 input at x 2..6, y 4..12 is at x 5..15, y 0..20 of the 40x20 image.
    cv::Mat out = blob3(5, 8);
    const float v[5] = {4, 8, 4, 8, 0.9f};
    for (int a = 0; a < 5; ++a) out.at<float>(0, a, 0) = v[a];
    DecodeOptions o = opts({16, 16}, {40, 20});
    o.letterbox = true;
    auto d = decode_detections({out}, o);
    QCOMPARE(d.size(), std::size_t{1});
    QCOMPARE(d[0].box, cv::Rect(5, 0, 10, 20));
    o.letterbox = false;  // stretched: x x 2.5, y x 1.25
    QCOMPARE(decode_detections({out}, o)[0].box, cv::Rect(5, 5, 10, 10));
    // SSD rows letterboxed: 0..1 of the input, then through the letterbox (and clipped to the image).
    cv::Mat ssd(std::vector<int>{1, 1, 1, 7}, CV_32F, cv::Scalar(0));
    const float row[7] = {0, 3, 0.8f, 0.125f, 0.375f, 0.375f, 1.0f};  // input x 2..6, y 6..16
    std::memcpy(ssd.ptr<float>(), row, sizeof row);
    o.letterbox = true;
    d = decode_detections({ssd}, o);
    QCOMPARE(d.size(), std::size_t{1});
    QCOMPARE(d[0].box, cv::Rect(cv::Point(5, 5), cv::Point(15, 20)));  // y 5..30 clipped to 20
    QCOMPARE(d[0].class_id, 3);
  }

  // End to end, the letterbox in the preprocessing, not only in the decoding: an 80x40 image into an 8x8 input is
  // scaled by 0.1 to 8x4 at y = 2, rows 0-1 and 6-7 grey (114). The 1x1 convolution gives per pixel (B, G, R =
  // pixel / 255): cx = 8 B, cy = 4 R + 1, w = h = 2, class 0 = R, class 1 = 2 G. The painted block (B 128, R 255)
  // is class 0 at cx 4.02, cy 5; the grey padding is class 1 (0.894) at cx 3.58, cy 2.79 and the black rest
  // scores 0. Stretched, there is no padding, so no class 1.
  void letterbox_reaches_the_network() {
    cv::Mat img(40, 80, CV_8UC3, cv::Scalar(0, 0, 0));
    img(cv::Rect(30, 10, 10, 10)).setTo(cv::Scalar(128, 0, 255));
    const cv::Mat w = (cv::Mat_<float>(6, 3) << 8, 0, 0, 0, 0, 4, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 2, 0);
    const cv::Mat b = (cv::Mat_<float>(1, 6) << 0, 1, 2, 2, 0, 0);
    DnnOptions o;
    o.input_size = {8, 8};
    o.swap_rb = false;
    DnnDetectorInfo info;
    auto d = dnn_detector(conv_net(w, b, false), o, "letterbox", &info)(img);
    QVERIFY(info.letterbox);
    QCOMPARE(d.size(), std::size_t{2});
    // Block: input x 3.02..5.02, y 4..6 -> image x 30.2..50.2, y (4 - 2) x 10 = 20 .. 40.
    QCOMPARE(d[0].class_id, 0);
    QCOMPARE(d[0].box, cv::Rect(30, 20, 20, 20));
    QVERIFY(std::fabs(d[0].score - 1.0) < 1e-5);
    // Padding: input x 2.58..4.58, y 1.79..3.79 -> image x 25.8..45.8, y -2.1..17.9, clipped at 0.
    QCOMPARE(d[1].class_id, 1);
    QCOMPARE(d[1].box, cv::Rect(26, 0, 20, 18));
    QVERIFY(std::fabs(d[1].score - 2 * 114.0 / 255) < 1e-5);
    o.letterbox = false;
    d = dnn_detector(conv_net(w, b, false), o, "stretched")(img);
    QCOMPARE(d.size(), std::size_t{1});
    QCOMPARE(d[0].class_id, 0);
    QCOMPARE(d[0].box, cv::Rect(cv::Point(30, 20), cv::Point(50, 30)));  // y 4..6 x 5
  }

  // End to end: image -> blobFromImage -> network -> decoder. The 1x1 convolution gives per pixel (B, G, R the
  // blob's channels = pixel / 255) cx = 8 B, cy = G, w = 2, h = 1 (input pixels), then YOLOv8: class 0 = R,
  // class 1 = 0.2; YOLOv5: objectness = R, class 0 = 1. Image 80x10 of 10x10 blocks, network input 8x1: one
  // anchor per block (the linear downscale samples inside a block), boxes scale back by 10 on both axes.
  void yolo_networks_end_to_end() {
    cv::Mat img(10, 80, CV_8UC3, cv::Scalar(0, 0, 0));
    const auto paint = [&](int block, int B, int G, int R) {
      img(cv::Rect(10 * block, 0, 10, 10)).setTo(cv::Scalar(B, G, R));
    };
    paint(1, 102, 128, 230);  // cx 3.2, score 0.90
    paint(2, 106, 128, 204);  // cx 3.33, score 0.80: IoU 0.88 with block 1, suppressed
    paint(5, 204, 128, 255);  // cx 6.4, score 1.0
    const cv::Mat w = (cv::Mat_<float>(6, 3) << 8, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0);
    for (const bool v5 : {false, true}) {
      const cv::Mat b = (cv::Mat_<float>(1, 6) << 0, 0, 2, 1, 0, v5 ? 1.f : 0.2f);
      DnnOptions o;
      o.input_size = {8, 1};
      o.swap_rb = false;
      o.min_confidence = 0.5f;
      DnnDetectorInfo info;
      const Detector detect = dnn_detector(conv_net(w, b, v5), o, "fixture", &info);
      QCOMPARE(QString::fromStdString(info.family), QString(v5 ? "YOLOv5" : "YOLOv8"));
      QCOMPARE(info.scale, 1.0 / 255);  // the YOLO preprocessing default
      const auto d = detect(img);
      QCOMPARE(d.size(), std::size_t{2});
      QCOMPARE(d[0].box, cv::Rect(54, 0, 20, 10));  // x (6.4 -+ 1) x 10; y (0.502 -+ 0.5) x 10 clipped to 0..10
      QVERIFY(std::fabs(d[0].score - 1.0) < 1e-4);
      QCOMPARE(d[1].box, cv::Rect(22, 0, 20, 10));
      QVERIFY(std::fabs(d[1].score - 230.0 / 255) < 1e-4);
      QCOMPARE(d[1].class_id, 0);
    }
    // A network whose output is of no known family is refused when the detector is made, naming the shape.
    const cv::Mat w2 = (cv::Mat_<float>(2, 3) << 1, 0, 0, 0, 1, 0);
    cv::dnn::Net odd = conv_net(w2, cv::Mat::zeros(1, 2, CV_32F), false);  // 1 x 2 x 8
    DnnOptions o;
    o.input_size = {8, 1};
    try {
      dnn_detector(odd, o, "odd.onnx");
      QFAIL("no error for an unknown output family");
    } catch (const std::runtime_error& e) {
      QVERIFY2(std::string(e.what()).find("odd.onnx") != std::string::npos &&
                   std::string(e.what()).find("1x2x8") != std::string::npos,
               e.what());
    }
  }
};

QTEST_GUILESS_MAIN(TestDnnDecode)
#include "test_dnn_decode.moc"
