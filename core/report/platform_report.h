// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The one-page-per-platform report (benchscope-cli report, GUI File > Export report) as self-contained HTML:
// the comparison table, then per platform its peaks, % of theoretical peak, power, GFLOPS/W, battery runtime and
// pipeline timings with where each number came from, then the figures. No Qt: the figures arrive as image URIs
// (data: URIs for a self-contained file, resource names when Qt prints the same HTML to PDF).
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/platform/platform_comparison.h"
#include "model/dnn_run.h"

namespace bs {

struct ReportFigure {
  std::string caption;
  std::string image_src;  // an <img src>: "data:image/png;base64,..." or a name the renderer resolves
};

struct ReportInput {
  std::string workspace;  // shown in the heading
  std::string generated;  // ISO 8601 date-time
  std::string tool;       // "benchscope 0.1.0"
  std::vector<PlatformRow> rows;
  std::vector<PlatformVerdict> verdicts;  // same order as rows, may be empty
  std::string constraints;                // human-readable constraints the verdicts used, e.g. "power budget 10 W"
  std::vector<ReportFigure> figures;
  std::vector<DnnRun> inference_runs;  // bench dnn runs: a table after the comparison when there are any
  std::string candidates_html;         // the "Candidates" section (report/candidates_section.h), after the pages
};

std::string report_html(const ReportInput& in);
std::string html_escape(std::string_view text);

}  // namespace bs
