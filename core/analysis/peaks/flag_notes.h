// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Plausibility flags as numbered footnotes of a table (CLI text, LaTeX/CSV exports, the report): a flagged cell gets
// "[1]" (or "[1,2]"), and the table's notes say "[1] above_spec_peak: <reason>". Equal flags share one number.
#include <string>
#include <vector>

#include "analysis/peaks/plausibility.h"
#include "util/table_export.h"

namespace bs {

class FlagNotes {
 public:
  // "[n,...]" for the flags (numbering new ones), "" for none.
  std::string marker(const std::vector<PlausibilityFlag>& flags);
  // `text` followed by " [n]" when flagged.
  std::string mark(const std::string& text, const std::vector<PlausibilityFlag>& flags);
  bool empty() const { return notes_.empty(); }
  // "[n] code: reason", one per flag, in number order.
  std::vector<std::string> lines() const;
  // Appends lines() to table.notes.
  void add_to(ExportTable& table) const;

 private:
  std::vector<PlausibilityFlag> notes_;
};

// A note line in short, for a figure or a page that has room for one line: "[1] above_spec_peak: 2.40 TFLOPS is
// 5.4x the X's FP32 peak of 441.60 GFLOPS (24 EUs ...). No measurement ..." -> "[1] 2.40 TFLOPS is 5.4x the X's
// FP32 peak of 441.60 GFLOPS." (the code and everything after the first sentence or parenthesis left out).
std::string short_flag_line(const std::string& line);

}  // namespace bs
