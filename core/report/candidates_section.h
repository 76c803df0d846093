// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The report's "Candidates" section: the own platforms beside published results from the library, as HTML
// (analysis/library/candidates.h ranks them). Kept apart from platform_report.cpp so that the report's layout and
// this section change independently; report_html() places ReportInput::candidates_html after the platform pages.
#include <span>
#include <string>

#include "analysis/library/candidates.h"

namespace bs {

struct CandidatesSectionInput {
  std::span<const CandidateClass> classes;
  std::span<const PeakClass> peaks;
  std::string selection;    // what was taken from the library, e.g. "orin, pi5"
  std::string constraints;  // as the report's heading says them; empty: none
  std::string figure_src;   // an image of the candidates figure (data URI or resource name); empty: none
};

// "" when there is nothing to show (no library selection and no own inference result).
std::string candidates_section_html(const CandidatesSectionInput& in);

}  // namespace bs
