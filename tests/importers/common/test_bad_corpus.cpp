// SPDX-License-Identifier: GPL-3.0-or-later
// Every file of the bad-input corpus is rejected with its expected category and a clear message: the file, the
// place (line or field) where the manifest says there is one, the text it lists under "contains", and a reason.
// The corpus is tests/data/bad/, tests/data/importers/bad/ and tests/data/power/bad/, all under one manifest, plus a
// few real files other people published (the shared folder's tests/data/bad/), checked apart: they skip without it.
#include <QTemporaryDir>
#include <QTest>

#include "../../support/bad_corpus.h"
#include "../../support/public_data.h"
#include "workspace/registry.h"

namespace {

// Each case rejected as the manifest says; returns on the first that is not (the failure is recorded).
void check_rejected(const std::vector<bs::test::BadCase>& cases) {
  for (const auto& c : cases) {
    try {
      (void)bs::import_file(c.path, bs::CancelToken{});
      QFAIL(qPrintable(QString::fromStdString(c.path) + " was accepted"));
    } catch (const bs::ImportError& e) {
      const std::string what = e.what();
      QVERIFY2(std::string(bs::to_string(e.category())) == c.category,
               qPrintable(QString::fromStdString(what + "  (expected category " + c.category + ", got " +
                                                 std::string(bs::to_string(e.category())) + ")")));
      QVERIFY2(what.starts_with(c.path), what.c_str());
      QVERIFY2(!e.reason().empty() && e.reason().size() > 8, what.c_str());
      if (c.place) QVERIFY2(e.location().line > 0 || !e.location().field.empty(), what.c_str());
      QVERIFY2(what.find('\n') == std::string::npos, what.c_str());  // one line, fit for a terminal or a dialog
      for (const std::string& text : c.contains)
        QVERIFY2(what.find(text) != std::string::npos,
                 qPrintable(QString::fromStdString(what + "  (expected to contain \"" + text + "\")")));
    }
  }
}

}  // namespace

class TestBadCorpus : public QObject {
  Q_OBJECT
 private slots:
  void every_bad_file_gives_a_clear_error() {
    QTemporaryDir scratch;
    const auto cases = bs::test::bad_cases(
        bs::test::load_bad_corpus(BENCHSCOPE_TEST_DATA_DIR, BENCHSCOPE_PUBLIC_DATA_DIR, scratch.path().toStdString()),
        false);
    QVERIFY(cases.size() >= 40);
    int bad_dir_files = 0;
    for (const auto& c : cases)
      if (c.path.starts_with(std::string(BENCHSCOPE_TEST_DATA_DIR) + "/bad/")) ++bad_dir_files;
    QVERIFY(bad_dir_files >= 40);
    check_rejected(cases);
  }

  void every_third_party_bad_file_gives_a_clear_error() {
    BENCHSCOPE_REQUIRE_PUBLIC_DATA(bs::test::kThirdPartyBadFolder);
    QTemporaryDir scratch;
    const auto cases = bs::test::bad_cases(
        bs::test::load_bad_corpus(BENCHSCOPE_TEST_DATA_DIR, BENCHSCOPE_PUBLIC_DATA_DIR, scratch.path().toStdString()),
        true);
    QVERIFY(!cases.empty());
    check_rejected(cases);
  }
};

QTEST_APPLESS_MAIN(TestBadCorpus)
#include "test_bad_corpus.moc"
