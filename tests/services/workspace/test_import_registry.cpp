// SPDX-License-Identifier: GPL-3.0-or-later
// Sniffing by content and the bad-input corpus: every broken file gives one clear error naming the file and the
// place (line or JSON pointer) with the right category.
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include "common/importer.h"
#include "runs/clpeak_text.h"
#include "runs/google_benchmark_json.h"
#include "runs/run_json.h"
#include "workspace/registry.h"

namespace {
const QString kBad = BENCHSCOPE_TEST_DATA_DIR "/importers/bad/";
const QString kData = BENCHSCOPE_TEST_DATA_DIR "/importers/";

void write(const QString& path, const QByteArray& bytes) {
  QFile f(path);
  QVERIFY(f.open(QIODevice::WriteOnly));
  QCOMPARE(f.write(bytes), bytes.size());
}

QByteArray read(const QString& path) {
  QFile f(path);
  return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

struct Outcome {
  bool threw = false;
  bs::ImportErrorCategory category = bs::ImportErrorCategory::Io;
  QString what;
};

Outcome import(const QString& path) {
  Outcome out;
  try {
    bs::import_file(path.toStdString(), bs::CancelToken{});
  } catch (const bs::ImportError& e) {
    out.threw = true;
    out.category = e.category();
    out.what = QString::fromStdString(e.what());
  }
  return out;
}

QByteArray utf16le(const QByteArray& ascii) {
  QByteArray out;
  for (char c : ascii) out.append(c).append('\0');
  return out;
}
}  // namespace

class TestImportRegistry : public QObject {
  Q_OBJECT
 private slots:
  void knows_its_importers() {
    QVERIFY(bs::find_importer("benchscope-run-v1"));
    QVERIFY(bs::find_importer("google-benchmark-json"));
    QVERIFY(bs::find_importer("clpeak-text"));
    QVERIFY(!bs::find_importer("no-such-format"));
    for (const auto& imp : bs::all_importers()) QCOMPARE(bs::find_importer(imp->id()), imp.get());
  }

  void sniffs_by_content_not_extension() {
    QTemporaryDir dir;
    QVERIFY(QFile::copy(kData + "run-json/two-runs.json", dir.filePath("looks-like.txt")));
    QVERIFY(QFile::copy(kData + "google-benchmark/rotation-repetitions.json", dir.filePath("bench.json")));
    QVERIFY(QFile::copy(kData + "google-benchmark/aggregates-only-nan.json", dir.filePath("results.csv")));
    QVERIFY(QFile::copy(kData + "clpeak/gtx1080ti.txt", dir.filePath("clpeak.json")));
    const bs::CancelToken cancel;
    const auto run = bs::import_file(dir.filePath("looks-like.txt").toStdString(), cancel);
    QCOMPARE(run.format, std::string("benchscope-run-v1"));
    QCOMPARE(run.runs.size(), std::size_t{2});
    QCOMPARE(run.source_path, dir.filePath("looks-like.txt").toStdString());
    QCOMPARE(bs::import_file(dir.filePath("bench.json").toStdString(), cancel).format,
             std::string("google-benchmark-json"));
    QCOMPARE(bs::import_file(dir.filePath("results.csv").toStdString(), cancel).format,
             std::string("google-benchmark-json"));
    QCOMPARE(bs::import_file(dir.filePath("clpeak.json").toStdString(), cancel).format, std::string("clpeak-text"));
  }

  void extension_only_breaks_ties() {
    const bs::FormatImporter run(bs::kRunJsonFileFormat);
    const bs::FormatImporter gbench(bs::kGoogleBenchmarkJsonFileFormat);
    const bs::FormatImporter clpeak(bs::kClpeakTextFileFormat);
    QVERIFY(run.usual_extension("a/b.json") && gbench.usual_extension("x.json") && clpeak.usual_extension("c.txt"));
    QVERIFY(!clpeak.usual_extension("c.json"));
    // The extension alone never makes a format: JSON-named notes are still not run JSON.
    QCOMPARE(run.sniff("just some notes", "notes.json"), 0);
    QCOMPARE(gbench.sniff("just some notes", "notes.json"), 0);
  }

  void strips_a_utf8_bom() {
    QTemporaryDir dir;
    write(dir.filePath("bom.json"), "\xEF\xBB\xBF" + read(kData + "run-json/two-runs.json"));
    QCOMPARE(bs::import_file(dir.filePath("bom.json").toStdString(), bs::CancelToken{}).runs.size(), std::size_t{2});
    write(dir.filePath("bom-only.json"), "\xEF\xBB\xBF \n");
    QCOMPARE(import(dir.filePath("bom-only.json")).category, bs::ImportErrorCategory::Empty);
  }

