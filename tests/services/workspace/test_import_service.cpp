// SPDX-License-Identifier: GPL-3.0-or-later
// The import service (services/workspace/import_service.h) that the CLI and the GUI share: folder order, skipped files
// and their reasons, duplicates by content, all-or-nothing batches, cancel and progress.
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QTest>

#include "store/workspace.h"
#include "workspace/import_service.h"

namespace {

const QString kPaper = BENCHSCOPE_SOURCE_DIR "/sample_data/paper-2018";
using Kind = bs::FileOutcome::Kind;

void write(const QString& path, const QByteArray& bytes) {
  QDir().mkpath(QFileInfo(path).path());
  QFile f(path);
  QVERIFY(f.open(QIODevice::WriteOnly));
  QCOMPARE(f.write(bytes), bytes.size());
}

void copy(const QString& from, const QString& to) {
  QDir().mkpath(QFileInfo(to).path());
  QVERIFY2(QFile::copy(from, to), qPrintable(from + " -> " + to));
}

// A folder as a lab hands it over: two run files, a power log in a subfolder, a README, a hidden file.
void make_lab_folder(const QString& dir) {
  copy(kPaper + "/gpu-nuc.json", dir + "/b-gpu-nuc.json");
  copy(kPaper + "/cpu.json", dir + "/a-cpu.json");
  copy(kPaper + "/power/nuc-current.csv", dir + "/logs/nuc.csv");
  write(dir + "/README.md", "# Measurements of 20 November\nNothing to import here.\n");
  write(dir + "/.notes.json", "{ not even json");
}

std::string s(const QString& q) { return q.toStdString(); }

std::size_t imports_in(const QString& ws) { return bs::Workspace(s(ws)).imports().size(); }

}  // namespace

class TestImportService : public QObject {
  Q_OBJECT
 private slots:
  void folders_expand_in_a_stable_order_without_hidden_files() {
    QTemporaryDir dir;
    make_lab_folder(dir.path());
    const auto files = bs::expand_import_paths({s(dir.filePath("logs/nuc.csv")), s(dir.path())});
    QCOMPARE(files.size(), std::size_t{5});  // the named file, then the folder's four (not .notes.json)
    QCOMPARE(files[0].path, s(dir.filePath("logs/nuc.csv")));
    QVERIFY(!files[0].from_folder);
    const std::vector<std::string> walked{s(dir.filePath("README.md")), s(dir.filePath("a-cpu.json")),
                                          s(dir.filePath("b-gpu-nuc.json")), s(dir.filePath("logs/nuc.csv"))};
    for (std::size_t i = 0; i < walked.size(); ++i) {
      QCOMPARE(files[i + 1].path, walked[i]);  // byte order: 'R' (0x52) sorts before 'a' (0x61)
      QVERIFY(files[i + 1].from_folder);
    }
  }

  void unknown_files_in_a_folder_are_skipped_with_a_reason_but_named_ones_fail() {
    QTemporaryDir dir;
    make_lab_folder(dir.filePath("lab"));
    const QString ws = dir.filePath("w.bsw");
    const auto r = bs::import_paths(s(ws), {s(dir.filePath("lab"))});
    QCOMPARE(r.files.size(), std::size_t{4});
    QCOMPARE(r.count(Kind::Imported), 3);
    QCOMPARE(r.files[0].kind, Kind::NotData);
    QVERIFY(r.files[0].reason.find("not a format BenchScope reads") != std::string::npos);
    QVERIFY(r.committed);
    QCOMPARE(imports_in(ws), std::size_t{3});
    QCOMPARE(r.files[1].summary, std::string("4 runs (benchscope-run-v1)"));  // paper-2018/cpu.json holds 4 runs
    QVERIFY(r.files[1].import_id > 0);
    // The same README named on its own is the user's mistake, not a file to pass over.
    const auto named = bs::import_paths(s(ws), {s(dir.filePath("lab/README.md"))});
    QCOMPARE(named.files.at(0).kind, Kind::Failed);
    QVERIFY(named.files[0].reason.starts_with(s(dir.filePath("lab/README.md"))));
    QVERIFY(!named.committed);
  }

