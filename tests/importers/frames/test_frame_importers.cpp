// SPDX-License-Identifier: GPL-3.0-or-later
// Frame importers: raw Bayer + sidecar (8/16-bit, both byte orders), raw with explicit geometry, PGM/PPM, PNG and
// TIFF through OpenCV; and the broken cases: size mismatch, huge claims (refused before allocating), truncation.
#include <QTemporaryDir>
#include <QTest>

#include <cstring>
#include <fstream>

#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "frames/frame_raw.h"
#include "workspace/registry.h"

namespace {

void write(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

std::string le16(std::uint16_t v) { return {static_cast<char>(v & 0xFF), static_cast<char>(v >> 8)}; }
std::string be16(std::uint16_t v) { return {static_cast<char>(v >> 8), static_cast<char>(v & 0xFF)}; }

std::uint16_t sample16(const bs::Frame& f, std::size_t i) {
  std::uint16_t v;
  std::memcpy(&v, f.pixels.data() + 2 * i, 2);
  return v;
}

struct Failure {
  bool threw = false;
  bs::ImportErrorCategory category = bs::ImportErrorCategory::Io;
  std::string what, field;
};

template <class F>
Failure failure(F&& f) {
  try {
    f();
  } catch (const bs::ImportError& e) {
    return {true, e.category(), e.what(), e.location().field};
  }
  return {};
}

Failure import_failure(const std::string& path) {
  return failure([&] { (void)bs::import_file(path, bs::CancelToken{}); });
}

std::string read_all(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(f), {});
}

}  // namespace

class TestFrameImporters : public QObject {
  Q_OBJECT
  QTemporaryDir dir_;
  std::string at(const char* name) { return dir_.filePath(name).toStdString(); }

