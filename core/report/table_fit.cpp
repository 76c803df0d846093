// SPDX-License-Identifier: GPL-3.0-or-later
#include "report/table_fit.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace bs {

namespace {

// A unit's denominator of one or two characters after a '/' ("GFLOPS/W", "op/s"): the writer keeps it with the
// numerator (figures/report_writer.cpp, widest_unbreakable), so the word is counted whole.
bool short_denominator(std::string_view text, std::size_t from) {
  std::size_t n = 0;
  while (from + n < text.size() && text[from + n] != ' ' && text[from + n] != '/') ++n;
  return n >= 1 && n <= 2;
}

}  // namespace

std::size_t longest_word(std::string_view text) {
  std::size_t best = 0, run = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c == ' ') {
      best = std::max(best, run);
      run = 0;
      continue;
    }
    if ((c & 0xC0) != 0x80) ++run;
    // A line may break after this character: the slash of a path, a hyphen before a letter ("jetpack-orin", not
    // "Area-51").
    const bool digit_next = i + 1 < text.size() && text[i + 1] >= '0' && text[i + 1] <= '9';
    if ((c == '/' && !short_denominator(text, i + 1)) || (c == '-' && !digit_next && run > 1)) {
      best = std::max(best, run);
      run = 0;
    }
  }
  return std::max(best, run);
}

double column_need_pt(std::span<const std::vector<std::string>> rows, std::size_t column, double char_pt) {
  std::size_t widest = 1;
  for (const auto& row : rows)
    if (column < row.size()) widest = std::max(widest, longest_word(row[column]));
  return static_cast<double>(widest) * char_pt + kTableCellPadPt;
}

std::vector<std::pair<std::size_t, std::size_t>> fit_column_groups(std::span<const double> needs, double width_pt,
                                                                   std::size_t max_per_group) {
  std::vector<std::pair<std::size_t, std::size_t>> groups;
  std::size_t first = 0;
  double used = 0;
  for (std::size_t c = 0; c < needs.size(); ++c) {
    if (c > first && (used + needs[c] > width_pt || c - first >= std::max<std::size_t>(1, max_per_group))) {
      groups.emplace_back(first, c);
      first = c;
      used = 0;
    }
    used += needs[c];
  }
  if (first < needs.size()) groups.emplace_back(first, needs.size());
  return groups;
}

std::vector<ReportTable> split_to_width(const ReportTable& t, std::size_t keep) {
  std::vector<std::vector<std::string>> all = t.header;
  all.insert(all.end(), t.rows.begin(), t.rows.end());
  const std::size_t columns = t.header.empty() ? 0 : t.header.front().size();
  keep = std::min(keep, columns);
  std::vector<double> needs;
  for (std::size_t c = 0; c < columns; ++c) needs.push_back(column_need_pt(all, c, kTableMinCharPt));
  const double kept = std::accumulate(needs.begin(), needs.begin() + static_cast<std::ptrdiff_t>(keep), 0.0);
  auto groups = fit_column_groups(std::span<const double>(needs).subspan(keep),
                                  std::max(0.0, ReportBuilder::kTextWidthPt - kept), columns);
  if (groups.empty()) groups.emplace_back(0, 0);
  std::vector<ReportTable> out;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    std::vector<std::size_t> picked(keep);
    std::iota(picked.begin(), picked.end(), 0);
    for (std::size_t c = groups[g].first; c < groups[g].second; ++c) picked.push_back(keep + c);
    const auto cut = [&](const std::vector<std::string>& row) {
      std::vector<std::string> cells;
      for (const std::size_t c : picked) cells.push_back(c < row.size() ? row[c] : std::string());
      return cells;
    };
    ReportTable part;
    part.caption = t.caption;
    if (groups.size() > 1)
      part.caption += " (part " + std::to_string(g + 1) + " of " + std::to_string(groups.size()) + ")";
    for (const auto& row : t.header) part.header.push_back(cut(row));
    for (const auto& row : t.rows) part.rows.push_back(cut(row));
    // Widths in proportion to the needs: the PDF writer refits them from the fonts, a browser takes them as is.
    double sum = 0;
    for (const std::size_t c : picked) sum += needs[c];
    for (const std::size_t c : picked)
      part.width_percent.push_back(static_cast<int>(std::lround(100 * needs[c] / sum)));
    part.numeric_right = t.numeric_right;
    if (!t.align.empty())
      for (const std::size_t c : picked) part.align += c < t.align.size() ? t.align[c] : 'l';
    if (g + 1 == groups.size()) part.notes = t.notes;
    out.push_back(std::move(part));
  }
  return out;
}

}  // namespace bs
