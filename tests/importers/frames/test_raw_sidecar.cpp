// SPDX-License-Identifier: GPL-3.0-or-later
// The raw-frame sidecar (core/model/raw_sidecar.h): what is written is read back, and the frame importer and the
// pipeline's frame reader, which used to read sidecars with rules of their own, accept the same files; where they
// still differ (the importer needs a pattern) the difference is the documented one.
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <fstream>

#include <nlohmann/json.hpp>

#include "frames/frame_raw.h"
#include "model/raw_sidecar.h"
#include "vision/frames/frame_file.h"
#include "workspace/registry.h"

namespace {

void write(const std::string& path, const std::string& bytes) { std::ofstream(path, std::ios::binary) << bytes; }

// What each reader says about raw file `raw`: "" when it reads it, else its error.
std::string importer_says(const std::string& raw) {
  try {
    (void)bs::import_file(raw, bs::CancelToken{});
    return {};
  } catch (const bs::ImportError& e) {
    return e.what();
  }
}
std::string pipeline_says(const std::string& raw) {
  try {
    (void)bs::vision::read_frame_file(raw);
    return {};
  } catch (const std::runtime_error& e) {
    return e.what();
  }
}

}  // namespace

class TestRawSidecar : public QObject {
  Q_OBJECT
 private slots:
  void what_is_written_is_read_back() {
    bs::RawSidecar s;
    s.width = 1280;
    s.height = 1024;
    s.pattern = "GRBG";
    s.bit_depth = 12;
    s.big_endian = true;
    s.synthetic = true;
    s.truth = "capture-truth.png";
    s.lens_json = R"({"format":"benchscope-lens","model":"equidistant"})";
    const nlohmann::json j = bs::raw_sidecar_to_json(s);
    QCOMPARE(j.at("format").get<std::string>(), std::string("benchscope-raw"));
    QCOMPARE(j.at("version").get<int>(), 1);
    const bs::RawSidecar back = bs::raw_sidecar_from_json(nlohmann::json::parse(j.dump(2)));
    QCOMPARE(back.width, 1280);
    QCOMPARE(back.height, 1024);
    QCOMPARE(back.pattern.value_or(""), std::string("GRBG"));
    QCOMPARE(back.bit_depth, 12);
    QVERIFY(back.big_endian);
    QVERIFY(back.synthetic);
    QCOMPARE(back.truth, s.truth);
    QCOMPARE(back.lens_json, s.lens_json);
    // Every member written is one the schema describes.
    std::ifstream schema_file(BENCHSCOPE_SOURCE_DIR "/resources/schema/benchscope-raw-v1.schema.json");
    const auto schema = nlohmann::json::parse(schema_file);
    for (const auto& [key, value] : j.items()) QVERIFY2(schema.at("properties").contains(key), key.c_str());
    QVERIFY(schema.at("required") == (nlohmann::json{"width", "height", "bit_depth"}));
  }

  void the_rules() {
    using K = bs::RawSidecarError::Kind;
    const auto kind_of = [](const char* text) {
      try {
        (void)bs::raw_sidecar_from_json(nlohmann::json::parse(text));
      } catch (const bs::RawSidecarError& e) {
        return std::pair{e.kind(), e.pointer()};
      }
      return std::pair{K::Invalid, std::string("accepted")};
    };
    QVERIFY(kind_of(R"({"height": 2, "bit_depth": 8})") == std::pair(K::Missing, std::string("/width")));
    QVERIFY(kind_of(R"({"width": 2.5, "height": 2, "bit_depth": 8})") ==
            std::pair(K::WrongType, std::string("/width")));
    QVERIFY(kind_of(R"({"width": 2, "height": 2, "bit_depth": 17})") ==
            std::pair(K::Invalid, std::string("/bit_depth")));
    QVERIFY(kind_of(R"({"width": 2, "height": 2, "bit_depth": 12})") ==
            std::pair(K::Missing, std::string("/endianness")));
    QVERIFY(kind_of(R"({"width": 2, "height": 2, "bit_depth": 8, "pattern": "BGRG"})") ==
            std::pair(K::Invalid, std::string("/pattern")));
    QVERIFY(kind_of(R"({"format": "other", "width": 2, "height": 2, "bit_depth": 8})") ==
            std::pair(K::Unsupported, std::string("/format")));
    QVERIFY(kind_of(R"({"version": 2, "width": 2, "height": 2, "bit_depth": 8})") ==
            std::pair(K::Unsupported, std::string("/version")));
    QCOMPARE(kind_of(R"({"width": 4e1, "height": 2, "bit_depth": 8, "pattern": "rggb", "extra": 1})").second,
             std::string("accepted"));
  }

