// SPDX-License-Identifier: GPL-3.0-or-later
#include "report/report_html.h"

#include <algorithm>
#include <cmath>

namespace bs {

std::string html_escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

void ReportBuilder::heading(int level, std::string_view text, bool new_page) {
  const std::string tag = "h" + std::to_string(level);
  out_ << '<' << tag << (new_page ? " style=\"page-break-before: always\"" : "") << '>' << html_escape(text) << "</"
       << tag << ">\n";
}

void ReportBuilder::paragraph(std::string_view text, std::string_view css_class) {
  out_ << "<p" << (css_class.empty() ? "" : " class=\"" + std::string(css_class) + "\"") << '>' << html_escape(text)
       << "</p>\n";
}

void ReportBuilder::html(std::string_view raw) { out_ << raw; }

void ReportBuilder::page_break() { out_ << "<div style=\"page-break-before: always\"></div>\n"; }

int ReportBuilder::figure(const ReportFigure& f) {
  const int n = ++figures_;
  const double w = f.width_pt > 0 ? std::min(f.width_pt, kTextWidthPt) : kTextWidthPt;
  // Image and caption in one paragraph: the PDF writer moves a paragraph that would straddle a page break to the
  // next page whole, so a caption never lands on another page than its figure.
  // Sizes in CSS pixels (1/96 in), which browsers and QTextDocument both scale to the device.
  constexpr double kPxPerPt = 96.0 / 72.0;
  out_ << "<p class=\"figure\" align=\"center\"><img src=\"" << html_escape(f.image_src) << "\" width=\""
       << std::lround(w * kPxPerPt) << "\"";
  if (f.height_pt > 0)
    out_ << " height=\"" << std::lround(f.height_pt * w / std::max(1.0, f.width_pt) * kPxPerPt) << "\"";
  out_ << " alt=\"Figure " << n << "\"><br><span class=\"caption\"><b>Figure " << n << ".</b> "
       << html_escape(f.caption);
  if (!f.id.empty()) out_ << " (" << html_escape(f.id) << ")";
  out_ << "</span></p>\n";
  return n;
}

int ReportBuilder::table(const ReportTable& t) {
  const int n = ++tables_;
  const auto right = [&](std::size_t c) { return c < t.align.size() ? t.align[c] == 'r' : c > 0 && t.numeric_right; };
  // Caption above, as journals set tables.
  out_ << "<p class=\"caption\"><b>Table " << n << ".</b> " << html_escape(t.caption) << "</p>\n";
  out_ << "<table class=\"data\" width=\"100%\" cellspacing=\"0\" cellpadding=\"3\">\n";
  // The header rows in <thead>: a table that runs over a page break repeats them there (Qt's importer makes them
  // the table's header rows; browsers print them again too).
  out_ << "<thead>\n";
  for (std::size_t r = 0; r < t.header.size(); ++r) {
    out_ << "<tr class=\"" << (r == 0 ? "head" : "units") << "\">";
    for (std::size_t c = 0; c < t.header[r].size(); ++c) {
      out_ << "<th";
      if (r == 0 && c < t.width_percent.size()) out_ << " width=\"" << t.width_percent[c] << "%\"";
      out_ << " align=\"" << (right(c) ? "right" : "left") << "\">" << html_escape(t.header[r][c]) << "</th>";
    }
    out_ << "</tr>\n";
  }
  out_ << "</thead>\n<tbody>\n";
  for (const auto& row : t.rows) {
    out_ << "<tr>";
    for (std::size_t c = 0; c < row.size(); ++c) {
      if (c == 0 && t.align.empty())
        out_ << "<td class=\"rowhead\">" << html_escape(row[c]) << "</td>";
      else
        out_ << "<td" << (right(c) ? " align=\"right\"" : "") << ">" << html_escape(row[c]) << "</td>";
    }
    out_ << "</tr>\n";
  }
  out_ << "</tbody>\n</table>\n";
  // The notes run on in one paragraph, as a journal sets table footnotes: no half-empty line per note.
  if (!t.notes.empty()) {
    out_ << "<p class=\"note\">";
    for (std::size_t i = 0; i < t.notes.size(); ++i) out_ << (i ? " " : "") << html_escape(t.notes[i]);
    out_ << "</p>\n";
  }
  return n;
}

}  // namespace bs