  // Each file of tests/data/importers/bad/ (category, place, wording) is checked with the whole corpus from
  // tests/data/bad/manifest.json by test_bad_corpus; the checks below are about particular messages.
  void truncation_is_called_so() {
    const Outcome out = import(kBad + "truncated.json");
    QVERIFY2(out.what.contains("unexpected end of file"), qPrintable(out.what));
  }

  void wrong_type_names_line_and_field() {
    const Outcome out = import(kBad + "wrong-type-dims.json");
    QVERIFY2(out.what.contains(":8:") && out.what.contains("/runs/0/params/dims"), qPrintable(out.what));
    const Outcome time = import(kBad + "negative-seconds.json");
    QVERIFY2(time.what.contains("/runs/1/samples/0/seconds/0"), qPrintable(time.what));
  }

  void deep_nesting_file_is_refused() {
    QTemporaryDir dir;
    QByteArray deep = "{\"format\": \"benchscope-run\", \"version\": 1, \"runs\": ";
    deep += QByteArray(10000, '[') + QByteArray(10000, ']') + QByteArray(1, '}');
    write(dir.filePath("deep.json"), deep);
    const Outcome out = import(dir.filePath("deep.json"));
    QVERIFY(out.threw);
    QCOMPARE(out.category, bs::ImportErrorCategory::TooDeep);
    QVERIFY2(out.what.startsWith(dir.filePath("deep.json") + ":1:"), qPrintable(out.what));
  }

  void binary_and_wide_encodings() {
    QTemporaryDir dir;
    QByteArray with_nul;
    for (int i = 0; i < 4096; ++i) with_nul.append(static_cast<char>((i * 37) & 0xff));
    write(dir.filePath("blob.bin"), with_nul);
    QByteArray no_nul;  // high bytes that are not UTF-8, no NUL at all
    for (int i = 0; i < 4096; ++i) no_nul.append(static_cast<char>(0x80 + (i * 13) % 0x7f));
    write(dir.filePath("blob.json"), no_nul);
    const QByteArray json = read(kData + "run-json/two-runs.json");
    write(dir.filePath("utf16-bom.json"), QByteArray("\xFF\xFE", 2) + utf16le(json));
    write(dir.filePath("utf16.json"), utf16le(json));
    QByteArray utf16be;
    for (char c : json) utf16be.append('\0').append(c);
    write(dir.filePath("utf16be.json"), utf16be);
    QByteArray utf32;
    for (char c : json) utf32.append(c).append(QByteArray(3, '\0'));
    write(dir.filePath("utf32.json"), utf32);
    write(dir.filePath("utf32-bom.json"), QByteArray("\xFF\xFE\0\0", 4) + utf32);
    write(dir.filePath("notes.txt"), "just some notes, no data here\n");

    const struct {
      const char* name;
      bs::ImportErrorCategory category;
    } expected[] = {
        {"blob.bin", bs::ImportErrorCategory::Binary},         {"blob.json", bs::ImportErrorCategory::Binary},
        {"utf16-bom.json", bs::ImportErrorCategory::Encoding}, {"utf16.json", bs::ImportErrorCategory::Encoding},
        {"utf16be.json", bs::ImportErrorCategory::Encoding},   {"utf32.json", bs::ImportErrorCategory::Encoding},
        {"utf32-bom.json", bs::ImportErrorCategory::Encoding}, {"notes.txt", bs::ImportErrorCategory::UnknownFormat},
        {"missing.json", bs::ImportErrorCategory::Io}};
    for (const auto& e : expected) {
      const Outcome out = import(dir.filePath(e.name));
      QVERIFY2(out.threw, e.name);
      QVERIFY2(out.category == e.category, qPrintable(QString(e.name) + ": " + out.what));
      QVERIFY2(out.what.startsWith(dir.filePath(e.name)), qPrintable(out.what));
    }
    const Outcome unknown = import(dir.filePath("notes.txt"));
    for (const auto& imp : bs::all_importers())  // the message lists what was tried
      QVERIFY2(unknown.what.contains(QString::fromUtf8(imp->description().data(), imp->description().size())),
               qPrintable(unknown.what));
    QVERIFY(import(dir.path()).category == bs::ImportErrorCategory::Io);  // a folder
  }

  void check_text_tolerates_a_stray_latin1_byte() {
    // "µA" in Latin-1 inside otherwise plain text is text, not binary.
    QByteArray text =
        "time_s,current_\xB5"
        "A\n0,1.5\n1,1.6\n";
    bs::check_text(std::string_view(text.constData(), static_cast<std::size_t>(text.size())), "latin1.csv");
    QVERIFY_THROWS_EXCEPTION(bs::ImportError, bs::check_text(std::string_view("\x01\x02\x03\x04\x05\x06", 6), "c"));
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
      QVERIFY(std::string(e.what()).find("1024") != std::string::npos);
    }
  }
};

QTEST_GUILESS_MAIN(TestImportRegistry)
#include "test_import_registry.moc"
