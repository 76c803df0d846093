// SPDX-License-Identifier: GPL-3.0-or-later
// Frame files for the pipeline (raw Bayer + sidecar, grey images) and the conversion of a pipeline result into the
// stored run (ms -> s, stage names).
#include <QTemporaryDir>
#include <QTest>

#include <fstream>

#include <opencv2/imgcodecs.hpp>

#include "vision/frames/frame_file.h"
#include "vision/pipeline/pipeline_record.h"

namespace {

void write(const std::string& path, const std::string& bytes) { std::ofstream(path, std::ios::binary) << bytes; }

QString error_of(const std::string& path) {
  try {
    bs::vision::read_frame_file(path);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

class TestFrameFile : public QObject {
  Q_OBJECT
 private slots:
  void raw_with_sidecar() {
    QTemporaryDir dir;
    const std::string raw = dir.filePath("a.raw").toStdString(), side = dir.filePath("a.json").toStdString();
    // 4x2, 12-bit big-endian: sample k = 0x0100 * k + 3.
    std::string bytes;
    for (int k = 0; k < 8; ++k) {
      bytes.push_back(static_cast<char>(k));
      bytes.push_back(3);
    }
    write(raw, bytes);
    write(side, R"({"width": 4, "height": 2, "pattern": "RGGB", "bit_depth": 12, "endianness": "big"})");
    const auto f = bs::vision::read_frame_file(raw);
    QCOMPARE(f.mosaic.type(), CV_16UC1);
    QCOMPARE(f.mosaic.size(), cv::Size(4, 2));
    QCOMPARE(f.mosaic.at<std::uint16_t>(1, 3), std::uint16_t{0x0703});
    QCOMPARE(f.pattern, bs::vision::BayerPattern::RGGB);
    QVERIFY(f.pattern_from_file);
    QCOMPARE(f.bit_depth, 12);
    // 12-bit full scale maps to 255.
    const cv::Mat m8 = bs::vision::to_8bit(cv::Mat(1, 1, CV_16UC1, cv::Scalar(4095)), 12);
    QCOMPARE(m8.at<std::uint8_t>(0, 0), std::uint8_t{255});
  }

  void bad_raw_files_are_named() {
    QTemporaryDir dir;
    const std::string raw = dir.filePath("b.raw").toStdString(), side = dir.filePath("b.json").toStdString();
    write(raw, std::string(10, '\0'));
    QVERIFY(error_of(raw).contains("needs a JSON sidecar"));
    write(side, R"({"width": 4, "height": 2, "bit_depth": 8})");
    QVERIFY2(error_of(raw).contains("b.raw: is 10 bytes") && error_of(raw).contains("needs 8"),
             qPrintable(error_of(raw)));
    // A size claim far beyond the file is refused before any allocation.
    write(side, R"({"width": 65536, "height": 65536, "bit_depth": 16, "endianness": "little"})");
    QVERIFY(error_of(raw).contains("needs 8589934592"));
    write(side, R"({"width": 4, "height": "2", "bit_depth": 8})");
    QVERIFY(error_of(raw).contains("b.json: /height: expected an integer"));
    write(side, R"({"width": 4, "height": 2, "bit_depth": 17, "endianness": "little"})");
    QVERIFY(error_of(raw).contains("/bit_depth"));
    write(side, R"({"width": 5, "height": 2, "bit_depth": 8, "pattern": "XYZW"})");
    QVERIFY(error_of(raw).contains("/pattern"));
    write(raw, std::string(8, '\xff') + std::string(8, '\0'));
    write(side, R"({"width": 4, "height": 2, "bit_depth": 10, "endianness": "little"})");
    QVERIFY(error_of(raw).contains("more than 10 bits"));
    // Above 8 bits the byte order must be stated (model/raw_sidecar.h, the importer's rule; this reader used to
    // assume little-endian).
    write(side, R"({"width": 4, "height": 2, "bit_depth": 10})");
    QVERIFY2(error_of(raw).contains("b.json: /endianness: a sidecar for samples above 8 bits"),
             qPrintable(error_of(raw)));
  }

  void grey_images_and_colour_refused() {
    QTemporaryDir dir;
    const std::string grey = dir.filePath("g.png").toStdString(), colour = dir.filePath("c.png").toStdString();
    QVERIFY(cv::imwrite(grey, cv::Mat(6, 8, CV_8UC1, cv::Scalar(7))));
    QVERIFY(cv::imwrite(colour, cv::Mat(6, 8, CV_8UC3, cv::Scalar(1, 2, 3))));
    const auto f = bs::vision::read_frame_file(grey, bs::vision::BayerPattern::GRBG);
    QCOMPARE(f.mosaic.size(), cv::Size(8, 6));
    QCOMPARE(f.pattern, bs::vision::BayerPattern::GRBG);
    QVERIFY(!f.pattern_from_file);
    QVERIFY(error_of(colour).contains("has 3 channels"));
    write(dir.filePath("t.png").toStdString(), "not an image");
    QVERIFY(error_of(dir.filePath("t.png").toStdString()).contains("not an image OpenCV can read"));
  }

  void result_becomes_a_stored_run() {
    bs::vision::PipelineResult r;
    r.stages.push_back(bs::vision::make_stage_timing("preprocessing", {2.0, 4.0, 6.0}));
    r.stages.push_back(bs::vision::make_stage_timing("detection", {100.0, 300.0, 200.0}));
    r.stages.push_back(bs::vision::make_stage_timing("end-to-end", {}));  // no frame: left out
    r.throughput_fps = 4.5;
    const bs::PipelineRun run = bs::vision::to_pipeline_run(r);
    QCOMPARE(run.stages.size(), std::size_t{2});
    const bs::StageStats* pre = run.stage("preprocess");
    QVERIFY(pre);
    QCOMPARE(pre->n, std::size_t{3});
    QVERIFY(std::fabs(pre->mean_s - 0.004) < 1e-15);
    QVERIFY(std::fabs(pre->sd_s - 0.002) < 1e-15);
    QVERIFY(std::fabs(*pre->min_s - 0.002) < 1e-15);
    QVERIFY(std::fabs(*pre->max_s - 0.006) < 1e-15);
    QVERIFY(std::fabs(*run.stage("detect")->p50_s - 0.2) < 1e-15);
    QCOMPARE(*run.throughput_fps, 4.5);
  }
};

QTEST_GUILESS_MAIN(TestFrameFile)
#include "test_frame_file.moc"
