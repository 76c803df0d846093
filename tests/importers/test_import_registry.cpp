// SPDX-License-Identifier: GPL-3.0-or-later
// Sniffing by content and the bad-input corpus: every broken file gives one clear error naming the file.
#include <QtTest>

#include "importer.h"

namespace {
const QString kBad = BENCHSCOPE_TEST_DATA_DIR "/importers/bad/";

void write(const QString& path, const QByteArray& bytes) {
  QFile f(path);
  QVERIFY(f.open(QIODevice::WriteOnly));
  f.write(bytes);
}
}  // namespace

class TestImportRegistry : public QObject {
  Q_OBJECT
 private slots:
  void sniffs_by_content_not_extension() {
    QTemporaryDir dir;
    QFile::copy(BENCHSCOPE_TEST_DATA_DIR "/importers/run-json/two-runs.json", dir.filePath("looks-like.txt"));
    QFile::copy(BENCHSCOPE_TEST_DATA_DIR "/importers/google-benchmark/rotation-repetitions.json", dir.filePath("bench.json"));
    QFile::copy(BENCHSCOPE_TEST_DATA_DIR "/importers/clpeak/gtx1080ti.txt", dir.filePath("clpeak.json"));
    const bs::CancelToken cancel;
    QCOMPARE(bs::import_file(dir.filePath("looks-like.txt").toStdString(), cancel).format, std::string("benchscope-run-v1"));
    QCOMPARE(bs::import_file(dir.filePath("bench.json").toStdString(), cancel).format, std::string("google-benchmark-json"));
    QCOMPARE(bs::import_file(dir.filePath("clpeak.json").toStdString(), cancel).format, std::string("clpeak-text"));
  }

  void bad_corpus_data() {
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("category");
    QTest::addColumn<QString>("where");  // text the message must contain besides the file name
    QTest::newRow("empty") << "empty.json" << "empty" << "empty";
    QTest::newRow("whitespace") << "whitespace.json" << "empty" << "whitespace";
    QTest::newRow("truncated") << "truncated.json" << "syntax" << "truncated";
    QTest::newRow("nan") << "nan.json" << "syntax" << ":16:";
    QTest::newRow("overflow") << "overflow.json" << "invalid-value" << "out of range";
    QTest::newRow("wrong type") << "wrong-type-dims.json" << "wrong-type" << "/runs/0/params/dims";
    QTest::newRow("missing runs") << "missing-runs.json" << "missing-field" << "/runs";
    QTest::newRow("negative time") << "negative-seconds.json" << "invalid-value" << "/runs/1/samples/0/seconds/0";
    QTest::newRow("workers order") << "workers-not-ascending.json" << "invalid-value" << "/runs/0/samples/1/workers";
    QTest::newRow("newer version") << "version-2.json" << "unsupported" << "newer";
    QTest::newRow("clpeak no device") << "clpeak-no-device.txt" << "missing-field" << "Device";
    QTest::newRow("gbench wrong type") << "gbench-benchmarks-not-array.json" << "wrong-type" << "/benchmarks";
  }
  void bad_corpus() {
    QFETCH(QString, file);
    QFETCH(QString, category);
    QFETCH(QString, where);
    const std::string path = (kBad + file).toStdString();
    try {
      bs::import_file(path, bs::CancelToken{});
      QFAIL("bad file accepted");
    } catch (const bs::ImportError& e) {
      const QString what = QString::fromStdString(e.what());
      QCOMPARE(QString::fromUtf8(bs::to_string(e.category()).data()), category);
      QVERIFY2(what.startsWith(QString::fromStdString(path)), qPrintable(what));
      QVERIFY2(what.contains(where), qPrintable(what));
      QVERIFY2(!what.contains('\n'), "one line");
    }
  }

  void binary_utf16_and_unknown() {
    QTemporaryDir dir;
    QByteArray binary;
    for (int i = 0; i < 4096; ++i) binary.append(static_cast<char>((i * 37) & 0xff));
    write(dir.filePath("blob.bin"), binary);
    QByteArray utf16("\xFF\xFE", 2);
    for (char c : QByteArray("{\"format\": \"benchscope-run\"}")) utf16.append(c).append('\0');
    write(dir.filePath("utf16.json"), utf16);
    write(dir.filePath("notes.txt"), "just some notes, no data here\n");
    const bs::CancelToken cancel;
    QVERIFY_THROWS_EXCEPTION(bs::ImportError, bs::import_file(dir.filePath("blob.bin").toStdString(), cancel));
    auto category_of = [&](const char* name) {
      try {
        bs::import_file(dir.filePath(name).toStdString(), cancel);
      } catch (const bs::ImportError& e) {
        return e.category();
      }
      return bs::ImportErrorCategory::Io;
    };
    QCOMPARE(category_of("blob.bin"), bs::ImportErrorCategory::Binary);
    QCOMPARE(category_of("utf16.json"), bs::ImportErrorCategory::Encoding);
    QCOMPARE(category_of("notes.txt"), bs::ImportErrorCategory::UnknownFormat);
    QCOMPARE(category_of("missing.json"), bs::ImportErrorCategory::Io);
  }

  void size_is_checked_before_reading() {
    QTemporaryDir dir;
    write(dir.filePath("big.json"), QByteArray(2048, ' ') + "{\"format\": \"benchscope-run\"}");
    bs::ImportLimits limits;
    limits.max_json_bytes = 1024;
    try {
      bs::import_file(dir.filePath("big.json").toStdString(), bs::CancelToken{}, limits);
      QFAIL("accepted");
    } catch (const bs::ImportError& e) {
      QCOMPARE(e.category(), bs::ImportErrorCategory::TooLarge);
    }
  }
};

QTEST_GUILESS_MAIN(TestImportRegistry)
#include "test_import_registry.moc"
