// SPDX-License-Identifier: GPL-3.0-or-later
#include "report_writer.h"

#include <qcustomplot.h>
#include <QAbstractTextDocumentLayout>
#include <QBuffer>
#include <QDateTime>
#include <QDir>
#include <QFileInfo>
#include <QFontMetricsF>
#include <QImage>
#include <QPageLayout>
#include <QPainter>
#include <QPdfWriter>
#include <QSaveFile>
#include <QTemporaryDir>
#include <QTextBlock>
#include <QTextBoundaryFinder>
#include <QTextCursor>
#include <QTextDocument>
#include <QTextTable>
#include <QUrl>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "device_palette.h"
#include "plot_export.h"
#include "report/platform_report.h"
#include "report/table_fit.h"
#include "report_chart.h"

namespace bs::ui {
namespace {

constexpr double kPtPerMm = 72.0 / 25.4;
constexpr double kMarginMm = 15;

struct RenderedFigure {
  ReportFigure meta;  // caption, size, id, sources; image_src set per output
  QString name;
  QImage image;
  QByteArray png;
};

QByteArray read_all(const QString& path) {
  QFile f(path);
  return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

// "fig1a: GTX1080Ti OpenCL D=4 (reconstructed), ...": what render_figures says a figure shows, without the id.
std::string shown_by(const QStringList& contents, const std::string& id) {
  for (const QString& line : contents)
    if (line.startsWith(QString::fromStdString(id) + ": "))
      return line.mid(static_cast<int>(id.size()) + 2).toStdString();
  return {};
}

// What the triptych shows, said first: a synthetic capture (the paper's sample stands in for a capture that was never
// published) must not pass for a camera image, and a reader should know where it comes from.
std::string triptych_caption(const std::optional<Frame>& frame) {
  const std::string panels = ": raw mosaic as grey, demosaiced, and reprojected.";
  if (!frame)
    return "Synthetic test chart, not a camera image (the workspace holds no capture), rendered by BenchScope through "
           "the paper's 195\xC2\xB0 lens" +
           panels;
  const std::string& path = frame->provenance.source_file;
  const std::string file = path.empty() ? frame->label : path.substr(path.find_last_of('/') + 1);
  if (frame->synthetic)
    return "Synthetic capture, not a camera image: " + file + ", a test chart rendered through a lens model by " +
           (frame->provenance.tool.empty() ? std::string("benchscope-cli synth-frame") : frame->provenance.tool) +
           panels;
  return "Camera frame " + file + panels;
}

std::string figure_caption(const FigureTemplate& t, const FigureData& data) {
  if (t.kind == "flops")
    return t.title + ": " + (t.y_label.empty() ? "FLOPS" : t.y_label) + " against " +
           (t.x_label.empty() ? "workers" : t.x_label) + ", mean over repetitions.";
  if (t.kind == "current") return t.title + ": supply current over time (minimum and maximum per time bucket).";
  if (t.kind == "triptych") return triptych_caption(data.frame);
  return t.title + ".";
}

std::vector<RenderedFigure> render_pngs(const std::vector<FigureTemplate>& templates, const FigureData& data,
                                        FigureOptions o, const CancelToken& cancel,
                                        const std::function<void(int, int, const QString&)>& progress) {
  QTemporaryDir dir;
  if (!dir.isValid()) throw std::runtime_error("cannot create a temporary folder for the report's figures");
  o.formats = {"png"};
  o.dpi = 200;  // sharp on an A4 page; the figures command gives print resolution in vector formats
  std::vector<RenderedFigure> out;
  int done = 0;
  for (const FigureTemplate& t : templates) {
    if (progress) progress(done++, static_cast<int>(templates.size()) + 1, QString::fromStdString(t.id));
    // A template whose data the workspace lacks (no power log: no fig4) is left out of the report, not an error.
    FigureOutput rendered;
    try {
      rendered = render_figures({t}, data, dir.path(), o, cancel);
    } catch (const Cancelled&) {
      throw;
    } catch (const std::runtime_error&) {
      continue;
    }
    const QString name = QString::fromStdString(t.id) + ".png";
    RenderedFigure r;
    r.name = name;
    r.png = read_all(QDir(dir.path()).filePath(name));
    if (r.png.isEmpty() || !r.image.loadFromData(r.png, "PNG")) continue;  // optional and skipped: no file
    r.meta.caption = figure_caption(t, data);
    r.meta.id = t.id;
    r.meta.sources = shown_by(rendered.contents, t.id);
    r.meta.width_pt = o.width_mm * kPtPerMm;
    r.meta.height_pt = r.meta.width_pt * r.image.height() / std::max(1, r.image.width());
    out.push_back(std::move(r));
  }
  return out;
}

// Page one's chart at the text width, short enough to leave the page to the table.
std::optional<RenderedFigure> render_chart(const std::vector<PlatformRow>& rows,
                                           const std::vector<PlatformVerdict>& verdicts, const FigureData& data,
                                           const FigureOptions& base) {
  // Each platform in its colour as everywhere else (device_palette.h): a platform with no device of its own (a
  // power log only) takes the free colour the Power tab and fig4 give it, not another platform's.
  std::vector<std::pair<std::string, int>> devices;
  for (const auto& [key, index] : data.colors) devices.emplace_back(key.first, index);
  std::vector<std::string> platforms;  // the same platforms the Power tab is given, so the free colours match
  for (const PowerTrace& trace : data.traces) platforms.push_back(trace.platform);
  std::map<std::string, int> colors;
  for (const auto& [platform, index] : platform_color_indices(devices, platforms)) colors[platform] = index;
  FigureOptions o = base;
  o.width_mm = 180;
  o.height_mm = 40;
  o.formats = {"png"};
  o.dpi = 200;
  QCustomPlot plot;
  const QSizeF size = figure_size_pt(o);
  plot.resize(static_cast<int>(size.width()), static_cast<int>(size.height()));
  RenderedFigure r;
  try {
    r.meta.sources = comparison_chart(plot, rows, verdicts, colors, o);
  } catch (const std::runtime_error&) {
    return std::nullopt;  // no FLOPS peak anywhere: page one has the table alone
  }
  QTemporaryDir dir;
  QStringList files;
  save_plot(plot, dir.filePath("comparison"), o, "comparison", files);
  r.name = "comparison.png";
  r.png = read_all(dir.filePath("comparison.png"));
  r.image.loadFromData(r.png, "PNG");
  r.meta.caption = comparison_chart_caption();
  r.meta.width_pt = size.width();
  r.meta.height_pt = size.height();
  return r;
}

// The report's folder is created if missing, as `figures --out` does.
void make_parent(const QString& path) { QDir().mkpath(QFileInfo(path).absolutePath()); }

void save_whole(const QString& path, const QByteArray& bytes) {
  make_parent(path);
  QSaveFile f(path);
  if (!f.open(QIODevice::WriteOnly) || f.write(bytes) != bytes.size() || !f.commit())
    throw std::runtime_error(path.toStdString() + ": cannot write: " + f.errorString().toStdString());
}

// A format change relays out only from the change on, and leaves what follows a table that changed width with
// stale positions (blocks of zero height, dropped from the pages): lay out the whole document again.
void relayout(QTextDocument& doc) { doc.markContentsDirty(0, doc.characterCount()); }

bool has_image(const QTextBlock& block) {
  for (auto it = block.begin(); !it.atEnd(); ++it)
    if (it.fragment().charFormat().isImageFormat()) return true;
  return false;
}

int page_of(double y, double page_h) { return static_cast<int>(std::floor(y / page_h)); }

// The bottom of a table's first body row (after its repeated header rows), in document coordinates.
double first_body_row_bottom(QAbstractTextDocumentLayout& layout, const QTextTable& table) {
  const int row = std::min(table.rows() - 1, std::max(0, table.format().headerRowCount()));
  double bottom = 0;
  for (int c = 0; c < table.columns(); ++c) {
    const QTextTableCell cell = table.cellAt(row, c);
    if (!cell.isValid()) continue;
    for (auto it = cell.begin(); !it.atEnd(); ++it)
      if (it.currentBlock().isValid()) bottom = std::max(bottom, layout.blockBoundingRect(it.currentBlock()).bottom());
  }
  return bottom;
}

// Keeps together what belongs together, as LaTeX does: a figure with its caption (one paragraph), a heading and a
// table caption with what follows. A paragraph that would straddle a page break, or a heading left alone at a
// page's foot, starts the next page. One fix per pass, since each moves everything after it.
void keep_together(QTextDocument& doc) {
  const double page_h = doc.pageSize().height();
  QAbstractTextDocumentLayout* layout = doc.documentLayout();
  for (int pass = 0; pass < 200; ++pass) {
    bool moved = false;
    for (QTextBlock b = doc.begin(); b.isValid() && !moved; b = b.next()) {
      if (QTextCursor(b).currentTable()) continue;
      const QRectF r = layout->blockBoundingRect(b);
      const QTextBlock next = b.next();
      const bool heading = b.blockFormat().headingLevel() > 0;
      const bool before_table = next.isValid() && QTextCursor(next).currentTable() && !b.text().isEmpty();
      bool bad = has_image(b) && page_of(r.top(), page_h) != page_of(r.bottom() - 1, page_h);
      if ((heading || before_table) && next.isValid()) {
        // The first line of what follows must be on this block's page; for a table caption, the table's header rows
        // and its first body row (a caption and header alone at a page's foot say nothing).
        const QTextLayout* nl = next.layout();
        double next_bottom =
            layout->blockBoundingRect(next).top() + (nl && nl->lineCount() > 0 ? nl->lineAt(0).height() : 0);
        if (before_table)
          next_bottom = std::max(next_bottom, first_body_row_bottom(*layout, *QTextCursor(next).currentTable()));
        bad = bad || page_of(r.top(), page_h) != page_of(next_bottom - 1, page_h);
      }
      if (bad && b.blockFormat().pageBreakPolicy() != QTextFormat::PageBreak_AlwaysBefore &&
          page_of(r.top(), page_h) * page_h < r.top() - 1) {
        QTextBlockFormat f;
        f.setPageBreakPolicy(QTextFormat::PageBreak_AlwaysBefore);
        QTextCursor(b).mergeBlockFormat(f);
        relayout(doc);
        moved = true;
      }
    }
    if (!moved) return;
  }
}

// The widest piece of `text` a line cannot break inside, as the layout breaks lines (Unicode line breaking: at
// spaces, after '/', after a '-' before a letter). A unit's short denominator stays with its numerator
// ("GFLOPS/W", "op/s"): the column is made wide enough that the layout never needs that break, since "GFLOPS/" over
// "W" reads as two words.
double widest_unbreakable(const QString& text, const QFontMetricsF& m) {
  QTextBoundaryFinder lines(QTextBoundaryFinder::Line, text);
  double widest = 0;
  QString piece;
  for (qsizetype start = 0, end = lines.toNextBoundary(); end != -1; start = end, end = lines.toNextBoundary()) {
    const QString next = text.mid(start, end - start).trimmed();
    piece = piece.endsWith('/') && next.size() <= 2 ? piece + next : next;
    widest = std::max(widest, m.horizontalAdvance(piece));
  }
  return widest;
}

struct ColumnWidths {
  std::vector<double> widest, natural;  // points: the widest unbreakable piece, the longest line
};

ColumnWidths measure_columns(const QTextTable& table, QPaintDevice* device) {
  ColumnWidths w{std::vector<double>(static_cast<std::size_t>(table.columns()), 0),
                 std::vector<double>(static_cast<std::size_t>(table.columns()), 0)};
  for (int r = 0; r < table.rows(); ++r)
    for (int c = 0; c < table.columns(); ++c) {
      const QTextTableCell cell = table.cellAt(r, c);
      if (cell.columnSpan() != 1) continue;
      for (auto it = cell.begin(); !it.atEnd(); ++it) {
        const QTextBlock block = it.currentBlock();
        double line = 0;
        for (auto f = block.begin(); !f.atEnd(); ++f) {
          const QFontMetricsF m(f.fragment().charFormat().font(), device);
          auto& widest = w.widest[static_cast<std::size_t>(c)];
          widest = std::max(widest, widest_unbreakable(f.fragment().text(), m));
          line += m.horizontalAdvance(f.fragment().text());
        }
        auto& natural = w.natural[static_cast<std::size_t>(c)];
        natural = std::max(natural, line);
      }
    }
  return w;
}

// Every character of the table at `pt` points (bold, italic and colours kept).
void set_table_font_size(QTextTable& table, double pt) {
  QTextCursor all = table.firstCursorPosition();
  all.setPosition(table.lastCursorPosition().position(), QTextCursor::KeepAnchor);
  QTextCharFormat size;
  size.setFontPointSize(pt);
  all.mergeCharFormat(size);
}

// Column widths from the fonts as printed: each column at least as wide as its widest unbreakable piece (so no
// word is broken, "Preproces sing", and nothing runs past the page), the rest of the text width shared out in
// proportion to the columns' natural widths. A table whose whole words do not fit at its font is set smaller, down
// to kTableMinFontPt (report/table_fit.h, which split it beforehand where even that would not do).
void fit_tables(QTextDocument& doc, QPaintDevice* device) {
  const double text_w = doc.pageSize().width();
  for (QTextFrame* frame : doc.rootFrame()->childFrames()) {
    auto* table = qobject_cast<QTextTable*>(frame);
    if (!table) continue;
    const QTextTableFormat format = table->format();
    const double pad = format.cellPadding() * 2 + format.cellSpacing() + 2;
    ColumnWidths m;
    double need = 0, extra = 0;
    double font_pt = table->cellAt(0, 0).firstCursorPosition().charFormat().font().pointSizeF();
    for (int attempt = 0; attempt < 4; ++attempt) {
      m = measure_columns(*table, device);
      need = extra = 0;
      // Row headings on one line where they are short ("Energy per frame"): a quarter of the width at most.
      if (!m.widest.empty()) m.widest[0] = std::max(m.widest[0], std::min(m.natural[0], text_w * 0.22));
      for (std::size_t c = 0; c < m.widest.size(); ++c) {
        m.widest[c] += pad;
        m.natural[c] += pad;
        need += m.widest[c];
        extra += std::max(0.0, m.natural[c] - m.widest[c]);
      }
      if (need <= text_w - 4 || font_pt <= kTableMinFontPt || font_pt <= 0) break;
      // Text widths scale with the font; the padding does not.
      const double cols_pad = pad * static_cast<double>(m.widest.size());
      const double scale = (text_w - 4 - cols_pad) / std::max(1.0, need - cols_pad);
      font_pt = std::max(kTableMinFontPt, std::floor(font_pt * scale * 4) / 4);
      set_table_font_size(*table, font_pt);
    }
    const double spare = text_w - need - 4;
    if (spare < 0) continue;  // not even at the smallest font: table_fit.h splits such tables before this
    // All on one line when that fits (the space left spread in proportion); else the widest pieces, plus the spare
    // width where the text is longest.
    const double total = std::accumulate(m.natural.begin(), m.natural.end(), 0.0);
    QVector<QTextLength> widths;
    for (std::size_t c = 0; c < m.widest.size(); ++c) {
      const double w = total <= text_w - 4 ? m.natural[c] + (text_w - 4 - total) * m.natural[c] / total
                                           : m.widest[c] + spare * std::max(0.0, m.natural[c] - m.widest[c]) / extra;
      // QTextDocument scales fixed lengths by the device's dpi / 96, as if they were CSS pixels: give them so.
      widths << QTextLength(QTextLength::FixedLength, w * 96.0 / device->logicalDpiX());
    }
    QTextTableFormat f = table->format();
    f.setColumnWidthConstraints(widths);
    table->setFormat(f);
  }
  relayout(doc);
}

void print_pdf(const QString& path, const std::string& html, const std::vector<RenderedFigure>& figures) {
  make_parent(path);
  QSaveFile file(path);
  if (!file.open(QIODevice::WriteOnly))
    throw std::runtime_error(path.toStdString() + ": cannot write: " + file.errorString().toStdString());
  {
    QPdfWriter pdf(&file);
    pdf.setPageSize(QPageSize(QPageSize::A4));
    pdf.setPageMargins(QMarginsF(kMarginMm, kMarginMm, kMarginMm, kMarginMm), QPageLayout::Millimeter);
    pdf.setResolution(72);  // device units are points, the HTML's pt sizes come out as written
    pdf.setCreator("BenchScope");
    pdf.setTitle("BenchScope report");
    const QSizeF text(pdf.width(), pdf.height());
    QTextDocument doc;
    doc.documentLayout()->setPaintDevice(&pdf);
    doc.setDocumentMargin(0);
    // Whole words only: a word too long for its column overflows rather than breaks ("Preproces sing").
    QTextOption option = doc.defaultTextOption();
    option.setWrapMode(QTextOption::WordWrap);
    doc.setDefaultTextOption(option);
    QFont body("DejaVu Serif");
    body.setPointSizeF(9.5);
    doc.setDefaultFont(body);
    for (const RenderedFigure& f : figures) doc.addResource(QTextDocument::ImageResource, QUrl(f.name), f.image);
    doc.setHtml(QString::fromStdString(html));
    // The body's CSS margin is for browsers; on paper the page margins are the only ones.
    QTextFrameFormat root = doc.rootFrame()->frameFormat();
    root.setMargin(0);
    root.setPadding(0);
    doc.rootFrame()->setFrameFormat(root);
    doc.setPageSize(text);
    fit_tables(doc, &pdf);
    keep_together(doc);
    QPainter painter(&pdf);
    const int pages = doc.pageCount();
    for (int p = 0; p < pages; ++p) {
      if (p > 0) pdf.newPage();
      painter.save();
      painter.translate(0, -p * text.height());
      // Half a point inside the page: a block that starts exactly at the next page's top is that page's only.
      const QRectF clip(0, p * text.height() + 0.5, text.width(), text.height() - 1);
      doc.drawContents(&painter, clip);
      painter.restore();
      // Page numbers in the bottom margin, as a printed report has them.
      QFont f = body;
      f.setPointSizeF(8);
      painter.setFont(f);
      painter.setPen(QColor(90, 90, 90));
      painter.drawText(QRectF(0, text.height() + 6, text.width(), 14), Qt::AlignHCenter | Qt::AlignTop,
                       QStringLiteral("%1 / %2").arg(p + 1).arg(pages));
    }
    painter.end();
  }
  if (!file.commit())
    throw std::runtime_error(path.toStdString() + ": cannot write: " + file.errorString().toStdString());
}

// The report's constraints line lists each constraint in force, comma-separated.
void add_constraint(std::string& constraints, const std::string& constraint) {
  constraints += (constraints.empty() ? "" : ", ") + constraint;
}

}  // namespace

QStringList write_report(const ReportRequest& request, const std::vector<FigureTemplate>& templates,
                         const FigureData& data, const FigureOptions& figure_options, const CancelToken& cancel,
                         const std::function<void(int, int, const QString&)>& progress) {
  if (request.html_path.isEmpty() && request.pdf_path.isEmpty()) throw std::runtime_error("no report file named");
  const std::vector<RenderedFigure> figures = render_pngs(templates, data, figure_options, cancel, progress);
  cancel.throw_if_cancelled();

  ReportInput in;
  in.workspace = request.workspace_name.toStdString();
  in.generated = QDateTime::currentDateTime().toString(Qt::ISODate).toStdString();
  in.tool = "BenchScope " BENCHSCOPE_VERSION;
  in.rows = compare_platforms(data.runs, data.traces, data.pipelines, request.comparison);
  in.verdicts = recommend(in.rows, request.constraints);
  in.constraints = describe_constraints(request.constraints);
  in.inference_runs = data.inference_runs;
  in.headroom = data.headroom;
  // The requirements judge the platforms compared (and any other that has a record).
  std::vector<std::string> names;
  for (const PlatformRow& r : in.rows) names.push_back(r.platform);
  if (request.loop) {
    in.loop = request.loop;
    in.loop_verdicts = headroom::evaluate_loop(*request.loop, data.headroom, names);
    headroom::apply_loop(in.verdicts, in.loop_verdicts);
    add_constraint(in.constraints, "control loop " + headroom::describe(*request.loop));
  }
  if (request.sustained) {
    in.sustained = request.sustained;
    in.sustained_verdicts = sustain::evaluate_sustain(*request.sustained, data.sustain_runs, names);
    sustain::apply_sustain(in.verdicts, in.sustained_verdicts);
    add_constraint(in.constraints, "sustained " + sustain::describe(*request.sustained));
  }
  in.candidates = request.candidates;
  in.chosen_log_platforms = request.chosen_log_platforms;
  in.data_selection = data.selection;
  const std::optional<RenderedFigure> chart = render_chart(in.rows, in.verdicts, data, figure_options);

  // Figures as data: URIs for the one-file HTML, as resource names for the PDF (QTextDocument resources).
  const auto with_figures = [&](bool embed) {
    ReportInput out = in;
    const auto src = [&](const RenderedFigure& f) {
      return embed ? "data:image/png;base64," + f.png.toBase64().toStdString() : f.name.toStdString();
    };
    if (chart) {
      out.comparison_chart = chart->meta;
      out.comparison_chart->image_src = src(*chart);
    }
    for (const RenderedFigure& f : figures) {
      out.figures.push_back(f.meta);
      out.figures.back().image_src = src(f);
    }
    return out;
  };
  QStringList written;
  try {
    if (!request.html_path.isEmpty()) {
      save_whole(request.html_path, QByteArray::fromStdString(report_html(with_figures(true))));
      written << request.html_path;
    }
    cancel.throw_if_cancelled();
    if (!request.pdf_path.isEmpty()) {
      std::vector<RenderedFigure> all = figures;
      if (chart) all.push_back(*chart);
      print_pdf(request.pdf_path, report_html(with_figures(false)), all);
      written << request.pdf_path;
    }
  } catch (...) {
    for (const QString& f : written) QFile::remove(f);
    throw;
  }
  if (progress) progress(1, 1, "done");
  return written;
}

}  // namespace bs::ui
