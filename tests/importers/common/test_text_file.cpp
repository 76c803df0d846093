// SPDX-License-Identifier: GPL-3.0-or-later
// parse_text_file(): the one path from a file to a whole-document parser. The parser gets the text without a UTF-8
// byte-order mark, the path and the caller's options and limits; a file over the limit, a missing file and a folder
// are refused naming the file before any parser runs.
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include "common/text_file.h"

#include "../../support/import_errors.h"

namespace {

void write(const QString& path, const QByteArray& bytes) {
  QFile f(path);
  QVERIFY(f.open(QIODevice::WriteOnly));
  QCOMPARE(f.write(bytes), bytes.size());
}

// What the parser last saw (a TextParser is a plain function, so it reports through here).
struct Seen {
  int calls = 0;
  std::string text, file, platform;
  std::size_t max_json_bytes = 0;
};
Seen seen;

bs::ImportBatch record(const std::string& text, const std::string& file, const bs::ParseOptions& options,
                       const bs::ImportLimits& limits, const bs::CancelToken& /*cancel*/) {
  ++seen.calls;
  seen.text = text;
  seen.file = file;
  seen.platform = options.platform;
  seen.max_json_bytes = limits.max_json_bytes;
  return {};
}

}  // namespace

class TestTextFile : public QObject {
  Q_OBJECT
 private slots:
  void init() { seen = {}; }

  void strips_a_utf8_bom_and_passes_the_rest_through() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("bom.txt").toStdString();
    write(QString::fromStdString(path), "\xEF\xBB\xBF{\"a\": 1}\n");
    bs::ParseOptions options;
    options.platform = "NUC";
    bs::ImportLimits limits;
    limits.max_json_bytes = 4096;
    (void)bs::parse_text_file(path, options, limits, bs::CancelToken{}, record);
    QCOMPARE(seen.calls, 1);
    QCOMPARE(seen.text, std::string("{\"a\": 1}\n"));
    QCOMPARE(seen.file, path);
    QCOMPARE(seen.platform, std::string("NUC"));
    QCOMPARE(seen.max_json_bytes, std::size_t{4096});
    // Only a leading mark is dropped; text without one is passed as it is.
    write(QString::fromStdString(path), "x\xEF\xBB\xBF");
    (void)bs::parse_text_file(path, {}, {}, bs::CancelToken{}, record);
    QCOMPARE(seen.text, std::string("x\xEF\xBB\xBF"));
    QCOMPARE(bs::strip_utf8_bom("\xEF\xBB\xBF"), std::string_view());
    QCOMPARE(bs::strip_utf8_bom("\xEF\xBB"), std::string_view("\xEF\xBB"));
  }

  void refuses_a_file_over_the_limit_naming_it() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("big.json").toStdString();
    write(QString::fromStdString(path), QByteArray(2048, ' '));
    bs::ImportLimits limits;
    limits.max_json_bytes = 1024;
    const bs::ImportError e =
        bs::test::import_error_of([&] { return bs::parse_text_file(path, {}, limits, bs::CancelToken{}, record); });
    QCOMPARE(e.category(), bs::ImportErrorCategory::TooLarge);
    QCOMPARE(e.location().file, path);
    QVERIFY2(std::string(e.what()).find(path) != std::string::npos, e.what());
    QVERIFY2(std::string(e.what()).find("1024") != std::string::npos, e.what());
    QCOMPARE(seen.calls, 0);
  }

  void refuses_a_missing_file_and_a_folder() {
    QTemporaryDir dir;
    const std::string missing = dir.filePath("missing.json").toStdString();
    bs::ImportError e =
        bs::test::import_error_of([&] { return bs::parse_text_file(missing, {}, {}, bs::CancelToken{}, record); });
    QCOMPARE(e.category(), bs::ImportErrorCategory::Io);
    QCOMPARE(e.location().file, missing);
    const std::string folder = dir.path().toStdString();
    e = bs::test::import_error_of([&] { return bs::parse_text_file(folder, {}, {}, bs::CancelToken{}, record); });
    QCOMPARE(e.category(), bs::ImportErrorCategory::Io);
    QCOMPARE(e.location().file, folder);
    QCOMPARE(seen.calls, 0);
  }

  void a_cancel_stops_before_parsing() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("a.txt").toStdString();
    write(QString::fromStdString(path), "text\n");
    bs::CancelToken cancel;
    cancel.cancel();
    QVERIFY_THROWS_EXCEPTION(bs::Cancelled, bs::parse_text_file(path, {}, {}, cancel, record));
    QCOMPARE(seen.calls, 0);
  }
};

QTEST_GUILESS_MAIN(TestTextFile)
#include "test_text_file.moc"
