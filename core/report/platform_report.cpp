// SPDX-License-Identifier: GPL-3.0-or-later
#include "report/platform_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "analysis/peaks/flag_notes.h"
#include "analysis/platform/platform_table.h"
#include "report/report_sections.h"
#include "report/table_fit.h"

namespace bs {
namespace {

// Print-friendly: serif body like a paper, small tables with rules above and below (booktabs' look). Browsers
// read all of it; Qt's QTextDocument reads the fonts, sizes, colours and borders.
constexpr const char* kStyle = R"(
body { font-family: 'DejaVu Serif', serif; font-size: 9.5pt; max-width: 180mm; }
h1 { font-size: 14pt; margin: 0 0 2pt 0; } h2 { font-size: 12pt; margin: 8pt 0 3pt 0; }
h3 { font-size: 10pt; margin: 8pt 0 2pt 0; }
p { margin: 2pt 0 4pt 0; }
table.data { border-collapse: collapse; border-top: 1.2px solid black; border-bottom: 1.2px solid black;
  font-size: 8.5pt; margin: 2pt 0 2pt 0; }
table.data th { border-bottom: 0.6px solid black; font-weight: bold; vertical-align: bottom; }
table.data tr.units th { font-weight: normal; font-style: italic; }
table.data td { vertical-align: top; }
td.rowhead { font-weight: normal; }
.decision { font-size: 10pt; }
.note { color: #444; font-size: 8pt; margin: 0; }
.flags { color: #8a4b00; }
.caption { font-size: 8.5pt; }
p.figure { margin: 6pt 0 10pt 0; }
img { max-width: 100%; }
)";

const char* const kDash = "\xE2\x80\x93";  // en dash: no data

struct Measure {
  std::string name, unit;
};

// "GPU peak (TFLOPS)" -> {"GPU peak", "TFLOPS"}: units go to their own column, the measure keeps the words.
Measure split_header(const std::string& h) {
  static const std::vector<std::pair<std::string, Measure>> kNamed = {
      {"GFLOPS/W (paper: peak / max power)", {"Efficiency (paper)", "GFLOPS/W"}},
      {"GFLOPS/W (peak / mean power)", {"Efficiency (mean)", "GFLOPS/W"}},
      {"Of theoretical peak", {"Of theoretical peak", "%"}},
      {"Energy per preprocessed frame (J)", {"Energy, preprocessing", "J"}},
      {"Energy per inference (J)", {"Energy, inference", "J"}},
      {"Frames per Wh", {"Frames per Wh", "1/Wh"}},
      {"Failed (margin)", {"Failed (margin)", ""}},
  };
  for (const auto& [full, m] : kNamed)
    if (h == full) return m;
  const auto open = h.rfind(" (");
  if (open != std::string::npos && h.back() == ')') {
    const std::string unit = h.substr(open + 2, h.size() - open - 3);
    if (unit.find(' ') == std::string::npos) return {h.substr(0, open), unit};
  }
  return {h, ""};
}

// "4.7 (Jetson CPU (ARM A57 + Denver2), CPU SIMD (NEON))" -> "4.7 (Jetson CPU, CPU SIMD)": a device's details
// stay in the platform details, the table keeps the names.
std::string without_nested_parentheses(const std::string& text) {
  std::string out;
  int depth = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '(') ++depth;
    if (depth < 2) out += c;
    if (c == ')') --depth;
    if (depth >= 2 && !out.empty() && out.back() == ' ') out.pop_back();  // the space before "(ARM ..."
  }
  return out;
}

}  // namespace

