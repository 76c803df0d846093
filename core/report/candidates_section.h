// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The report's "Candidates" section: the own platforms beside published results from the library
// (analysis/library/candidates.h ranks them), written through the ReportBuilder like every other section, so its
// tables are numbered and fit the page as the platforms table of page one does (report/table_fit.h): short
// headers with the units in a header row, whole words, split by columns when they do not fit. What a row says in
// words (statistic, differences, conditions, source) follows the table as notes keyed by the row's number.
// candidates_section() (report_sections.h) places it after the details.
#include <string>
#include <vector>

#include "analysis/library/candidates.h"
#include "report/report_html.h"

namespace bs {

struct CandidatesSectionInput {
  std::vector<CandidateClass> classes;
  std::vector<PeakClass> peaks;
  std::string selection;    // what was taken from the library, e.g. "orin, pi5"
  std::string constraints;  // as the report's heading says them; empty: none
  std::string figure_src;   // an image of the candidates figure (data URI or resource name); empty: none
};

// Writes nothing when there is nothing to show (no library selection and no own inference result).
void write_candidates_section(const CandidatesSectionInput& in, ReportBuilder& b);

}  // namespace bs
