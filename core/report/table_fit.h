// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Report tables that fit the text width with whole words: the platforms table of page one, the candidates' tables
// and the sources appendix. A column needs its longest word (header or cell) at about 5 pt a character in the
// tables' 8.5 pt DejaVu Serif, plus padding. A table too wide at 8.5 pt is set smaller, down to 7 pt, before it is
// split: only columns that do not fit even then, beside the ones kept in every part, go to a further part. The PDF
// writer then sizes the columns and the font from the real font metrics (figures/report_writer.cpp, fit_tables).
// A "word" is what a line cannot break inside: text layouts (Qt's and browsers', Unicode line breaking) also break
// after '/' and after a '-' that no digit follows, so a file path or "perf-rapl-validation.csv" wraps there.
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
inline constexpr double kTableFontPt = 8.5;     // the tables' font (platform_report.cpp's style)
inline constexpr double kTableMinFontPt = 7.0;  // the smallest a too-wide table is set before it is split
// Points a character takes at the smallest table font.
inline constexpr double kTableMinCharPt = kTableCharPt * kTableMinFontPt / kTableFontPt;

// The longest word of `text` in characters (UTF-8 continuation bytes not counted): words end at spaces, after '/'
// (except before a unit's denominator of 1-2 characters: "GFLOPS/W" is one word) and after a '-' not followed by a
// digit, where lines break.
std::size_t longest_word(std::string_view text);
// Points a column needs so that no word of it breaks: its longest word in any of `rows`, at `char_pt` a character.
double column_need_pt(std::span<const std::vector<std::string>> rows, std::size_t column,
                      double char_pt = kTableCharPt);
// Consecutive groups [first, last) of columns with widths `needs` (points) that each fit `width_pt`, at most
// `max_per_group` columns in one; a column wider than `width_pt` gets a group of its own.
std::vector<std::pair<std::size_t, std::size_t>> fit_column_groups(std::span<const double> needs, double width_pt,
                                                                   std::size_t max_per_group);
// `t` split by columns to fit ReportBuilder::kTextWidthPt at the smallest table font: the first `keep` columns (row
// headings) in every part, the others in groups (fit_column_groups); width_percent set from the needs. One part
// when it fits (the usual case); several: the captions end " (part i of n)" and the notes go under the last part.
std::vector<ReportTable> split_to_width(const ReportTable& t, std::size_t keep);

}  // namespace bs
