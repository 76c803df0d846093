// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Typed, located access to untrusted JSON: every failure becomes an ImportError naming the file, the JSON pointer
// of the offending field and its line:column, so JSON importers never repeat their validation boilerplate.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "common/import_error.h"
#include "common/importer.h"

namespace bs::json_access {

using json = nlohmann::json;

// Parses `text`, refusing nesting deeper than limits.max_json_depth and more than limits.max_json_values values
// while the document is being built (never after). Syntax errors carry line:column computed from the byte offset;
// a truncated document says "unexpected end of file"; NaN/Infinity literals are syntax errors and numbers that
// overflow a double (1e999) are InvalidValue with their location. A key that appears twice in one object with
// different values (or an object/array twice) is InvalidValue naming the key's second occurrence: nlohmann would
// keep the last silently. The same key twice with the same scalar value loses nothing and is accepted. Polls
// `cancel` while parsing when given.
json parse(std::string_view text, const std::string& file, const ImportLimits& limits,
           const CancelToken* cancel = nullptr);

// 1-based line and column (in characters, not bytes) of byte `offset` in `text`.
ErrorLocation location_of_offset(const std::string& file, std::string_view text, std::size_t offset);

// Byte offset where the value at JSON pointer `pointer` starts in the (valid) document `text`. When the pointer
// names something absent (a missing key), the offset of the deepest value that exists on the way, so an error
// about a missing field points at the object that lacks it.
std::size_t offset_of_pointer(std::string_view text, std::string_view pointer);

class Reader {
 public:
  // `text` is the parsed document's source; it lets errors carry line:column. It must outlive the Reader.
  Reader(std::string file, std::string_view text) : file_(std::move(file)), text_(text) {}
  const std::string& file() const { return file_; }

  [[noreturn]] void fail(ImportErrorCategory category, const std::string& pointer, const std::string& reason) const;
  // "file:line:col: /pointer" for warnings.
  std::string where(const std::string& pointer) const;

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
  std::int64_t integer(const json& value, const std::string& pointer, std::int64_t min, std::int64_t max) const;
  std::int64_t require_integer(const json& object, const std::string& pointer, std::string_view key, std::int64_t min,
                               std::int64_t max) const;

 private:
  ErrorLocation locate(const std::string& pointer) const;
  std::string file_;
  std::string_view text_;
};

// JSON pointer of a member / element (RFC 6901 escaping of '~' and '/').
std::string child(const std::string& pointer, std::string_view key);
inline std::string child(const std::string& pointer, std::size_t index) {
  return pointer + '/' + std::to_string(index);
}

}  // namespace bs::json_access
