// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Report tables that fit the text width with whole words: the platforms table of page one and the candidates'
// tables. A column needs its longest word (header or cell) at about 5 pt a character in the tables' 8.5 pt DejaVu
// Serif, plus padding; columns that do not fit beside the ones kept in every part go to a further part of the
// table. The PDF writer then sizes the columns from the real font metrics (figures/report_writer.cpp, fit_tables).
#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "report/report_html.h"

namespace bs {

inline constexpr double kTableCharPt = 5.0;     // DejaVu Serif at 8.5 pt averages 4.7 pt a character
inline constexpr double kTableCellPadPt = 8.0;  // cell padding and rule

// The longest word of `text` in characters (UTF-8 continuation bytes not counted).
std::size_t longest_word(std::string_view text);
// Points a column needs so that no word of it breaks: its longest word in any of `rows`.
double column_need_pt(std::span<const std::vector<std::string>> rows, std::size_t column);
// Consecutive groups [first, last) of columns with widths `needs` (points) that each fit `width_pt`, at most
// `max_per_group` columns in one; a column wider than `width_pt` gets a group of its own.
std::vector<std::pair<std::size_t, std::size_t>> fit_column_groups(std::span<const double> needs, double width_pt,
                                                                   std::size_t max_per_group);
// `t` split by columns to fit ReportBuilder::kTextWidthPt: the first `keep` columns (row headings) in every part,
// the others in groups (fit_column_groups); width_percent set from the needs. Several parts: the captions end
// " (part i of n)" and the notes go under the last part.
std::vector<ReportTable> split_to_width(const ReportTable& t, std::size_t keep);

}  // namespace bs
