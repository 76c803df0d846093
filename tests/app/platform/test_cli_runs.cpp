// SPDX-License-Identifier: GPL-3.0-or-later
// `benchscope-cli runs` on a workspace of the paper's sample data: the runs listed with their ids, a run labelled,
// the label kept in the workspace (read back by a new process) and drawn in the paper figures' legends, a label
// cleared, and errors for a run that is not there, a label without a run and a run without a label.
#include <QDir>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

#include "../../support/cli_harness.h"

namespace {

using bs::test::cli;
using bs::test::kPaper;

// The id of the run listed on the line that holds `device` and `backend` with D = `dims` ("" when none).
QString run_id(const QByteArray& listing, const QString& device, const QString& backend, int dims) {
  for (const QString& line : QString::fromUtf8(listing).split('\n'))
    if (line.contains(device) && line.contains(QRegularExpression(backend + "\\s+" + QString::number(dims) + "\\s"))) {
      const auto m = QRegularExpression(R"(^\s*(\d+)\s)").match(line);
      if (m.hasMatch()) return m.captured(1);
    }
  return {};
}

#ifdef BENCHSCOPE_WITH_FIGURES_TEST
// The text of a PDF figure (pdftotext, poppler-utils; legends keep their text as text).
QString pdf_text(const QString& pdf) {
  QProcess p;
  p.start("pdftotext", {"-enc", "UTF-8", pdf, "-"});
  return p.waitForFinished(60000) ? QString::fromUtf8(p.readAllStandardOutput()) : QString();
}
#endif

QString line_of(const QByteArray& listing, const QString& id) {
  for (const QString& line : QString::fromUtf8(listing).split('\n'))
    if (line.trimmed().startsWith(id + ' ')) return line;
  return {};
}

}  // namespace

class TestCliRuns : public QObject {
  Q_OBJECT
 private slots:
  void list_label_and_clear() {
    QTemporaryDir dir;
    const QString ws = dir.filePath("paper.bsw");
    QCOMPARE(cli({"import", ws, kPaper, "--quiet"}).code, 0);
    const auto listed = cli({"runs", ws});
    QCOMPARE(listed.code, 0);
    QVERIFY2(listed.out.startsWith("Id") && listed.out.contains("Label"), listed.out.constData());
    const QString nuc = run_id(listed.out, "NUC GPU", "OpenCL", 4);
    QVERIFY2(!nuc.isEmpty(), listed.out.constData());
    QVERIFY(!line_of(listed.out, nuc).contains("after BIOS update"));

    // Labelled; a new process reads the label back from the workspace.
    auto r = cli({"runs", ws, "--run", nuc, "--label", "after BIOS update"});
    QCOMPARE(r.code, 0);
    QCOMPARE(r.out, QByteArray("run " + nuc.toUtf8() + ": labelled \"after BIOS update\"\n"));
    r = cli({"runs", ws});
    QCOMPARE(r.code, 0);
    QVERIFY2(line_of(r.out, nuc).trimmed().endsWith("after BIOS update"), r.out.constData());
    // Only that run carries it.
    QCOMPARE(QString::fromUtf8(r.out).count("after BIOS update"), 1);

#ifdef BENCHSCOPE_WITH_FIGURES_TEST  // the CLI has `figures` only in a build with Qt (not the robot's, not ASan's)
    // The figures' legends show it after the run's name: fig1a (every GPU at D = 4) and fig1b (the NUC and the
    // Jetson at each D); the CPU figure holds no GPU run.
    const QString figs = dir.filePath("figs");
    r = cli({"figures", ws, "--out", figs, "--quiet"});
    QCOMPARE(r.code, 0);
    const QString fig1a = pdf_text(figs + "/fig1a.pdf");
    QVERIFY2(fig1a.contains("NUC GPU, OpenCL \u2014 after BIOS update"), qPrintable(fig1a));
    QVERIFY2(pdf_text(figs + "/fig1b.pdf").contains("NUC GPU, OpenCL, D = 4 \u2014 after BIOS update"),
             qPrintable(pdf_text(figs + "/fig1b.pdf")));
    QVERIFY(!pdf_text(figs + "/fig2a.pdf").contains("after BIOS update"));
#endif

    // Cleared: gone from the listing and from the figure.
    r = cli({"runs", ws, "--run", nuc, "--clear"});
    QCOMPARE(r.code, 0);
    QCOMPARE(r.out, QByteArray("run " + nuc.toUtf8() + ": label removed\n"));
    r = cli({"runs", ws});
    QVERIFY(!r.out.contains("after BIOS update"));
#ifdef BENCHSCOPE_WITH_FIGURES_TEST
    QCOMPARE(cli({"figures", ws, "--out", figs, "--quiet"}).code, 0);
    QVERIFY(pdf_text(figs + "/fig1a.pdf").contains("NUC GPU, OpenCL"));
    QVERIFY(!pdf_text(figs + "/fig1a.pdf").contains("after BIOS update"));
#endif
  }

  void errors() {
    QTemporaryDir dir;
    const QString ws = dir.filePath("paper.bsw");
    QCOMPARE(cli({"import", ws, kPaper, "--quiet"}).code, 0);
    // A run that is not there: an error naming the id, and how to list them.
    auto r = cli({"runs", ws, "--run", "9999", "--label", "x"});
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains("no run with id 9999") && r.err.contains("benchscope-cli runs"), r.err.constData());
    // Usage errors: an id that is no number, --run without --label or --clear, --label without --run.
    QCOMPARE(cli({"runs", ws, "--run", "1x", "--label", "x"}).code, 2);
    QCOMPARE(cli({"runs", ws, "--run", "1"}).code, 2);
    QCOMPARE(cli({"runs", ws, "--label", "x"}).code, 2);
    QCOMPARE(cli({"runs", dir.filePath("nope.txt")}).code, 2);
    // A label longer than 80 characters is refused and nothing is stored.
    const QString first = run_id(cli({"runs", ws}).out, "NUC GPU", "OpenCL", 4);
    QCOMPARE(cli({"runs", ws, "--run", first, "--label", QString(81, 'a')}).code, 1);
    QVERIFY(!cli({"runs", ws}).out.contains(QByteArray(81, 'a')));
  }
};

QTEST_GUILESS_MAIN(TestCliRuns)
#include "test_cli_runs.moc"
