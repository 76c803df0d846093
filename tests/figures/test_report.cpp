// SPDX-License-Identifier: GPL-3.0-or-later
// The report on the paper's sample data: self-contained HTML with the comparison, one section per platform, the
// paper's numbers and the figures embedded; an A4 PDF with a page per platform; the recommendation under a 10 W
// budget; nothing left behind when cancelled.
#include <QDir>
#include <QFile>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

#include "../support/paper_sample.h"
#include "report_writer.h"

namespace {

bs::ui::FigureData paper_data() {
  const auto sample = bs::test::load_paper_sample();
  bs::ui::FigureData d;
  d.runs = sample.runs;
  d.traces = sample.traces;
  return d;
}

QByteArray read(const QString& path) {
  QFile f(path);
  return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

}  // namespace

class TestReport : public QObject {
  Q_OBJECT
 private slots:
  void html_and_pdf_on_paper_data() {
    QTemporaryDir dir;
    bs::ui::ReportRequest request;
    request.workspace_name = "paper-2018";
    request.html_path = dir.filePath("report.html");
    request.pdf_path = dir.filePath("report.pdf");
    request.constraints.power_budget_w = 10;
    const auto templates = bs::load_figure_templates(bs::ui::paper_template_path().toStdString());
    const QStringList files = bs::ui::write_report(request, templates, paper_data(), {}, bs::CancelToken{});
    QCOMPARE(files, (QStringList{request.html_path, request.pdf_path}));

    const QString html = QString::fromUtf8(read(request.html_path));
    QVERIFY(html.startsWith("<!DOCTYPE html>"));
    for (const char* s : {"<h2>NUC</h2>", "<h2>Jetson TX2</h2>", "40.52", "9.48", "104.64", "41.26", "84.36", "360.48",
                          "reconstructed", "Recommended under a power budget of 10 W: Jetson TX2"})
      QVERIFY2(html.contains(QString::fromUtf8(s)), s);
    QCOMPARE(html.count("<img src=\"data:image/png;base64,"), 6);  // every figure of the template, embedded
    QVERIFY(!html.contains("src=\"fig"));                          // nothing refers to a file beside it

    const QByteArray pdf = read(request.pdf_path);
    QVERIFY(pdf.startsWith("%PDF-"));
    const QString text = QString::fromLatin1(pdf);
    const int pages = static_cast<int>(text.count(QRegularExpression(R"(/Type\s*/Page\b(?!s))")));
    QVERIFY2(pages >= 5, qPrintable(QString::number(pages)));  // overview + one per platform (4) + figures
    const auto box = QRegularExpression(R"(/MediaBox\s*\[\s*0\s+0\s+([\d.]+)\s+([\d.]+))").match(text);
    QVERIFY(box.hasMatch());
    QVERIFY(std::abs(box.captured(1).toDouble() - 595.3) < 1.5);  // A4 in points
    QVERIFY(std::abs(box.captured(2).toDouble() - 841.9) < 1.5);
  }

  void cancelled_report_writes_nothing() {
    QTemporaryDir dir;
    bs::ui::ReportRequest request;
    request.html_path = dir.filePath("report.html");
    bs::CancelToken cancel;
    const auto templates = bs::load_figure_templates(bs::ui::paper_template_path().toStdString());
    QVERIFY_THROWS_EXCEPTION(bs::Cancelled, bs::ui::write_report(request, templates, paper_data(), {}, cancel,
                                                                 [&](int, int, const QString&) { cancel.cancel(); }));
    QVERIFY(QDir(dir.path()).entryList(QDir::Files).isEmpty());
  }

  void constraints_described_for_the_heading() {
    bs::Constraints c;
    QCOMPARE(bs::ui::describe_constraints(c), std::string());
    c.power_budget_w = 10;
    c.min_fps = 5;
    c.min_runtime_h = 1.5;
    QCOMPARE(bs::ui::describe_constraints(c),
             std::string("a power budget of 10 W, at least 5 fps, at least 90 min on the battery"));
  }
};

QTEST_MAIN(TestReport)
#include "test_report.moc"
