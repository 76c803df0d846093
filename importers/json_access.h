// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Typed, located access to untrusted JSON: every failure becomes an ImportError naming the file and the JSON
// pointer of the offending field, so JSON importers never repeat their validation boilerplate.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "import_error.h"

namespace bs::json_access {

using json = nlohmann::json;

// Parses `text` refusing nesting deeper than `max_depth` before the document is built. Syntax errors carry
// line:column computed from the byte offset; NaN/Infinity literals and number overflow are rejected.
json parse(std::string_view text, const std::string& file, std::size_t max_depth);

class Reader {
 public:
  explicit Reader(std::string file) : file_(std::move(file)) {}
  const std::string& file() const { return file_; }

  [[noreturn]] void fail(ImportErrorCategory category, const std::string& pointer, const std::string& reason) const;

  const json& require(const json& object, const std::string& pointer, std::string_view key) const;
  const json* optional(const json& object, std::string_view key) const;  // nullptr when absent or null

  const json& require_object(const json& value, const std::string& pointer) const;
  const json& require_array(const json& value, const std::string& pointer) const;
  std::string require_string(const json& object, const std::string& pointer, std::string_view key) const;
  std::string optional_string(const json& object, const std::string& pointer, std::string_view key,
                              std::string fallback = {}) const;
  double number(const json& value, const std::string& pointer) const;  // finite number
  double require_number(const json& object, const std::string& pointer, std::string_view key) const;
  std::optional<double> optional_number(const json& object, const std::string& pointer, std::string_view key) const;
  std::int64_t require_integer(const json& object, const std::string& pointer, std::string_view key,
                               std::int64_t min, std::int64_t max) const;

 private:
  std::string file_;
};

inline std::string child(const std::string& pointer, std::string_view key) {
  std::string out = pointer;
  out += '/';
  out += key;
  return out;
}
inline std::string child(const std::string& pointer, std::size_t index) {
  return pointer + '/' + std::to_string(index);
}

}  // namespace bs::json_access