std::vector<ReportTable> platform_summary_tables(const std::vector<PlatformRow>& rows,
                                                 const std::vector<PlatformVerdict>& verdicts) {
  const ExportTable table = platform_table(rows, verdicts);
  // Transposed: a measure per row, a platform per column (fifteen measures never fit across a page, a few
  // platforms do). Rows where no platform has a value are left out.
  std::vector<std::vector<std::string>> body;
  for (std::size_t c = 1; c < table.header.size(); ++c) {
    const Measure m = split_header(table.header[c]);
    std::vector<std::string> row{m.name, m.unit.empty() ? kDash : m.unit};
    bool any = false;
    const bool peak = m.name == "GPU peak" || m.name == "CPU peak";
    for (const auto& cells : table.rows) {
      std::string cell = c < cells.size() ? cells[c] : kDash;
      if (peak) cell = without_nested_parentheses(cell);
      if (cell == "yes (recommended)") cell = "yes: chosen";  // "(recommended)" is the table's widest word
      for (std::string::size_type at; (at = cell.find(" (mean power)")) != std::string::npos;) cell.erase(at, 13);
      if (m.unit == "%")
        if (const auto p = cell.find(" %"); p != std::string::npos) cell.erase(p, 2);
      any = any || cell != kDash;
      row.push_back(std::move(cell));
    }
    if (any) body.push_back(std::move(row));
  }
  // One table whenever the platforms fit side by side at the smallest table font after the measure and unit
  // columns, each platform as wide as the widest platform column (report/table_fit.h): one look for every column.
  // Only more platforms than that (or than eight) go on in a further table of the same rows.
  std::vector<std::vector<std::string>> kept_columns{{"Measure", "Unit"}};
  for (const auto& row : body) kept_columns.push_back({row[0], row[1]});
  const double kept_pt =
      column_need_pt(kept_columns, 0, kTableMinCharPt) + column_need_pt(kept_columns, 1, kTableMinCharPt);
  const double platform_pt = ReportBuilder::kTextWidthPt - kept_pt;
  double need = 6 * kTableMinCharPt + kTableCellPadPt;
  for (std::size_t p = 0; p < table.rows.size(); ++p) {
    need = std::max(need, static_cast<double>(longest_word(table.rows[p][0])) * kTableMinCharPt + kTableCellPadPt);
    for (const auto& row : body)
      need = std::max(need, static_cast<double>(longest_word(row[p + 2])) * kTableMinCharPt + kTableCellPadPt);
  }
  const std::vector<double> needs(table.rows.size(), need);
  const auto groups = fit_column_groups(needs, platform_pt, 8);
  const double measure_pct =
      std::round(100 * column_need_pt(kept_columns, 0, kTableMinCharPt) / ReportBuilder::kTextWidthPt);
  const double unit_pct =
      std::round(100 * column_need_pt(kept_columns, 1, kTableMinCharPt) / ReportBuilder::kTextWidthPt);
  const std::size_t per_table = groups.empty() ? 1 : groups.front().second - groups.front().first;
  std::vector<ReportTable> out;
  for (const auto& [first, last] : groups) {
    ReportTable t;
    t.caption = "Platforms at a glance";
    if (table.rows.size() > per_table)
      t.caption += " (platforms " + std::to_string(first + 1) + " to " + std::to_string(last) + " of " +
                   std::to_string(table.rows.size()) + ")";
    t.caption +=
        ". Timings are mean \xC2\xB1 SD (n); efficiency (paper): peak / max power, (mean): peak / mean "
        "power; " +
        std::string(kDash) + ": no data.";
    std::vector<std::string> head{"Measure", "Unit"};
    t.width_percent = {static_cast<int>(measure_pct), static_cast<int>(unit_pct)};
    const int each = static_cast<int>((100 - measure_pct - unit_pct) / static_cast<double>(last - first));
    for (std::size_t p = first; p < last; ++p) {
      head.push_back(table.rows[p][0]);
      t.width_percent.push_back(each);
    }
    t.header.push_back(std::move(head));
    for (const auto& row : body) {
      std::vector<std::string> cells{row[0], row[1]};
      for (std::size_t p = first; p < last; ++p) cells.push_back(row[p + 2]);
      t.rows.push_back(std::move(cells));
    }
    // The flags' footnotes once, under the last part, in short: the reasons in full are in the platform details.
    if (last == table.rows.size()) {
      for (const std::string& note : table.notes) t.notes.push_back(short_flag_line(note));
      if (!table.notes.empty()) t.notes.push_back("In full: Platform details.");
    }
    out.push_back(std::move(t));
  }
  return out;
}

std::string recommendation_text(const ReportInput& in) {
  for (const PlatformVerdict& v : in.verdicts)
    if (v.recommended)
      return "Recommended" + (in.constraints.empty() ? std::string() : " under " + in.constraints) + ": " + v.platform;
  return {};
}

std::string decision_basis_text(const ReportInput& in) {
  std::string logs;
  for (const PlatformRow& r : in.rows) {
    if (r.power_log.empty()) continue;
    logs += (logs.empty() ? "" : "; ") + r.platform + ": " + r.power_log;
    if (r.power_logs > 1) {
      const bool chosen = std::find(in.chosen_log_platforms.begin(), in.chosen_log_platforms.end(), r.platform) !=
                          in.chosen_log_platforms.end();
      logs += " (" + std::string(chosen ? "chosen of " : "the first of ") + std::to_string(r.power_logs) + " logs)";
    }
  }
  std::string out;
  if (!logs.empty()) out = "Power logs used: " + logs + ".";
  if (in.candidates && !in.candidates->selection.empty())
    out += (out.empty() ? "" : " ") + std::string("Library candidates: ") + in.candidates->selection + ".";
  return out;
}

std::string report_html(const ReportInput& in) { return report_html(in, report_sections()); }

std::string report_html(const ReportInput& in, const std::vector<ReportSection>& sections) {
  ReportBuilder b;
  b.html("<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\">\n<title>BenchScope report: " +
         html_escape(in.workspace) + "</title>\n<style>" + kStyle + "</style></head>\n<body>\n");
  for (const ReportSection& section : sections) section(in, b);
  b.html("</body></html>\n");
  return b.str();
}

}  // namespace bs
