// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A small table model written as LaTeX (booktabs; numbers as siunitx-friendly plain text) or CSV (RFC 4180), for
// the tables a lab puts in a paper or a spreadsheet.
#include <string>
#include <vector>

namespace bs {

struct ExportTable {
  std::string caption;
  std::string label;                // LaTeX \label, e.g. "tab:platforms"
  std::vector<std::string> header;  // may contain units, e.g. "Mean power (W)"
  std::vector<std::vector<std::string>> rows;
  std::string align;  // LaTeX column spec, e.g. "lrrr"; empty: first column l, others r
  // Footnotes under the table ("[1] above_spec_peak: ..."): LaTeX prints them below the tabular in \footnotesize;
  // CSV after one empty line, one note per line in the first column.
  std::vector<std::string> notes{};
};

// \begin{table}..\toprule..\midrule..\bottomrule..\end{table}; LaTeX special characters in cells are escaped.
std::string to_latex(const ExportTable& table);
// Header line then rows; cells with a comma, quote or newline are quoted, quotes doubled. Lines end with \r\n.
std::string to_csv(const ExportTable& table);
// Escapes & % $ # _ { } ~ ^ \ for LaTeX text; "±" becomes $\pm$.
std::string latex_escape(const std::string& text);

}  // namespace bs
