// SPDX-License-Identifier: GPL-3.0-or-later
#include "report/candidates_section.h"

#include <sstream>

#include "report/platform_report.h"

namespace bs {
namespace {

// "https://github.com/owner/repo/blob/<commit>/.../file" -> "owner/repo@1234567 .../<folder>/file": short enough
// for an A4 column, the full address stays in the link.
std::string link_text(const std::string& url) {
  constexpr std::string_view kGithub = "https://github.com/";
  if (!url.starts_with(kGithub)) return url;
  const std::string rest = url.substr(kGithub.size());
  const std::size_t blob = rest.find("/blob/");
  if (blob == std::string::npos) return rest;
  const std::string repo = rest.substr(0, blob);
  const std::string after = rest.substr(blob + 6);
  const std::string commit = after.substr(0, std::min<std::size_t>(7, after.find('/')));
  std::string path = after.substr(after.find('/') + 1);
  // The last four path components name the result (system/network/scenario/.../file).
  std::size_t cut = path.size();
  for (int i = 0; i < 6 && cut != std::string::npos && cut > 0; ++i) cut = path.rfind('/', cut - 1);
  if (cut != std::string::npos && cut > 0) path = "…" + path.substr(cut);
  return repo + "@" + commit + " " + path;
}

}  // namespace

std::string candidates_section_html(const CandidatesSectionInput& in) {
  if (in.classes.empty() && in.peaks.empty()) return {};
  std::ostringstream h;
  h << "<div class=\"platform\">\n<h2>Candidates</h2>\n"
    << "<p>Computers this lab does not own yet, from BenchScope's library of published results"
    << (in.selection.empty() ? "" : " (" + html_escape(in.selection) + ")")
    << ", beside the platforms above. Origin is said in every row: <b>measured</b> (this lab), "
    << "<b>reconstructed</b> (from the paper's figures) or <b>published</b> (others' files, each with its source). "
    << "Results are ranked only within one network, scenario and precision"
    << (in.constraints.empty() ? "" : ", under " + html_escape(in.constraints))
    << "; what still differs inside a class is said in the row.</p>\n";
  // Nine narrow columns fit an A4 page; what a row says in words (statistic, differences, conditions, source)
  // follows on a line of its own under it.
  const bool constrained = !in.constraints.empty();
  const ExportTable t = candidates_table(in.classes, constrained);
  std::size_t row = 0;
  for (const CandidateClass& k : in.classes) {
    h << "<h3>" << html_escape(k.title()) << "</h3>\n<table width=\"100%\" style=\"font-size: 8pt\">\n<tr>"
      << "<th>#</th><th>Platform</th><th>Origin</th><th>Latency ms</th><th>Rate 1/s</th>"
      << "<th>Power W</th><th>mJ per inference</th><th>Battery h</th>"
      << (constrained ? "<th>Meets constraints</th>" : "") << "</tr>\n";
    for (std::size_t i = 0; i < k.rows.size(); ++i, ++row) {
      const Candidate& c = k.rows[i];
      const auto& cells = t.rows[row];
      const bool published = c.origin == DataOrigin::Published;
      const std::string style = published ? " style=\"font-style: italic\"" : "";
      h << "<tr" << style << "><td>" << html_escape(cells[1]) << "</td><td>" << html_escape(cells[2]) << "</td><td>"
        << (published                               ? "&#9670; "
            : c.origin == DataOrigin::Reconstructed ? "&#9632; "
                                                    : "&#9679; ")
        << html_escape(cells[3]) << "</td>";
      h << "<td class=\"num\">" << html_escape(cells[4].substr(0, cells[4].find(' '))) << "</td>";
      for (std::size_t col = 5; col <= 8; ++col) h << "<td class=\"num\">" << html_escape(cells[col]) << "</td>";
      if (constrained) h << "<td>" << html_escape(cells[9]) << "</td>";
      h << "</tr>\n<tr" << style << "><td></td><td colspan=\"" << (constrained ? 8 : 7) << "\" class=\"note\">";
      std::string words = c.latency_s ? "latency: " + c.latency_statistic : std::string();
      const std::string& more = cells[cells.size() - 2];
      if (!more.empty()) words += (words.empty() ? "" : "; ") + more;
      h << html_escape(words);
      const std::string& src = cells.back();
      if (src.starts_with("http"))
        h << " &mdash; <a href=\"" << html_escape(src) << "\">" << html_escape(link_text(src)) << "</a>";
      else if (!src.empty())
        h << " &mdash; " << html_escape(src);
      h << "</td></tr>\n";
    }
    h << "</table>\n";
  }
  for (const std::string& n : t.notes) h << "<p class=\"note flags\">" << html_escape(n) << "</p>\n";
  if (!in.peaks.empty()) {
    const ExportTable p = peak_candidates_table(in.peaks);
    h << "<h3>Compute peaks</h3>\n<table width=\"100%\" style=\"font-size: 8pt\">\n<tr>";
    for (const std::string& c : p.header) h << "<th>" << html_escape(c) << "</th>";
    h << "</tr>\n";
    for (const auto& cells : p.rows) {
      h << "<tr>";
      for (std::size_t c = 0; c < cells.size(); ++c) {
        if (c + 1 == cells.size() && cells[c].starts_with("http"))
          h << "<td><a href=\"" << html_escape(cells[c]) << "\">source</a></td>";
        else
          h << "<td" << (c >= 4 && c <= 6 ? " class=\"num\"" : "") << ">" << html_escape(cells[c]) << "</td>";
      }
      h << "</tr>\n";
    }
    h << "</table>\n";
    for (const std::string& n : p.notes) h << "<p class=\"note flags\">" << html_escape(n) << "</p>\n";
  }
  if (!in.figure_src.empty())
    h << "<figure><img src=\"" << html_escape(in.figure_src)
      << "\" width=\"600\" alt=\"Candidates\"><figcaption>Candidates: inferences per second against power, one "
         "marker per origin (measured, reconstructed, published)</figcaption></figure>\n";
  h << "</div>\n";
  return h.str();
}

}  // namespace bs
