// SPDX-License-Identifier: GPL-3.0-or-later
#include "json_access.h"

#include <cmath>

namespace bs::json_access {
namespace {

ErrorLocation location_of_byte(const std::string& file, std::string_view text, std::size_t byte) {
  // nlohmann reports the 1-based byte position just past the offending character.
  ErrorLocation loc{file, 1, 1, {}};
  const std::size_t end = std::min(byte > 0 ? byte - 1 : 0, text.size());
  for (std::size_t i = 0; i < end; ++i) {
    if (text[i] == '\n') {
      ++loc.line;
      loc.column = 1;
    } else {
      ++loc.column;
    }
  }
  return loc;
}

// nlohmann's messages start with "[json.exception.parse_error.101] parse error at line 1, column 5: ": keep only
// the part after the last ": " that describes the problem, since we print our own location.
std::string short_reason(const std::string& what) {
  const auto pos = what.find("syntax error");
  std::string reason = pos == std::string::npos ? what : what.substr(pos);
  if (reason.find("unexpected end of input") != std::string::npos) reason += " (the file is truncated)";
  return reason;
}

}  // namespace

json parse(std::string_view text, const std::string& file, std::size_t max_depth) {
  bool too_deep = false;
  std::size_t deepest = 0;
  const json::parser_callback_t limit_depth = [&](int depth, json::parse_event_t event, json&) {
    if ((event == json::parse_event_t::object_start || event == json::parse_event_t::array_start) &&
        static_cast<std::size_t>(depth) >= max_depth) {
      too_deep = true;
      deepest = static_cast<std::size_t>(depth) + 1;
      throw std::length_error("too deep");
    }
    return true;
  };
  try {
    return json::parse(text.begin(), text.end(), limit_depth, /*allow_exceptions=*/true,
                       /*ignore_comments=*/false);
  } catch (const std::length_error&) {
    if (!too_deep) throw;
    throw ImportError(ImportErrorCategory::TooDeep, {file, 0, 0, {}},
                      "JSON nesting deeper than " + std::to_string(max_depth) + " levels (reached " +
                          std::to_string(deepest) + ")");
  } catch (const json::parse_error& e) {
    throw ImportError(ImportErrorCategory::Syntax, location_of_byte(file, text, e.byte), short_reason(e.what()));
  } catch (const json::out_of_range& e) {
    // number overflow, e.g. 1e999
    throw ImportError(ImportErrorCategory::InvalidValue, {file, 0, 0, {}},
                      std::string("number out of range: ") + e.what());
  } catch (const json::exception& e) {
    throw ImportError(ImportErrorCategory::Syntax, {file, 0, 0, {}}, e.what());
  }
}

void Reader::fail(ImportErrorCategory category, const std::string& pointer, const std::string& reason) const {
  throw ImportError(category, {file_, 0, 0, pointer.empty() ? std::string("/") : pointer}, reason);
}

const json& Reader::require(const json& object, const std::string& pointer, std::string_view key) const {
  require_object(object, pointer);
  const auto it = object.find(key);
  if (it == object.end() || it->is_null())
    fail(ImportErrorCategory::MissingField, child(pointer, key), "required field is missing");
  return *it;
}

const json* Reader::optional(const json& object, std::string_view key) const {
  if (!object.is_object()) return nullptr;
  const auto it = object.find(key);
  if (it == object.end() || it->is_null()) return nullptr;
  return &*it;
}

const json& Reader::require_object(const json& value, const std::string& pointer) const {
  if (!value.is_object())
    fail(ImportErrorCategory::WrongType, pointer, std::string("expected an object, found ") + value.type_name());
  return value;
}

const json& Reader::require_array(const json& value, const std::string& pointer) const {
  if (!value.is_array())
    fail(ImportErrorCategory::WrongType, pointer, std::string("expected an array, found ") + value.type_name());
  return value;
}

std::string Reader::require_string(const json& object, const std::string& pointer, std::string_view key) const {
  const json& v = require(object, pointer, key);
  if (!v.is_string())
    fail(ImportErrorCategory::WrongType, child(pointer, key), std::string("expected a string, found ") + v.type_name());
  return v.get<std::string>();
}

std::string Reader::optional_string(const json& object, const std::string& pointer, std::string_view key,
                                    std::string fallback) const {
  const json* v = optional(object, key);
  if (!v) return fallback;
  if (!v->is_string())
    fail(ImportErrorCategory::WrongType, child(pointer, key), std::string("expected a string, found ") + v->type_name());
  return v->get<std::string>();
}

double Reader::number(const json& value, const std::string& pointer) const {
  if (!value.is_number())
    fail(ImportErrorCategory::WrongType, pointer, std::string("expected a number, found ") + value.type_name());
  const double d = value.get<double>();
  if (!std::isfinite(d)) fail(ImportErrorCategory::InvalidValue, pointer, "number is not finite");
  return d;
}

double Reader::require_number(const json& object, const std::string& pointer, std::string_view key) const {
  return number(require(object, pointer, key), child(pointer, key));
}

std::optional<double> Reader::optional_number(const json& object, const std::string& pointer,
                                              std::string_view key) const {
  const json* v = optional(object, key);
  if (!v) return std::nullopt;
  return number(*v, child(pointer, key));
}

std::int64_t Reader::require_integer(const json& object, const std::string& pointer, std::string_view key,
                                     std::int64_t min, std::int64_t max) const {
  const json& v = require(object, pointer, key);
  const std::string at = child(pointer, key);
  if (!v.is_number_integer()) {
    if (v.is_number_float()) {
      const double d = v.get<double>();
      if (std::isfinite(d) && d == std::floor(d) && d >= static_cast<double>(min) && d <= static_cast<double>(max))
        return static_cast<std::int64_t>(d);
    }
    fail(ImportErrorCategory::WrongType, at, std::string("expected an integer, found ") + v.type_name());
  }
  std::int64_t i = 0;
  if (v.is_number_unsigned()) {
    const auto u = v.get<std::uint64_t>();
    if (u > static_cast<std::uint64_t>(max))
      fail(ImportErrorCategory::InvalidValue, at, "must be between " + std::to_string(min) + " and " + std::to_string(max));
    i = static_cast<std::int64_t>(u);
  } else {
    i = v.get<std::int64_t>();
  }
  if (i < min || i > max)
    fail(ImportErrorCategory::InvalidValue, at,
         std::to_string(i) + " is out of range (" + std::to_string(min) + " to " + std::to_string(max) + ")");
  return i;
}

}  // namespace bs::json_access