 private slots:
  void raw_8bit_with_sidecar() {
    std::string px;
    for (int i = 0; i < 6 * 4; ++i) px += static_cast<char>(i * 10);
    write(at("cap.raw"), px);
    write(at("cap.json"), R"({"format":"benchscope-raw","version":1,"width":6,"height":4,"pattern":"rggb",
                             "bit_depth":8,"endianness":"little","synthetic":true,
                             "lens":{"format":"benchscope-lens"}})");
    const auto batch = bs::import_file(at("cap.raw"), bs::CancelToken{});
    QCOMPARE(batch.format, std::string("raw-bayer"));
    QCOMPARE(batch.frames.size(), std::size_t{1});
    const bs::Frame& f = batch.frames[0];
    QCOMPARE(f.width, 6);
    QCOMPARE(f.height, 4);
    QCOMPARE(f.pattern, std::string("RGGB"));
    QCOMPARE(f.bit_depth, 8);
    QVERIFY(f.synthetic);
    QVERIFY(f.provenance.note.find("synthetic") != std::string::npos);
    QCOMPARE(f.lens_json, std::string(R"({"format":"benchscope-lens"})"));
    QCOMPARE(f.pixels.size(), std::size_t{24});
    QCOMPARE(int(f.pixels[23]), 230);
    QCOMPARE(f.label, std::string("cap"));
  }

  void raw_16bit_both_byte_orders() {
    std::string le, be;
    for (int i = 0; i < 8; ++i) {
      le += le16(static_cast<std::uint16_t>(i * 500));
      be += be16(static_cast<std::uint16_t>(i * 500));
    }
    write(at("le.raw"), le);
    write(at("le.json"), R"({"width":4,"height":2,"pattern":"GBRG","bit_depth":12,"endianness":"little"})");
    write(at("be.raw"), be);
    write(at("be.json"), R"({"width":4,"height":2,"pattern":"GBRG","bit_depth":12,"endianness":"big"})");
    for (const char* name : {"le.raw", "be.raw"}) {
      const bs::Frame f = bs::import_file(at(name), bs::CancelToken{}).frames.at(0);
      QCOMPARE(f.bit_depth, 12);
      QCOMPARE(f.bytes_per_sample(), 2);
      for (std::size_t i = 0; i < 8; ++i) QCOMPARE(int(sample16(f, i)), int(i * 500));
    }
    // Read with the wrong byte order, 3500 = 0x0DAC becomes 0xAC0D = 44045 > 4095: refused, naming the offset.
    write(at("wrong.raw"), be);
    write(at("wrong.json"), R"({"width":4,"height":2,"pattern":"GBRG","bit_depth":12,"endianness":"little"})");
    const Failure e = import_failure(at("wrong.raw"));
    QVERIFY(e.threw);
    QCOMPARE(e.category, bs::ImportErrorCategory::InvalidValue);
    QVERIFY2(e.field.starts_with("offset "), e.what.c_str());
    QVERIFY2(e.what.find("byte order") != std::string::npos, e.what.c_str());
  }

  void raw_needs_a_sidecar_or_explicit_geometry() {
    write(at("bare.raw"), std::string(32, '\x07'));
    const Failure e = import_failure(at("bare.raw"));
    QCOMPARE(e.category, bs::ImportErrorCategory::MissingField);
    QVERIFY2(e.what.starts_with(at("bare.raw")) && e.what.find("sidecar") != std::string::npos, e.what.c_str());
    const bs::RawFrameOptions o = bs::parse_raw_geometry("8x4:grbg:8");
    QCOMPARE(o.pattern, std::string("GRBG"));
    const bs::Frame f = bs::read_raw_frame(at("bare.raw"), o).frames.at(0);
    QCOMPARE(f.width, 8);
    QCOMPARE(int(f.pixels[31]), 7);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, bs::parse_raw_geometry("8by4"));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, bs::parse_raw_geometry("8x4:XYZW"));
    // Wrong geometry: 8x8 needs 64 bytes.
    const Failure wrong = failure([&] { (void)bs::read_raw_frame(at("bare.raw"), bs::parse_raw_geometry("8x8")); });
    QCOMPARE(wrong.category, bs::ImportErrorCategory::InvalidValue);
    QVERIFY2(wrong.what.find("32 bytes") != std::string::npos && wrong.what.find("64 bytes") != std::string::npos,
             wrong.what.c_str());
  }

  void raw_size_mismatch_and_huge_claims() {
    write(at("short.raw"), std::string(100, '\0'));
    write(at("short.json"), R"({"width":64,"height":64,"pattern":"BGGR","bit_depth":8})");
    Failure e = import_failure(at("short.raw"));
    QCOMPARE(e.category, bs::ImportErrorCategory::InvalidValue);
    QCOMPARE(e.field, std::string("size"));
    QVERIFY2(e.what.find("100 bytes") != std::string::npos && e.what.find("4096 bytes") != std::string::npos,
             e.what.c_str());
    // 100000 x 100000 would be 10 GB: refused from the sidecar alone, before the raw file is even opened.
    write(at("huge.raw"), std::string(16, '\0'));
    write(at("huge.json"), R"({"width":100000,"height":100000,"pattern":"BGGR","bit_depth":8})");
    e = import_failure(at("huge.raw"));
    QCOMPARE(e.category, bs::ImportErrorCategory::TooLarge);
    QVERIFY2(e.what.starts_with(at("huge.raw")) && e.what.find("huge.json") != std::string::npos, e.what.c_str());
    QVERIFY2(e.field.find("/width") != std::string::npos, e.what.c_str());
    // Within the per-side limit but over the pixel limit.
    write(at("wide.json"), R"({"width":60000,"height":60000,"pattern":"BGGR","bit_depth":8})");
    write(at("wide.raw"), std::string(16, '\0'));
    QCOMPARE(import_failure(at("wide.raw")).category, bs::ImportErrorCategory::TooLarge);
    // Bad sidecar values name the field and its line.
    write(at("badpat.raw"), std::string(4, '\0'));
    write(at("badpat.json"), "{\"width\":2,\"height\":2,\n\"pattern\":\"XGGR\",\"bit_depth\":8}");
    e = import_failure(at("badpat.raw"));
    QCOMPARE(e.category, bs::ImportErrorCategory::InvalidValue);
    QVERIFY2(e.field.find("/pattern") != std::string::npos, e.what.c_str());
    write(at("noend.raw"), std::string(8, '\0'));
    write(at("noend.json"), R"({"width":2,"height":2,"pattern":"BGGR","bit_depth":10})");
    QCOMPARE(import_failure(at("noend.raw")).category, bs::ImportErrorCategory::MissingField);
  }

  void pgm_and_ppm() {
    const std::string data = BENCHSCOPE_TEST_DATA_DIR "/importers/frames/pnm/";
    bs::Frame f = bs::import_file(data + "grey-8bit-comments.pgm", bs::CancelToken{}).frames.at(0);
    QCOMPARE(f.source_format, std::string("pnm"));
    QCOMPARE(f.width, 6);
    QCOMPARE(f.height, 4);
    QCOMPARE(f.pattern, std::string("RGGB"));  // from the "# pattern: RGGB" comment
    const std::string bytes = read_all(data + "grey-8bit-comments.pgm");
    QCOMPARE(std::memcmp(f.pixels.data(), bytes.data() + bytes.size() - 24, 24), 0);

    f = bs::import_file(data + "grey-10bit.pgm", bs::CancelToken{}).frames.at(0);
    QCOMPARE(f.bit_depth, 10);                 // maxval 1023
    QCOMPARE(f.pattern, std::string("BGGR"));  // the default
    const std::string b10 = read_all(data + "grey-10bit.pgm");
    const std::size_t body = b10.size() - 24;
    for (std::size_t i = 0; i < 12; ++i) {
      const int expected =
          (static_cast<unsigned char>(b10[body + 2 * i]) << 8) | static_cast<unsigned char>(b10[body + 2 * i + 1]);
      QCOMPARE(int(sample16(f, i)), expected);  // big-endian in the file, host order in memory
    }
    f = bs::import_file(data + "colour-16bit.ppm", bs::CancelToken{}).frames.at(0);
    QCOMPARE(f.channels, 3);
    QCOMPARE(f.bit_depth, 16);
    QVERIFY(f.pattern.empty());

    Failure e = import_failure(data + "truncated.pgm");
    QCOMPARE(e.category, bs::ImportErrorCategory::Syntax);
    QVERIFY2(e.what.find("truncated") != std::string::npos && e.field.starts_with("offset"), e.what.c_str());
    QCOMPARE(import_failure(data + "ascii-p2.pgm").category, bs::ImportErrorCategory::Unsupported);

    write(at("huge.pgm"), "P5\n100000 100000\n255\n" + std::string(64, '\0'));
    e = import_failure(at("huge.pgm"));
    QCOMPARE(e.category, bs::ImportErrorCategory::TooLarge);
    QVERIFY2(e.field.find("width") != std::string::npos, e.what.c_str());
    write(at("over.pgm"), "P5 2 2 100\n" + std::string("\x01\x02\x03\x65", 4));  // 101 > maxval 100
    e = import_failure(at("over.pgm"));
    QCOMPARE(e.category, bs::ImportErrorCategory::InvalidValue);
    QCOMPARE(e.field, std::string("offset 14"));
    write(at("garbage.pgm"), "P5 2 x 255\n" + std::string(4, '\0'));
    QCOMPARE(import_failure(at("garbage.pgm")).category, bs::ImportErrorCategory::Syntax);
  }

  void png_and_tiff_8_and_16_bit() {
    cv::Mat grey8(48, 64, CV_8UC1), colour8(48, 64, CV_8UC3), grey16(48, 64, CV_16UC1);
    cv::randu(grey8, 0, 256);
    cv::randu(colour8, 0, 256);
    cv::randu(grey16, 0, 65536);
    QVERIFY(cv::imwrite(at("g8.png"), grey8));
    QVERIFY(cv::imwrite(at("c8.png"), colour8));
    QVERIFY(cv::imwrite(at("g16.png"), grey16));
    QVERIFY(cv::imwrite(at("g16.tif"), grey16));
    QVERIFY(cv::imwrite(at("c8.tiff"), colour8));
    const auto check = [&](const char* name, const cv::Mat& want, const char* format) {
      const auto batch = bs::import_file(at(name), bs::CancelToken{});
      QCOMPARE(batch.format, std::string(format));
      const bs::Frame& f = batch.frames.at(0);
      QCOMPARE(f.width, want.cols);
      QCOMPARE(f.height, want.rows);
      QCOMPARE(f.channels, want.channels());
      QCOMPARE(f.bit_depth, want.depth() == CV_16U ? 16 : 8);
      QCOMPARE(f.pixels.size(), want.total() * want.elemSize());
      QCOMPARE(std::memcmp(f.pixels.data(), want.data, f.pixels.size()), 0);
    };
    check("g8.png", grey8, "png");
    check("c8.png", colour8, "png");
    check("g16.png", grey16, "png");
    check("g16.tif", grey16, "tiff");
    check("c8.tiff", colour8, "tiff");
  }

  void truncated_png_and_tiff() {
    cv::Mat img(200, 300, CV_8UC3);
    cv::randu(img, 0, 256);  // noise does not compress: the IDAT data is large
    QVERIFY(cv::imwrite(at("full.png"), img));
    QVERIFY(cv::imwrite(at("full.tif"), img));
    const std::string png = read_all(at("full.png")), tif = read_all(at("full.tif"));
    write(at("cut.png"), png.substr(0, png.size() / 2));
    Failure e = import_failure(at("cut.png"));
    QCOMPARE(e.category, bs::ImportErrorCategory::Syntax);
    QVERIFY2(e.what.find("truncated") != std::string::npos && e.field.starts_with("offset "), e.what.c_str());
    write(at("noend.png"), png.substr(0, png.size() - 12));  // IEND cut off exactly
    QCOMPARE(import_failure(at("noend.png")).category, bs::ImportErrorCategory::Syntax);
    write(at("cut.tif"), tif.substr(0, tif.size() / 2));
    e = import_failure(at("cut.tif"));
    QCOMPARE(e.category, bs::ImportErrorCategory::Syntax);
    QVERIFY2(e.what.find("truncated") != std::string::npos, e.what.c_str());
    // An IHDR claiming 100000 x 100000: refused from the header, OpenCV never sees it.
    std::string huge = png;
    const std::string side = std::string("\x00\x01\x86\xA0", 4);  // 100000 big-endian
    huge.replace(16, 4, side);
    huge.replace(20, 4, side);
    write(at("huge.png"), huge);
    e = import_failure(at("huge.png"));
    QCOMPARE(e.category, bs::ImportErrorCategory::TooLarge);
    QVERIFY2(e.field.find("IHDR") != std::string::npos, e.what.c_str());
  }

  void sniffing_by_content_not_name() {
    cv::Mat img(8, 8, CV_8UC1, cv::Scalar(3));
    QVERIFY(cv::imwrite(at("really-png.png"), img));
    write(at("named.tif"), read_all(at("really-png.png")));
    QCOMPARE(bs::import_file(at("named.tif"), bs::CancelToken{}).format, std::string("png"));
    // A .bin of random bytes is still "binary", not a frame.
    write(at("blob.bin"), std::string("\x01\x00\xff\x10", 4) + std::string(100, '\0'));
    QCOMPARE(import_failure(at("blob.bin")).category, bs::ImportErrorCategory::Binary);
  }
};

QTEST_APPLESS_MAIN(TestFrameImporters)
#include "test_frame_importers.moc"
