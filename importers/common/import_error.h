// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>

#include "model/error_category.h"

namespace bs {

// Where in the file the problem is. line/column are 1-based; 0 means unknown. field is a JSON pointer
// ("/samples/3/seconds/0") or a column name, empty when not applicable.
struct ErrorLocation {
  std::string file;
  std::size_t line = 0;
  std::size_t column = 0;
  std::string field;
};

// what() is one line: "<file>:<line>:<column>: <field>: <reason>" (parts that are unknown are left out).
class ImportError : public std::runtime_error {
 public:
  ImportError(ImportErrorCategory category, ErrorLocation location, std::string reason);
  ImportErrorCategory category() const noexcept { return category_; }
  const ErrorLocation& location() const noexcept { return location_; }
  const std::string& reason() const noexcept { return reason_; }

 private:
  ImportErrorCategory category_;
  ErrorLocation location_;
  std::string reason_;
};

}  // namespace bs
