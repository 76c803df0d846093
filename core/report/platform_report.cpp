// SPDX-License-Identifier: GPL-3.0-or-later
#include "report/platform_report.h"

#include <cstdio>
#include <sstream>

#include "analysis/platform/inference_table.h"
#include "analysis/platform/platform_table.h"

namespace bs {
namespace {

// Print-friendly: serif body like a paper, each platform on its own page, tables that fit A4 portrait.
constexpr const char* kStyle = R"(
body { font-family: 'DejaVu Serif', serif; font-size: 10pt; margin: 1.5em; }
h1 { font-size: 16pt; } h2 { font-size: 13pt; } h3 { font-size: 11pt; }
table { border-collapse: collapse; margin: 0.5em 0; width: 100%; }
th, td { border-bottom: 1px solid #bbb; padding: 3px 8px; text-align: left; vertical-align: top; }
th { background: #eee; }
td.num { text-align: right; }
.platform { page-break-before: always; }
.note { color: #555; font-size: 9pt; }
.flags { color: #8a4b00; }
figure { margin: 1em 0; page-break-inside: avoid; }
figcaption { font-size: 9pt; }
)";

std::string percent(double fraction) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f %%", 100 * fraction);
  return buf;
}

std::string peak_detail(const PeakRow& p) {
  char buf[256];
  std::snprintf(buf, sizeof buf, "%.2f GFLOPS on %s (%s, D = %d, %lld workers)", p.peak.flops / 1e9, p.device.c_str(),
                p.backend.c_str(), p.dims, static_cast<long long>(p.peak.workers));
  std::string s = buf;
  if (p.fraction_of_theoretical) s += "; " + percent(*p.fraction_of_theoretical) + " of the theoretical peak";
  if (p.ratio_to_reported) s += "; " + percent(*p.ratio_to_reported) + " of the figure the vendor reports";
  if (p.fraction_of_spec) s += "; " + percent(*p.fraction_of_spec) + " of the " + p.spec->name + "'s FP32 peak";
  return s;
}

// Flags as a warning list: a flagged number is never shown without the reason.
void flag_list(std::ostringstream& h, const std::vector<PlausibilityFlag>& flags) {
  if (flags.empty()) return;
  h << "<ul class=\"flags\">\n";
  for (const PlausibilityFlag& f : flags)
    h << "<li><b>&#9888; " << html_escape(f.code) << "</b>: " << html_escape(f.reason) << "</li>\n";
  h << "</ul>\n";
}

void cell_row(std::ostringstream& h, const std::string& name, const std::string& value) {
  h << "<tr><th>" << html_escape(name) << "</th><td>" << html_escape(value) << "</td></tr>\n";
}

void platform_page(std::ostringstream& h, const ExportTable& table, std::size_t i, const PlatformRow& row) {
  h << "<div class=\"platform\">\n<h2>" << html_escape(row.platform) << "</h2>\n<table width=\"100%\">\n";
  for (std::size_t c = 1; c < table.header.size(); ++c) cell_row(h, table.header[c], table.rows[i][c]);
  h << "</table>\n";
  if (row.gpu) h << "<p>GPU peak: " << html_escape(peak_detail(*row.gpu)) << ".</p>\n";
  if (row.cpu) h << "<p>CPU peak: " << html_escape(peak_detail(*row.cpu)) << ".</p>\n";
  if (!row.power_measurement.empty()) h << "<p>Power measured by: " << html_escape(row.power_measurement) << ".</p>\n";
  flag_list(h, row.all_flags());
  if (!row.sources.empty()) {
    h << "<h3>Where the numbers come "
         "from</h3>\n<table>\n<tr><th>Measure</th><th>Source</th><th>Origin</th><th>How</th></tr>\n";
    for (const auto& [column, src] : row.sources)
      h << "<tr><td>" << html_escape(column) << "</td><td>" << html_escape(src.source_file) << "</td><td>"
        << html_escape(to_string(src.origin)) << "</td><td>" << html_escape(src.how) << "</td></tr>\n";
    h << "</table>\n";
  }
  h << "</div>\n";
}

}  // namespace

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

std::string report_html(const ReportInput& in) {
  const ExportTable table = platform_table(in.rows, in.verdicts);
  std::ostringstream h;
  h << "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\">\n<title>BenchScope report: " << html_escape(in.workspace)
    << "</title>\n<style>" << kStyle << "</style></head>\n<body>\n";
  h << "<h1>BenchScope report</h1>\n<p class=\"note\">Workspace " << html_escape(in.workspace) << ", generated "
    << html_escape(in.generated) << " by " << html_escape(in.tool)
    << ". Timings are mean &plusmn; SD (n); power figures use the supply voltage of each log.</p>\n";

  // Transposed, one column per platform: thirteen measures do not fit across an A4 page, four platforms do.
  h << "<h2>Platforms at a glance</h2>\n<table width=\"100%\">\n<tr><th>Measure</th>";
  for (const auto& cells : table.rows) h << "<th>" << html_escape(cells[0]) << "</th>";
  h << "</tr>\n";
  for (std::size_t c = 1; c < table.header.size(); ++c) {
    h << "<tr><th>" << html_escape(table.header[c]) << "</th>";
    for (const auto& cells : table.rows) h << "<td class=\"num\">" << html_escape(cells[c]) << "</td>";
    h << "</tr>\n";
  }
  h << "</table>\n";
  if (!table.notes.empty()) {
    h << "<div class=\"flags\"><p><b>Flags</b> (implausible numbers, marked [n] above):</p>\n";
    for (const std::string& n : table.notes) h << "<p class=\"note\">" << html_escape(n) << "</p>\n";
    h << "</div>\n";
  }
  for (const PlatformVerdict& v : in.verdicts)
    if (v.recommended)
      h << "<p><b>Recommended" << (in.constraints.empty() ? "" : " under " + html_escape(in.constraints)) << ": "
        << html_escape(v.platform)
        << "</b> (the highest peak among the platforms that meet every constraint and have a "
        << "power log).</p>\n";

  // Detection networks timed with bench dnn: one row per platform, network, input and target, as in the views.
  if (!in.inference_runs.empty()) {
    const ExportTable inf = inference_table(in.inference_runs);
    h << "<h2>Detection network inference</h2>\n<table width=\"100%\">\n<tr>";
    for (const std::string& c : inf.header) h << "<th>" << html_escape(c) << "</th>";
    h << "</tr>\n";
    for (const auto& cells : inf.rows) {
      h << "<tr>";
      for (std::size_t c = 0; c < cells.size(); ++c)
        h << "<td" << (c >= 4 ? " class=\"num\"" : "") << ">" << html_escape(cells[c]) << "</td>";
      h << "</tr>\n";
    }
    h << "</table>\n";
    for (const std::string& n : inf.notes) h << "<p class=\"note\">" << html_escape(n) << "</p>\n";
  }

  for (std::size_t i = 0; i < in.rows.size(); ++i) platform_page(h, table, i, in.rows[i]);
  h << in.candidates_html;

  if (!in.figures.empty()) {
    h << "<div class=\"platform\">\n<h2>Figures</h2>\n";
    for (const ReportFigure& f : in.figures)
      h << "<figure><img src=\"" << html_escape(f.image_src) << "\" width=\"600\" alt=\"" << html_escape(f.caption)
        << "\"><figcaption>" << html_escape(f.caption) << "</figcaption></figure>\n";
    h << "</div>\n";
  }
  h << "</body></html>\n";
  return h.str();
}

}  // namespace bs
