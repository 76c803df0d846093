// SPDX-License-Identifier: GPL-3.0-or-later
// Frames in the workspace: imported by reference or as a copy, read back after reopening with the same pixels, a
// referenced file that changed or vanished is an error naming it, and a failing import stores nothing.
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <fstream>

#include "frames/frame_store.h"
#include "store/workspace.h"
#include "workspace/registry.h"

namespace {

void write(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

// A 12-bit RGGB capture, 10 x 6, little-endian, with a sidecar.
std::vector<std::uint16_t> make_capture(const std::string& raw) {
  std::vector<std::uint16_t> values;
  std::string bytes;
  for (int i = 0; i < 60; ++i) {
    const auto v = static_cast<std::uint16_t>((i * 67) % 4096);
    values.push_back(v);
    bytes += static_cast<char>(v & 0xFF);
    bytes += static_cast<char>(v >> 8);
  }
  write(raw, bytes);
  write(raw.substr(0, raw.size() - 4) + ".json",
        R"({"format":"benchscope-raw","version":1,"width":10,"height":6,"pattern":"RGGB","bit_depth":12,
            "endianness":"little","synthetic":true})");
  return values;
}

std::vector<std::uint16_t> values_of(const bs::Frame& f) {
  std::vector<std::uint16_t> v(f.pixels.size() / 2);
  std::memcpy(v.data(), f.pixels.data(), f.pixels.size());
  return v;
}

}  // namespace

class TestFramesStore : public QObject {
  Q_OBJECT
 private slots:
  void copy_survives_reopening_and_the_file() {
    QTemporaryDir dir;
    const std::string raw = dir.filePath("cap.raw").toStdString(), ws_path = dir.filePath("w.bsw").toStdString();
    const auto values = make_capture(raw);
    {
      bs::ImportBatch batch = bs::import_file(raw, bs::CancelToken{});
      batch.frames.at(0).storage = bs::FrameStorage::Copy;
      bs::Workspace ws(ws_path);
      ws.add_import(batch, bs::file_content_hash(raw));
    }
    std::filesystem::remove(raw);  // a copy does not need the file any more
    const bs::Workspace ws(ws_path);
    QCOMPARE(ws.schema_version(), bs::Workspace::kSchemaVersion);
    const auto frames = ws.frames();
    QCOMPARE(frames.size(), std::size_t{1});
    const bs::StoredFrame& s = frames[0];
    QCOMPARE(s.frame.width, 10);
    QCOMPARE(s.frame.height, 6);
    QCOMPARE(s.frame.pattern, std::string("RGGB"));
    QCOMPARE(s.frame.bit_depth, 12);
    QVERIFY(s.frame.synthetic);
    QVERIFY(s.frame.pixels.empty());  // frames() gives the records only
    QCOMPARE(s.frame.storage, bs::FrameStorage::Copy);
    QVERIFY(s.frame.provenance.note.find("synthetic") != std::string::npos);
    QVERIFY(std::filesystem::path(s.path).is_absolute());
    const bs::Frame f = bs::load_frame(ws, s);
    QCOMPARE(values_of(f), values);
  }

  void reference_is_read_again_and_checked() {
    QTemporaryDir dir;
    const std::string raw = dir.filePath("cap.raw").toStdString(), ws_path = dir.filePath("w.bsw").toStdString();
    const auto values = make_capture(raw);
    {
      bs::Workspace ws(ws_path);
      ws.add_import(bs::import_file(raw, bs::CancelToken{}), bs::file_content_hash(raw));
    }
    bs::Workspace ws(ws_path);
    const bs::StoredFrame s = ws.frames().at(0);
    QCOMPARE(s.frame.storage, bs::FrameStorage::Reference);
    QVERIFY(ws.frame_pixels(s.id).empty());
    QCOMPARE(values_of(bs::load_frame(ws, s)), values);
    // The same size, other bytes: the content hash notices.
    std::string changed(120, '\0');
    write(raw, changed);
    try {
      (void)bs::load_frame(ws, s);
      QFAIL("a changed file was accepted");
    } catch (const bs::ImportError& e) {
      QVERIFY2(std::string(e.what()).find("changed since it was imported") != std::string::npos, e.what());
      QVERIFY2(std::string(e.what()).starts_with(s.path), e.what());
    }
    std::filesystem::remove(raw);
    QVERIFY_THROWS_EXCEPTION(bs::ImportError, (void)bs::load_frame(ws, s));
    // Removing the import removes its frame.
    ws.remove_import(s.import_id);
    QVERIFY(ws.frames().empty());
  }

