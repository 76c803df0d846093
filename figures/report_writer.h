// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Writes the platform report (core/report/platform_report.h) as a self-contained HTML file (figures embedded as
// PNG data URIs) and/or a PDF printed with Qt (QTextDocument on A4), the figures rendered from the same templates
// as `benchscope-cli figures`. Needs a QApplication (offscreen works).
#include <QString>
#include <QStringList>

#include "headroom/loop_requirement.h"
#include "paper_figures.h"
#include "report/candidates_section.h"
#include "store/decision_store.h"
#include "sustain/sustain_requirement.h"

namespace bs::ui {

struct ReportRequest {
  QString workspace_name;
  QString html_path;  // empty: no HTML
  QString pdf_path;   // empty: no PDF
  Constraints constraints;
  ComparisonOptions comparison;
  std::optional<CandidatesSectionInput> candidates;      // the "Candidates" section (report/candidates_section.h)
  std::optional<headroom::LoopRequirement> loop;         // a control-loop requirement (headroom/loop_requirement.h)
  std::optional<sustain::SustainRequirement> sustained;  // a sustained requirement (sustain/sustain_requirement.h)
  std::vector<std::string> chosen_log_platforms;         // platforms whose power log the user chose among several
};

// Returns the files written. Each file appears whole or not at all (QSaveFile); Cancelled or an error leaves none.
QStringList write_report(const ReportRequest& request, const std::vector<FigureTemplate>& templates,
                         const FigureData& data, const FigureOptions& figure_options, const CancelToken& cancel,
                         const std::function<void(int done, int total, const QString& what)>& progress = {});

// "a power budget of 10 W, at least 5 fps" for the report's heading: bs::describe_constraints (store/decision_store.h),
// the same words the CLI prints for the constraints stored in a workspace.
using bs::describe_constraints;

}  // namespace bs::ui