  void both_readers_accept_the_same_files() {
    QTemporaryDir dir;
    const std::string raw = dir.filePath("f.raw").toStdString(), side = dir.filePath("f.json").toStdString();
    // 4x2, 12-bit big-endian: sample k = 0x0100 * k + 3, all below 4096.
    std::string bytes;
    for (int k = 0; k < 8; ++k) bytes += {static_cast<char>(k), 3};
    write(raw, bytes);
    // What the pipeline's reader used to accept (its test's sidecar) and what the importer used to accept
    // (synth-frame's, with format, version, synthetic and lens): both readers read both now.
    for (const char* text :
         {R"({"width": 4, "height": 2, "pattern": "RGGB", "bit_depth": 12, "endianness": "big"})",
          R"({"format": "benchscope-raw", "version": 1, "width": 4, "height": 2, "pattern": "rggb", "bit_depth": 12,
              "endianness": "big", "synthetic": true, "truth": "f-truth.png", "lens": {"format": "benchscope-lens"}})"}) {
      write(side, text);
      QVERIFY2(importer_says(raw).empty(), importer_says(raw).c_str());
      QVERIFY2(pipeline_says(raw).empty(), pipeline_says(raw).c_str());
    }
    // Both find capture.raw.json too (only the pipeline's reader did).
    QVERIFY(QFile::rename(QString::fromStdString(side), QString::fromStdString(raw + ".json")));
    QVERIFY2(importer_says(raw).empty(), importer_says(raw).c_str());
    QVERIFY2(pipeline_says(raw).empty(), pipeline_says(raw).c_str());
    QVERIFY(QFile::remove(QString::fromStdString(raw + ".json")));
    // The documented differences: without a pattern the importer refuses (it must know how to demosaic), the
    // pipeline takes its --pattern; without a byte order above 8 bits both refuse (the pipeline used to guess).
    write(side, R"({"width": 4, "height": 2, "bit_depth": 12, "endianness": "big"})");
    QVERIFY2(importer_says(raw).find("/pattern") != std::string::npos, importer_says(raw).c_str());
    QVERIFY(pipeline_says(raw).empty());
    write(side, R"({"width": 4, "height": 2, "pattern": "RGGB", "bit_depth": 12})");
    QVERIFY(importer_says(raw).find("/endianness") != std::string::npos);
    QVERIFY(pipeline_says(raw).find("/endianness") != std::string::npos);
  }

  void the_papers_capture_reads_the_same_both_ways() {
    const std::string raw = BENCHSCOPE_SOURCE_DIR "/sample_data/paper-2018/frames/paper-capture.raw";
    const bs::ImportBatch batch = bs::import_file(raw, bs::CancelToken{});
    const bs::vision::FrameFile f = bs::vision::read_frame_file(raw);
    QCOMPARE(batch.frames.at(0).width, f.mosaic.cols);
    QCOMPARE(batch.frames.at(0).height, f.mosaic.rows);
    QCOMPARE(batch.frames[0].bit_depth, f.bit_depth);
    QCOMPARE(batch.frames[0].pattern, std::string(bs::vision::to_string(f.pattern)));
    QCOMPARE(std::memcmp(batch.frames[0].pixels.data(), f.mosaic.data, batch.frames[0].pixels.size()), 0);
  }
};

QTEST_APPLESS_MAIN(TestRawSidecar)
#include "test_raw_sidecar.moc"