  void failing_import_stores_nothing() {
    QTemporaryDir dir;
    const std::string raw = dir.filePath("cap.raw").toStdString(), ws_path = dir.filePath("w.bsw").toStdString();
    make_capture(raw);
    bs::ImportBatch good = bs::import_file(raw, bs::CancelToken{});
    bs::ImportBatch bad = good;
    bad.frames.push_back(good.frames[0]);
    bad.frames.back().storage = bs::FrameStorage::Copy;
    bad.frames.back().pixels.resize(7);  // the second frame's pixels do not match its geometry
    bs::Workspace ws(ws_path);
    QVERIFY_THROWS_EXCEPTION(bs::WorkspaceError, ws.add_import(bad, "hash-1"));
    QVERIFY(ws.imports().empty());
    QVERIFY(ws.frames().empty());
    bs::CancelToken cancel;
    cancel.cancel();
    QVERIFY_THROWS_EXCEPTION(bs::Cancelled, ws.add_import(good, "hash-2", &cancel));
    QVERIFY(ws.frames().empty());
    ws.add_import(good, "hash-3");
    QCOMPARE(ws.frames().size(), std::size_t{1});
  }

  void cli_import_with_copy_frames() {
    QTemporaryDir dir;
    const QString raw = dir.filePath("cap.raw"), ws_path = dir.filePath("w.bsw");
    const auto values = make_capture(raw.toStdString());
    const QString pgm = dir.filePath("grey.pgm");
    write(pgm.toStdString(), std::string("P5 4 2 255\n") + "abcdefgh");
    QProcess p;
    p.start(BENCHSCOPE_BINARY_DIR "/app/cli/benchscope-cli", {"import", ws_path, raw, pgm, "--copy-frames"});
    QVERIFY(p.waitForFinished(60000));
    QVERIFY2(p.exitCode() == 0, p.readAllStandardError().constData());
    const QByteArray out = p.readAllStandardOutput();
    QVERIFY2(out.contains("frame 10x6 RGGB 12-bit synthetic (copied)"), out.constData());
    const bs::Workspace ws(ws_path.toStdString());
    const auto frames = ws.frames();
    QCOMPARE(frames.size(), std::size_t{2});
    QCOMPARE(values_of(bs::load_frame(ws, frames[0])), values);
    const bs::Frame g = bs::load_frame(ws, frames[1]);
    QCOMPARE(std::string(g.pixels.begin(), g.pixels.end()), std::string("abcdefgh"));
    // The Figure 3 panels from the CLI are core's rendering of the stored frame.
    p.start(BENCHSCOPE_BINARY_DIR "/app/cli/benchscope-cli",
            {"frames", ws_path, "--triptych", "1", "--out", dir.filePath("fig/f3"), "--method", "mhc"});
    QVERIFY(p.waitForFinished(60000));
    QVERIFY2(p.exitCode() == 0, p.readAllStandardError().constData());
    for (const char* suffix : {"-a-mosaic.png", "-b-demosaiced.png", "-c-reprojected.png"})
      QVERIFY(QFile::exists(dir.filePath("fig/f3") + suffix));
    p.start(BENCHSCOPE_BINARY_DIR "/app/cli/benchscope-cli", {"frames", ws_path});
    QVERIFY(p.waitForFinished(60000));
    const QByteArray listing = p.readAllStandardOutput();
    QVERIFY2(listing.contains("10x6") && listing.contains("synthetic") && listing.contains("copy"),
             listing.constData());
    // A broken file among good ones: nothing at all is imported.
    const QString ws2 = dir.filePath("w2.bsw"), broken = dir.filePath("broken.pgm");
    write(broken.toStdString(), "P5 40 20 255\nshort");
    p.start(BENCHSCOPE_BINARY_DIR "/app/cli/benchscope-cli", {"import", ws2, pgm, broken});
    QVERIFY(p.waitForFinished(60000));
    QCOMPARE(p.exitCode(), 1);
    QVERIFY(!QFile::exists(ws2) || bs::Workspace(ws2.toStdString()).frames().empty());
  }
};

QTEST_GUILESS_MAIN(TestFramesStore)
#include "test_frames_store.moc"
