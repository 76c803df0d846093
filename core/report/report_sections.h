// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The report's sections, in order. Each writes its part through the ReportBuilder (headings, paragraphs, numbered
// tables and figures); figures and tables are numbered in the order the sections write them.
//
// Adding a section: write `void my_section(const ReportInput& in, ReportBuilder& b)` (a file of its own under
// core/report/ when it is more than a few lines), add what it needs to ReportInput (platform_report.h) and fill
// that in figures/report_writer.cpp, then append `my_section` to the list in report_sections() (report_sections.cpp)
// where it should appear. A section that has nothing to show writes nothing.
#include <vector>

#include "report/platform_report.h"

namespace bs {

// Page one: title, the recommendation with the constraints it met (and why others failed), the comparison chart
// and the platforms table with its footnotes.
void decision_section(const ReportInput& in, ReportBuilder& b);
// Per platform: where its peaks came from (device, backend, D, workers, % of peak), how power was measured, and
// every plausibility flag with its reason.
void platform_details_section(const ReportInput& in, ReportBuilder& b);
// bench dnn runs: the inference table (only when there are any).
void inference_section(const ReportInput& in, ReportBuilder& b);
// Headroom measurements: per measurement its kernel facts, flags and table per phase and thread; the loop
// requirement's verdicts first when one was set (only when there is something to show).
void headroom_section(const ReportInput& in, ReportBuilder& b);
// The sustained requirement's verdict per platform, with its margin or reason and the run that judged it (only when
// a sustained requirement was set).
void sustained_section(const ReportInput& in, ReportBuilder& b);
// Published results beside the own platforms (report --library, the GUI's candidates):
// write_candidates_section() (report/candidates_section.h), after the details; nothing without a selection.
void candidates_section(const ReportInput& in, ReportBuilder& b);
// The template's figures, numbered, each with its caption under it.
void figures_section(const ReportInput& in, ReportBuilder& b);
// Appendix: the report's own provenance, then every number's source (file, origin, how it was derived) and every
// figure's data.
void sources_appendix(const ReportInput& in, ReportBuilder& b);

std::vector<ReportSection> report_sections();

}  // namespace bs
