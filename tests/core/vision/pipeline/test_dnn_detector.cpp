// SPDX-License-Identifier: GPL-3.0-or-later
// The cv::dnn detector path end to end (read the model file, blobFromImage, forward, parse the SSD rows) with a
// network written here: a Caffe prototxt whose only layer reshapes the 1x3x1x7 input blob into three SSD output
// rows [image, class, score, x0, y0, x1, y1]. The image is painted so that the first row is one detection and
// the other two carry a negative image id (SSD's "no detection"), so the expected box is known exactly.
#include <QTemporaryDir>
#include <QTest>

#include <fstream>

#include "vision/pipeline/detector.h"

class TestDnnDetector : public QObject {
  Q_OBJECT
 private slots:
  void prototxt_network_gives_the_painted_box() {
    QTemporaryDir dir;
    const std::string model = dir.filePath("tiny.prototxt").toStdString();
    std::ofstream(model) << R"(name: "tiny-ssd-rows"
input: "data"
input_shape { dim: 1 dim: 3 dim: 1 dim: 7 }
layer { name: "rows" type: "Reshape" bottom: "data" top: "rows"
        reshape_param { shape { dim: 1 dim: 1 dim: 3 dim: 7 } } }
)";
    bs::vision::DnnOptions o;
    o.model = model;
    o.input_size = {7, 1};
    o.scale = 1.0 / 200;  // (pixel - 1) / 200
    o.mean = cv::Scalar::all(1);
    o.swap_rb = false;
    o.min_confidence = 0.5f;
    const bs::vision::Detector detect = bs::vision::dnn_detector(o);
    // 70x10 image, seven 10x10 blocks: blue carries row 0 = [0, 1, 0.9, 0.1, 0.2, 0.5, 0.8]; green and red are
    // 0, i.e. -0.005 everywhere, so rows 1 and 2 have a negative image id. Blocks survive the 10x linear
    // downscale to 7x1 exactly (samples fall inside a block).
    const int blue[7] = {1, 201, 181, 21, 41, 101, 161};
    cv::Mat img(10, 70, CV_8UC3, cv::Scalar::all(0));
    for (int k = 0; k < 7; ++k) img(cv::Rect(10 * k, 0, 10, 10)).setTo(cv::Scalar(blue[k], 0, 0));
    const auto found = detect(img);
    QCOMPARE(found.size(), std::size_t{1});
    QCOMPARE(found[0].box, cv::Rect(cv::Point(7, 2), cv::Point(35, 8)));  // 0.1 x 70, 0.2 x 10, 0.5 x 70, 0.8 x 10
    QVERIFY(std::fabs(found[0].score - 0.9) < 1e-5);
    QCOMPARE(found[0].class_id, 1);
    // Below the confidence threshold nothing is reported.
    img(cv::Rect(20, 0, 10, 10)).setTo(cv::Scalar(61, 0, 0));  // score 0.3
    QVERIFY(detect(img).empty());
    // A model file OpenCV cannot read is named in the error.
    const std::string junk = dir.filePath("junk.prototxt").toStdString();
    std::ofstream(junk) << "layer { this is not a network";
    o.model = junk;
    try {
      bs::vision::dnn_detector(o);
      QFAIL("no error for a broken model");
    } catch (const std::runtime_error& e) {
      QVERIFY(std::string(e.what()).find("junk.prototxt") != std::string::npos);
    }
  }
};

QTEST_GUILESS_MAIN(TestDnnDetector)
#include "test_dnn_detector.moc"
