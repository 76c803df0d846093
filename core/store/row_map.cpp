// SPDX-License-Identifier: GPL-3.0-or-later
#include "store/row_map.h"

#include <charconv>

namespace bs::store {

std::string number_text(double v) {
  if (std::isnan(v)) return "NaN";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

namespace {
// Thrown from the parser callback to stop building the tree at once.
struct StopParsing {
  ImportErrorCategory category;
  std::string reason;
};
}  // namespace

Check parse_json(std::string_view text, const ImportLimits& limits, nlohmann::json& out) {
  if (text.size() > limits.max_json_bytes)
    return flaw(ImportErrorCategory::TooLarge, "JSON of " + std::to_string(text.size()) + " bytes (limit " +
                                                   std::to_string(limits.max_json_bytes) + ")");
  std::size_t values = 0;
  const auto callback = [&](int depth, nlohmann::json::parse_event_t, nlohmann::json&) {
    if (static_cast<std::size_t>(depth) > limits.max_json_depth)
      throw StopParsing{ImportErrorCategory::TooDeep,
                        "JSON nested deeper than " + std::to_string(limits.max_json_depth) + " levels"};
    if (++values > limits.max_json_values)
      throw StopParsing{ImportErrorCategory::TooLarge,
                        "JSON with more than " + std::to_string(limits.max_json_values) + " values"};
    return true;
  };
  try {
    out = nlohmann::json::parse(text, callback);
  } catch (const StopParsing& s) {
    return flaw(s.category, s.reason);
  } catch (const nlohmann::json::out_of_range& e) {  // a number beyond a double (1e999)
    return flaw(ImportErrorCategory::InvalidValue, std::string("JSON number out of range: ") + e.what());
  } catch (const nlohmann::json::exception& e) {
    return flaw(ImportErrorCategory::Syntax, std::string("not valid JSON: ") + e.what());
  }
  return std::nullopt;
}

namespace detail {

Check expect(const sqlite::Statement& st, int col, int sqlite_type, bool nullable, const ImportLimits& limits) {
  const int type = st.type(col);
  if (type == SQLITE_NULL) {
    if (nullable) return std::nullopt;
    return flaw(ImportErrorCategory::MissingField, "is empty (NULL)");
  }
  // A REAL column holds integers too (SQLite stores 2.0 as 2); an INTEGER column holds only integers.
  const bool ok = type == sqlite_type || (sqlite_type == SQLITE_FLOAT && type == SQLITE_INTEGER);
  if (!ok) {
    const auto name = [](int t) {
      return t == SQLITE_INTEGER ? "an integer" : t == SQLITE_FLOAT ? "a number" : t == SQLITE_TEXT ? "text" : "a BLOB";
    };
    return flaw(ImportErrorCategory::WrongType,
                std::string("holds ") + name(type) + " where " + name(sqlite_type) + " belongs");
  }
  if (type == SQLITE_TEXT && st.size(col) > limits.max_json_bytes)
    return flaw(ImportErrorCategory::TooLarge, "text of " + std::to_string(st.size(col)) + " bytes (limit " +
                                                   std::to_string(limits.max_json_bytes) + ")");
  return std::nullopt;
}

Check in_range(std::int64_t v, std::int64_t min, std::int64_t max) {
  if (v >= min && v <= max) return std::nullopt;
  return flaw(ImportErrorCategory::InvalidValue,
              std::to_string(v) + " is outside " + std::to_string(min) + " .. " + std::to_string(max));
}

Check bounded(double v, Bound bound) {
  if (!std::isfinite(v)) return flaw(ImportErrorCategory::InvalidValue, number_text(v) + " is not a finite number");
  if (bound == Bound::Positive && !(v > 0))
    return flaw(ImportErrorCategory::InvalidValue, number_text(v) + " is not greater than 0");
  if (bound == Bound::NonNegative && v < 0)
    return flaw(ImportErrorCategory::InvalidValue, number_text(v) + " is negative");
  return std::nullopt;
}

Check json_rule(std::string_view text, const ImportLimits& limits, bool allow_empty) {
  if (text.empty() && allow_empty) return std::nullopt;
  nlohmann::json j;
  if (auto f = parse_json(text, limits, j)) return f;
  if (!j.is_object()) return flaw(ImportErrorCategory::WrongType, "is JSON but not an object");
  return std::nullopt;
}

}  // namespace detail
}  // namespace bs::store