  void duplicates_are_found_by_content_under_any_name() {
    QTemporaryDir dir;
    make_lab_folder(dir.filePath("lab"));
    copy(kPaper + "/cpu.json", dir.filePath("renamed.json"));
    const QString ws = dir.filePath("w.bsw");
    QCOMPARE(bs::import_paths(s(ws), {s(dir.filePath("lab"))}).count(Kind::Imported), 3);
    const auto again = bs::import_paths(s(ws), {s(dir.filePath("lab")), s(dir.filePath("renamed.json"))});
    QCOMPARE(again.count(Kind::Duplicate), 4);
    QCOMPARE(again.count(Kind::Imported), 0);
    QVERIFY(!again.committed);
    const bs::FileOutcome& renamed = again.files.back();
    QCOMPARE(renamed.earlier_path, s(dir.filePath("lab/a-cpu.json")));
    QCOMPARE(renamed.earlier_imported_at.size(), std::size_t{20});  // 2026-11-21T18:00:00Z
    QVERIFY(renamed.reason.starts_with("already imported on 20"));
    QCOMPARE(imports_in(ws), std::size_t{3});
    // Two copies in one all-or-nothing import: the second is skipped, naming the first.
    const QString ws2 = dir.filePath("w2.bsw");
    bs::ImportOptions all;
    all.atomicity = bs::ImportAtomicity::AllOrNothing;
    const auto twins = bs::import_paths(s(ws2), {s(kPaper + "/cpu.json"), s(dir.filePath("renamed.json"))}, all);
    QCOMPARE(twins.files[0].kind, Kind::Imported);
    QCOMPARE(twins.files[1].kind, Kind::Duplicate);
    QCOMPARE(twins.files[1].earlier_path, s(kPaper + "/cpu.json"));
    QVERIFY(twins.files[1].earlier_imported_at.empty());
    QVERIFY(twins.files[1].reason.find("earlier in this import") != std::string::npos);
    QCOMPARE(imports_in(ws2), std::size_t{1});
    // One file at a time, the second copy meets the first already in the workspace.
    const QString ws3 = dir.filePath("w3.bsw");
    const auto each = bs::import_paths(s(ws3), {s(kPaper + "/cpu.json"), s(dir.filePath("renamed.json"))});
    QCOMPARE(each.files[1].kind, Kind::Duplicate);
    QCOMPARE(each.files[1].earlier_path, s(kPaper + "/cpu.json"));
    QVERIFY(!each.files[1].earlier_imported_at.empty());
  }

  void all_or_nothing_stores_nothing_when_one_file_fails() {
    QTemporaryDir dir;
    make_lab_folder(dir.filePath("lab"));
    write(dir.filePath("lab/broken.json"), R"({"format": "benchscope-run", "version": 1, "runs": [)");
    bs::ImportOptions all;
    all.atomicity = bs::ImportAtomicity::AllOrNothing;
    const QString ws = dir.filePath("w.bsw");
    const auto r = bs::import_paths(s(ws), {s(dir.filePath("lab"))}, all);
    QCOMPARE(r.count(Kind::Failed), 1);
    QCOMPARE(r.count(Kind::NotReached), 3);  // parsed fine, not stored because of broken.json
    QCOMPARE(r.count(Kind::NotData), 1);
    QVERIFY(!r.committed);
    QVERIFY(!QFileInfo::exists(ws));  // not even created
    // Each file on its own: the good ones are stored, the broken one fails alone.
    const auto each = bs::import_paths(s(ws), {s(dir.filePath("lab"))});
    QCOMPARE(each.count(Kind::Imported), 3);
    QCOMPARE(each.count(Kind::Failed), 1);
    QCOMPARE(imports_in(ws), std::size_t{3});
    // All good: one transaction stores every file.
    const QString ws2 = dir.filePath("w2.bsw");
    QVERIFY(QFile::remove(dir.filePath("lab/broken.json")));
    const auto good = bs::import_paths(s(ws2), {s(dir.filePath("lab"))}, all);
    QVERIFY(good.committed);
    QCOMPARE(imports_in(ws2), std::size_t{3});
    for (const auto& f : good.files)
      if (f.kind == Kind::Imported) QVERIFY(f.import_id > 0);
  }

  void cancel_keeps_what_is_done_per_file_and_nothing_per_batch() {
    QTemporaryDir dir;
    make_lab_folder(dir.filePath("lab"));
    for (const auto atomicity : {bs::ImportAtomicity::EachFile, bs::ImportAtomicity::AllOrNothing}) {
      const QString ws = dir.filePath(atomicity == bs::ImportAtomicity::EachFile ? "each.bsw" : "all.bsw");
      bs::CancelToken cancel;
      std::vector<int> seen;
      bs::ImportOptions o;
      o.atomicity = atomicity;
      o.progress = [&](int done, int total, const std::string&) {
        seen.push_back(done);
        QCOMPARE(total, 4);
        if (done == 2) cancel.cancel();  // README and a-cpu.json are done, the user presses Cancel
      };
      const auto r = bs::import_paths(s(ws), {s(dir.filePath("lab"))}, o, cancel);
      QVERIFY(r.cancelled);
      QCOMPARE(seen, (std::vector<int>{0, 1, 2, 4}));  // then once more at the end: 4 of 4
      QCOMPARE(r.files[2].kind, Kind::NotReached);
      QCOMPARE(r.files[3].kind, Kind::NotReached);
      if (atomicity == bs::ImportAtomicity::EachFile) {
        QCOMPARE(r.files[1].kind, Kind::Imported);
        QCOMPARE(imports_in(ws), std::size_t{1});
      } else {
        QCOMPARE(r.files[1].kind, Kind::NotReached);
        QVERIFY(!QFileInfo::exists(ws));
      }
    }
  }

  void progress_counts_every_file_and_ends_at_the_total() {
    QTemporaryDir dir;
    make_lab_folder(dir.filePath("lab"));
    std::vector<std::pair<int, std::string>> calls;
    bs::ImportOptions o;
    o.progress = [&](int done, int, const std::string& path) { calls.emplace_back(done, path); };
    (void)bs::import_paths(s(dir.filePath("w.bsw")), {s(dir.filePath("lab"))}, o);
    QCOMPARE(calls.size(), std::size_t{5});
    QCOMPARE(calls.back(), (std::pair<int, std::string>{4, ""}));
    QCOMPARE(calls[3].second, s(dir.filePath("lab/logs/nuc.csv")));
  }
};

QTEST_APPLESS_MAIN(TestImportService)
#include "test_import_service.moc"
