// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The report's HTML as it is built: headings, paragraphs, numbered tables and numbered figures, each figure's
// image and caption in one block so that a renderer keeps them on one page. One HTML serves the browser (a
// self-contained file) and Qt's QTextDocument (the PDF), so it keeps to what both read: no CSS layout, widths as
// attributes, page breaks as `page-break-before`. No Qt.
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace bs {

std::string html_escape(std::string_view text);

struct ReportFigure {
  std::string caption;    // what the figure shows; the builder writes "Figure n. " before it
  std::string image_src;  // an <img src>: "data:image/png;base64,..." or a name the renderer resolves
  double width_pt = 0;    // as drawn on the page, in points (1/72 in); 0: the text width
  double height_pt = 0;   // 0: not stated
  std::string id;         // the template's figure id ("fig1a"), said in the caption and the appendix
  std::string sources;    // the data it was drawn from, for the sources appendix
};

// A table of text cells under a numbered caption. `header` may hold several rows (names, then units); a cell of
// the first column of a body row is a row heading. Widths are per cent of the text width (first row of header).
struct ReportTable {
  std::string caption;
  std::vector<std::vector<std::string>> header;
  std::vector<std::vector<std::string>> rows;
  std::vector<int> width_percent;  // empty: the renderer decides
  std::vector<std::string> notes;  // under the table, small
  bool numeric_right = true;       // body cells after the first column aligned right
  std::string align;               // per column 'l' or 'r' (as ExportTable's); overrides numeric_right when set
};

class ReportBuilder {
 public:
  // Text width of the page in points: A4 with 15 mm margins.
  static constexpr double kTextWidthPt = 510.2;

  void heading(int level, std::string_view text, bool new_page = false);
  void paragraph(std::string_view text, std::string_view css_class = {});  // text is escaped
  void html(std::string_view raw);                                         // trusted HTML, as is
  int figure(const ReportFigure& f);                                       // returns its number
  int table(const ReportTable& t);                                         // returns its number
  void page_break();
  int figures() const { return figures_; }
  int tables() const { return tables_; }
  std::string str() const { return out_.str(); }

 private:
  std::ostringstream out_;
  int figures_ = 0, tables_ = 0;
};

}  // namespace bs
