// SPDX-License-Identifier: GPL-3.0-or-later
#include "report/candidates_section.h"

#include "report/table_fit.h"

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
  // The last path components name the result (system/network/scenario/.../file).
  std::size_t cut = path.size();
  for (int i = 0; i < 6 && cut != std::string::npos && cut > 0; ++i) cut = path.rfind('/', cut - 1);
  if (cut != std::string::npos && cut > 0) path = "\xE2\x80\xA6" + path.substr(cut);
  return repo + "@" + commit + " " + path;
}

// A source as HTML: a link for an address, the file name otherwise.
std::string source_html(const std::string& src) {
  if (src.starts_with("http")) return "<a href=\"" + html_escape(src) + "\">" + html_escape(link_text(src)) + "</a>";
  return html_escape(src);
}

// The row notes under a table: "1: latency p90; MaxQ — source. 2: ..." in one paragraph, as table footnotes are set.
void row_notes(ReportBuilder& b, const std::vector<std::pair<std::string, std::string>>& notes) {
  std::string html;
  for (const auto& [key, text] : notes)
    if (!text.empty()) html += (html.empty() ? "" : " ") + std::string("<b>") + html_escape(key) + ":</b> " + text;
  if (!html.empty()) b.html("<p class=\"note\">" + html + "</p>\n");
}

// The figure's marker for the origin, joined to the word by a no-break space: "◆ published" never splits.
const char* origin_mark(DataOrigin o) {
  switch (o) {
    case DataOrigin::Published:
      return "\xE2\x97\x86\xC2\xA0";  // ◆, as the candidates figure draws it
    case DataOrigin::Reconstructed:
      return "\xE2\x96\xA0\xC2\xA0";  // ■
    default:
      return "\xE2\x97\x8F\xC2\xA0";  // ●
  }
}

void class_tables(const CandidatesSectionInput& in, ReportBuilder& b) {
  const bool constrained = !in.constraints.empty();
  // Columns of candidates_table(): class, rank, platform, origin, latency, rate, power, energy, battery,
  // [meets], differences and conditions, source.
  const ExportTable all = candidates_table(in.classes, constrained);
  std::size_t row = 0;
  for (const CandidateClass& k : in.classes) {
    ReportTable t;
    t.caption = "Candidates for " + k.title() + ", ranked (constraints met first, then by rate)";
    t.header = {{"#", "Platform", "Origin", "Latency", "Rate", "Power", "Energy", "Battery"},
                {"", "", "", "ms", "1/s", "W", "mJ", "h"}};
    t.align = "rllrrrrr";
    if (constrained) {
      t.header[0].push_back("Meets constraints");
      t.header[1].push_back("");
      t.align += "l";
    }
    std::vector<std::pair<std::string, std::string>> notes;
    for (std::size_t i = 0; i < k.rows.size(); ++i, ++row) {
      const Candidate& c = k.rows[i];
      const auto& cells = all.rows[row];
      std::vector<std::string> r{cells[1],
                                 cells[2],
                                 origin_mark(c.origin) + cells[3],
                                 cells[4].substr(0, cells[4].find(' ')),
                                 cells[5],
                                 cells[6],
                                 cells[7],
                                 cells[8]};
      if (constrained) r.push_back(cells[9]);
      t.rows.push_back(std::move(r));
      std::string words = c.latency_s ? "latency: " + c.latency_statistic : std::string();
      const std::string& more = cells[cells.size() - 2];
      if (!more.empty()) words += (words.empty() ? "" : "; ") + more;
      std::string note = html_escape(words);
      if (!cells.back().empty()) note += (note.empty() ? "" : " &mdash; ") + source_html(cells.back());
      notes.emplace_back(std::to_string(i + 1), note);
    }
    for (const ReportTable& part : split_to_width(t, 2)) b.table(part);
    row_notes(b, notes);
  }
  for (const std::string& n : all.notes) b.html("<p class=\"note flags\">" + html_escape(n) + "</p>\n");
}

void peak_tables(const CandidatesSectionInput& in, ReportBuilder& b) {
  if (in.peaks.empty()) return;
  // Columns of peak_candidates_table(): precision, platform, origin, device, peak, power, GFLOPS/W, kernel,
  // differences, source.
  const ExportTable p = peak_candidates_table(in.peaks);
  ReportTable t;
  t.caption = "Candidates' compute peaks, compared within one precision";
  t.header = {{"#", "Precision", "Platform", "Origin", "Device", "Peak", "Power", "Efficiency", "Kernel"},
              {"", "", "", "", "", "GFLOPS", "W", "GFLOPS/W", ""}};
  t.align = "rllllrrrl";
  std::vector<std::pair<std::string, std::string>> notes;
  std::size_t n = 0;
  for (const auto& cells : p.rows) {
    const std::string key = std::to_string(++n);
    t.rows.push_back({key, cells[0], cells[1], cells[2], cells[3], cells[4], cells[5], cells[6], cells[7]});
    std::string note = html_escape(cells[8]);
    if (!cells[9].empty()) note += (note.empty() ? "" : " &mdash; ") + source_html(cells[9]);
    notes.emplace_back(key, note);
  }
  t.notes = p.notes;
  for (const ReportTable& part : split_to_width(t, 3)) b.table(part);
  row_notes(b, notes);
}

}  // namespace

void write_candidates_section(const CandidatesSectionInput& in, ReportBuilder& b) {
  if (in.classes.empty() && in.peaks.empty()) return;
  b.html("<div class=\"platform\">\n");
  b.heading(2, "Candidates");
  b.html("<p>Computers this lab does not own yet, from BenchScope's library of published results" +
         (in.selection.empty() ? std::string() : " (" + html_escape(in.selection) + ")") +
         ", beside the platforms above. Origin is said in every row: <b>measured</b> (this lab), "
         "<b>reconstructed</b> (from the paper's figures) or <b>published</b> (others' files, each with its source). "
         "Results are ranked only within one network, scenario and precision" +
         (in.constraints.empty() ? std::string() : ", under " + html_escape(in.constraints)) +
         "; what still differs inside a class is said in the notes under its table, by row number.</p>\n");
  class_tables(in, b);
  peak_tables(in, b);
  if (!in.figure_src.empty())
    b.figure(
        {"Candidates: inferences per second against power, one marker per origin (measured, reconstructed, "
         "published)",
         in.figure_src, 0, 0, "candidates", "the candidates tables above"});
  b.html("</div>\n");
}

}  // namespace bs
