// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A PDF read back as a reader sees it, with poppler-utils: its text (pdftotext), each word's box on its page
// (pdftotext -bbox) and its pages as images (pdftoppm). What a person notices on paper becomes checkable: words
// printed over each other, words running past the page's edge, a name cut short.
#include <QFile>
#include <QImage>
#include <QProcess>
#include <QRectF>
#include <QRegularExpression>
#include <QString>
#include <QStringList>
#include <vector>

namespace bs::test {

// Standard output of `program args` (empty when it fails or runs over a minute).
inline QString run_tool(const QString& program, const QStringList& args) {
  QProcess p;
  p.start(program, args);
  if (!p.waitForFinished(60000) || p.exitStatus() != QProcess::NormalExit || p.exitCode() != 0) return {};
  return QString::fromUtf8(p.readAllStandardOutput());
}

// The text of `page` (1-based; 0: every page), NFKC-normalised so that ligatures ("ﬃ" in "Efficiency") read as their
// letters.
inline QString pdf_text(const QString& pdf, int page = 0) {
  QStringList args{"-enc", "UTF-8"};
  if (page > 0) args << "-f" << QString::number(page) << "-l" << QString::number(page);
  return run_tool("pdftotext", args << pdf << "-").normalized(QString::NormalizationForm_KC);
}

// The text with every run of white space (line ends of wrapped notes included) as one space: a name wrapped over
// two lines still reads as one string.
inline QString pdf_flat_text(const QString& pdf, int page = 0) { return pdf_text(pdf, page).simplified(); }

inline int pdf_page_count(const QString& pdf) {
  const auto m = QRegularExpression(R"(Pages:\s+(\d+))").match(run_tool("pdfinfo", {pdf}));
  return m.hasMatch() ? m.captured(1).toInt() : 0;
}

struct PdfWord {
  QString text;
  QRectF box;  // points, origin at the page's top-left
};

struct PdfPage {
  QSizeF size;  // points
  std::vector<PdfWord> words;
};

// Every word of every page with its box (pdftotext -bbox writes them as XHTML).
inline std::vector<PdfPage> pdf_words(const QString& pdf) {
  const QString xhtml = run_tool("pdftotext", {"-bbox", "-enc", "UTF-8", pdf, "-"});
  std::vector<PdfPage> pages;
  static const QRegularExpression page_re(R"re(<page width="([\d.]+)" height="([\d.]+)">)re");
  static const QRegularExpression word_re(
      R"re(<word xMin="([\d.-]+)" yMin="([\d.-]+)" xMax="([\d.-]+)" yMax="([\d.-]+)">([^<]*)</word>)re");
  for (const QString& chunk : xhtml.split("</page>")) {
    const auto p = page_re.match(chunk);
    if (!p.hasMatch()) continue;
    PdfPage page;
    page.size = QSizeF(p.captured(1).toDouble(), p.captured(2).toDouble());
    for (auto it = word_re.globalMatch(chunk, p.capturedEnd()); it.hasNext();) {
      const auto w = it.next();
      const QPointF top_left(w.captured(1).toDouble(), w.captured(2).toDouble());
      const QPointF bottom_right(w.captured(3).toDouble(), w.captured(4).toDouble());
      QString text = w.captured(5);
      text.replace("&lt;", "<")
          .replace("&gt;", ">")
          .replace("&quot;", "\"")
          .replace("&#39;", "'")
          .replace("&amp;", "&");
      page.words.push_back({text.normalized(QString::NormalizationForm_KC), QRectF(top_left, bottom_right)});
    }
    pages.push_back(std::move(page));
  }
  return pages;
}

// Pairs of words printed over each other: their boxes share more than a fifth of the smaller one's area (words on
// neighbouring lines touch at most by a sliver of their ascent and descent).
inline QStringList overprinted_words(const PdfPage& page) {
  QStringList out;
  for (std::size_t a = 0; a < page.words.size(); ++a)
    for (std::size_t b = a + 1; b < page.words.size(); ++b) {
      const QRectF& ra = page.words[a].box;
      const QRectF& rb = page.words[b].box;
      const QRectF both = ra.intersected(rb);
      if (both.isEmpty()) continue;
      const double smaller = std::min(ra.width() * ra.height(), rb.width() * rb.height());
      if (both.width() * both.height() > 0.2 * smaller)
        out << QStringLiteral("'%1' over '%2'").arg(page.words[a].text, page.words[b].text);
    }
  return out;
}

// Words that run past the page's printable width (`right_pt` from the left edge): cut at the page's edge on paper.
inline QStringList words_past(const PdfPage& page, double right_pt) {
  QStringList out;
  for (const PdfWord& w : page.words)
    if (w.box.right() > right_pt + 0.5)
      out << QStringLiteral("'%1' (to %2 pt)").arg(w.text).arg(w.box.right(), 0, 'f', 1);
  return out;
}

// What a person would see wrong in an exported figure's page: words printed over each other and words cut at the
// figure's edge, each said in a sentence.
inline QStringList figure_layout_problems(const PdfPage& page) {
  QStringList out;
  for (const QString& p : overprinted_words(page)) out << QStringLiteral("words print over each other: %1").arg(p);
  for (const QString& p : words_past(page, page.size.width()))
    out << QStringLiteral("a word runs past the figure's edge: %1").arg(p);
  return out;
}

// Page `page` (1-based) rendered at `dpi` as an image (pdftoppm), for pixel checks and for looking at it.
inline QImage pdf_page_image(const QString& pdf, int page, int dpi, const QString& png_stem) {
  run_tool("pdftoppm", {"-f", QString::number(page), "-l", QString::number(page), "-r", QString::number(dpi), "-png",
                        "-singlefile", pdf, png_stem});
  return QImage(png_stem + ".png");
}

}  // namespace bs::test
