// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The platform report (benchscope-cli report, GUI File > Export report) as HTML, in the shape of a benchmark
// report: page one holds the decision (the recommendation and the constraints it met, one comparison chart, the
// platforms table at the text width), then the details per platform, the figures, and an appendix of sources and
// provenance. No Qt: the figures arrive as image URIs (data: URIs for a self-contained file, resource names when Qt
// prints the same HTML to PDF).
//
// The report is a list of sections, each one function (ReportSection) that writes into a ReportBuilder; a new part
// of the report is one more function appended to the list in report_sections() (report_sections.h).
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "analysis/platform/platform_comparison.h"
#include "headroom/loop_requirement.h"
#include "model/dnn_run.h"
#include "report/candidates_section.h"
#include "report/report_html.h"
#include "sustain/sustain_requirement.h"

namespace bs {

struct ReportInput {
  std::string workspace;  // shown in the heading
  std::string generated;  // ISO 8601 date-time
  std::string tool;       // "benchscope 0.1.0"
  std::vector<PlatformRow> rows;
  std::vector<PlatformVerdict> verdicts;  // same order as rows, may be empty
  std::string constraints;                // human-readable constraints the verdicts used, e.g. "power budget 10 W"
  std::optional<ReportFigure> comparison_chart;      // page one's chart (report_chart in figures/)
  std::vector<ReportFigure> figures;                 // the template's figures, in template order
  std::vector<DnnRun> inference_runs;                // bench dnn runs: a table after the details when there are any
  std::string data_selection;                        // which data the report covers ("all data given")
  std::optional<CandidatesSectionInput> candidates;  // the "Candidates" section, after the details
  // Control-loop headroom (benchscope-cli headroom, the Headroom tab, imports): a section after the inference table;
  // with a loop requirement, its verdict per platform (already applied to `verdicts`).
  std::vector<headroom::HeadroomMeasurement> headroom;
  std::optional<headroom::LoopRequirement> loop;
  std::vector<headroom::LoopVerdict> loop_verdicts;
  // With a sustained requirement (sustain/sustain_requirement.h): its verdict per platform (already applied to
  // `verdicts`), in a section of its own after the control loop's.
  std::optional<sustain::SustainRequirement> sustained;
  std::vector<sustain::SustainVerdict> sustained_verdicts;
  std::vector<std::string> chosen_log_platforms;  // platforms whose power log the user chose among several
};

// Page one's account of what the decision rests on besides the data: each platform's power log where it has several
// (and whether the user chose it), and the library candidates; "" when there is nothing to say.
std::string decision_basis_text(const ReportInput& in);

using ReportSection = std::function<void(const ReportInput&, ReportBuilder&)>;

// The sections of report_sections() in order.
std::string report_html(const ReportInput& in);
std::string report_html(const ReportInput& in, const std::vector<ReportSection>& sections);

// The platforms table of page one: one row per measure that has a value for some platform (a measure nobody has is
// left out), a unit column, one column per platform. More platforms than fit across the text width (whole words,
// measured in characters) split it into several tables of the same rows.
std::vector<ReportTable> platform_summary_tables(const std::vector<PlatformRow>& rows,
                                                 const std::vector<PlatformVerdict>& verdicts);

// The recommendation in one sentence and the constraints it met, for page one ("" when nothing can be recommended).
std::string recommendation_text(const ReportInput& in);

}  // namespace bs
