// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <iosfwd>
#include <string>
#include <vector>

#include "util/text.h"

namespace bs::cli {

// A plain aligned text table for terminal output. Column widths count UTF-8 code points, not bytes.
class TextTable {
 public:
  explicit TextTable(std::vector<std::string> header) : header_(std::move(header)) {}
  void add(std::vector<std::string> row) { rows_.push_back(std::move(row)); }
  bool empty() const { return rows_.empty(); }
  void print(std::ostream& out) const;

 private:
  std::vector<std::string> header_;
  std::vector<std::vector<std::string>> rows_;
};

// Table cells and report lines format numbers with util/text.h's format_number.
using bs::format_number;

}  // namespace bs::cli
