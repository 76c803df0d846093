// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/json_access.h"

#include <cmath>
#include <cstring>
#include <functional>
#include <unordered_map>
#include <vector>

namespace bs::json_access {
namespace {

// Thrown from the parser callback to stop building the tree at once. A duplicate key names the object that holds
// it (`pointer`) and the key, so the error can point at the key's second occurrence.
struct StopParsing {
  StopParsing(ImportErrorCategory c, std::string why) : category(c), reason(std::move(why)) {}
  StopParsing(std::string why, std::string object, std::string key)
      : category(ImportErrorCategory::InvalidValue),
        reason(std::move(why)),
        pointer(std::move(object)),
        duplicate_key(std::move(key)),
        duplicate(true) {}
  ImportErrorCategory category;
  std::string reason;
  std::string pointer;
  std::string duplicate_key;
  bool duplicate = false;
};

bool is_json_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

// Index just past the string whose opening quote is at `i` (or text.size() when unterminated).
std::size_t skip_string(std::string_view text, std::size_t i) {
  for (++i; i < text.size(); ++i) {
    if (text[i] == '\\') {
      ++i;
    } else if (text[i] == '"') {
      return i + 1;
    }
  }
  return text.size();
}

// Offset of the bracket that first nests deeper than `max_depth`, for the TooDeep message.
std::size_t offset_of_depth(std::string_view text, std::size_t max_depth) {
  std::size_t depth = 0;
  for (std::size_t i = 0; i < text.size();) {
    const char c = text[i];
    if (c == '"') {
      i = skip_string(text, i);
      continue;
    }
    if (c == '{' || c == '[') {
      if (++depth > max_depth) return i;
    } else if ((c == '}' || c == ']') && depth > 0) {
      --depth;
    }
    ++i;
  }
  return text.size();
}

bool is_number_char(char c) {
  return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.' || c == 'e' || c == 'E';
}

// Where the number literal `token` stands outside strings; nlohmann reports overflow without a position.
std::size_t offset_of_number(std::string_view text, std::string_view token) {
  for (std::size_t i = 0; i < text.size();) {
    if (text[i] == '"') {
      i = skip_string(text, i);
      continue;
    }
    if (text.substr(i, token.size()) == token && (i == 0 || !is_number_char(text[i - 1])) &&
        (i + token.size() >= text.size() || !is_number_char(text[i + token.size()])))
      return i;
    ++i;
  }
  return text.size();
}

// nlohmann's what() is "[json.exception.parse_error.101] parse error at line 1, column 5: syntax error ...":
// keep the description only, since our own location comes first.
std::string describe_syntax_error(const std::string& what) {
  const auto pos = what.find("syntax error");
  std::string reason = pos == std::string::npos ? what : what.substr(pos);
  if (reason.find("unexpected end of input") != std::string::npos)
    return "unexpected end of file: the JSON is truncated (" + reason + ")";
  if (reason.find("last read: 'N") != std::string::npos || reason.find("last read: 'I") != std::string::npos ||
      reason.find("last read: '-I") != std::string::npos || reason.find("last read: '-N") != std::string::npos)
    reason += " (NaN and Infinity are not JSON numbers)";
  return reason;
}

std::string unescape_pointer_token(std::string_view token) {
  std::string out;
  for (std::size_t i = 0; i < token.size(); ++i) {
    if (token[i] == '~' && i + 1 < token.size() && (token[i + 1] == '0' || token[i + 1] == '1')) {
      out += token[i + 1] == '0' ? '~' : '/';
      ++i;
    } else {
      out += token[i];
    }
  }
  return out;
}

// A forward-only reader over a document that nlohmann already accepted, used to map pointers to offsets.
class Scanner {
 public:
  explicit Scanner(std::string_view text, std::size_t start = 0) : t_(text), i_(start) {}
  std::size_t pos() const { return i_; }
  bool at(char c) const { return i_ < t_.size() && t_[i_] == c; }
  void advance() { ++i_; }
  void skip_space() {
    while (i_ < t_.size() && is_json_space(t_[i_])) ++i_;
  }
  // Reads a string at the cursor; simple escapes are decoded, \u escapes kept as written (keys that need them
  // then fail to match and the location falls back to the enclosing value, which is still correct, only coarser).
  std::string read_string() {
    std::string out;
    for (++i_; i_ < t_.size() && t_[i_] != '"'; ++i_) {
      if (t_[i_] == '\\' && i_ + 1 < t_.size()) {
        const char c = t_[++i_];
        if (c == '"' || c == '\\' || c == '/') {
          out += c;
        } else {
          out += '\\';
          out += c;
        }
      } else {
        out += t_[i_];
      }
    }
    if (i_ < t_.size()) ++i_;
    return out;
  }
  void skip_value() {
    skip_space();
    if (at('"')) {
      i_ = skip_string(t_, i_);
      return;
    }
    if (at('{') || at('[')) {
      std::size_t depth = 0;
      while (i_ < t_.size()) {
        const char c = t_[i_];
        if (c == '"') {
          i_ = skip_string(t_, i_);
          continue;
        }
        ++i_;
        if (c == '{' || c == '[') ++depth;
        if ((c == '}' || c == ']') && --depth == 0) return;
      }
      return;
    }
    while (i_ < t_.size() && t_[i_] != ',' && t_[i_] != '}' && t_[i_] != ']' && !is_json_space(t_[i_])) ++i_;
  }

 private:
  std::string_view t_;
  std::size_t i_ = 0;
};

bool enter_member(Scanner& s, const std::string& key) {
  s.advance();  // '{'
  for (;;) {
    s.skip_space();
    if (!s.at('"')) return false;
    const std::string name = s.read_string();
    s.skip_space();
    if (!s.at(':')) return false;
    s.advance();
    s.skip_space();
    if (name == key) return true;
    s.skip_value();
    s.skip_space();
    if (!s.at(',')) return false;
    s.advance();
  }
}

// Offset of the `occurrence`-th (0-based) member named `key` of the object starting at `object_offset`; the
// object's offset when there are fewer.
std::size_t offset_of_member(std::string_view text, std::size_t object_offset, const std::string& key, int occurrence) {
  Scanner s(text, object_offset);
  if (!s.at('{')) return object_offset;
  s.advance();
  for (;;) {
    s.skip_space();
    if (!s.at('"')) return object_offset;
    const std::size_t at = s.pos();
    const std::string name = s.read_string();
    if (name == key && occurrence-- == 0) return at;
    s.skip_space();
    if (!s.at(':')) return object_offset;
    s.advance();
    s.skip_value();
    s.skip_space();
    if (!s.at(',')) return object_offset;
    s.advance();
  }
}

// Tracks the keys of every open object while nlohmann builds the tree, because nlohmann keeps the last of two
// equal keys silently and the first value would be lost without a word. Two equal keys with the same scalar value
// are harmless and accepted; different values, or an object/array twice, stop the parse.
class DuplicateKeyGuard {
 public:
  void open(bool is_object) {
    Frame f;
    f.object = is_object;
    if (!stack_.empty()) {
      const Frame& parent = stack_.back();
      f.pointer = parent.object ? child(parent.pointer, parent.key) : child(parent.pointer, parent.index);
    }
    stack_.push_back(std::move(f));
  }
  void close() {
    stack_.pop_back();
    member_done(kContainer);
  }
  void key(const std::string& key) {
    if (!stack_.empty()) stack_.back().key = key;
  }
  // A scalar member or element read: `print` is its fingerprint (print_of), equal for equal values.
  void value(std::uint64_t print) { member_done(print); }

  static std::uint64_t print_of(json::value_t type, std::uint64_t payload) {
    const std::uint64_t h = (static_cast<std::uint64_t>(type) * 0x9E3779B97F4A7C15ull) ^ payload;
    return h == kContainer ? h - 1 : h;
  }
  static std::uint64_t print_of(double d) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &d, sizeof bits);
    return print_of(json::value_t::number_float, bits);
  }

 private:
  static constexpr std::uint64_t kContainer = ~std::uint64_t{0};
  struct Frame {
    bool object = false;
    std::string pointer;
    std::string key;        // the key whose value is being read (objects)
    std::size_t index = 0;  // the element being read (arrays)
    std::unordered_map<std::string, std::uint64_t> seen;
  };

  void member_done(std::uint64_t print) {
    if (stack_.empty()) return;
    Frame& f = stack_.back();
    if (!f.object) {
      ++f.index;
      return;
    }
    const auto [it, inserted] = f.seen.emplace(f.key, print);
    if (inserted || (print == it->second && print != kContainer)) return;
    throw StopParsing{"key \"" + f.key + "\" appears twice in this object with " +
                          (print == kContainer || it->second == kContainer ? std::string("an object or array")
                                                                           : std::string("different values")) +
                          "; JSON does not say which one counts (a parser silently keeps one), so the file is refused",
                      f.pointer, f.key};
  }

  std::vector<Frame> stack_;
};

// The document built as nlohmann's own DOM parser builds it, with BenchScope's checks on every event on the way:
// nesting depth (checked before a container's children exist), the number of values, duplicate keys and
// cancellation. nlohmann's callback parser offers the same events, but after every object it closes it walks the
// enclosing container again (to drop values a callback discarded): quadratic in an array of objects. The paper's
// run JSON took 0.9 s under GCC and 40 s under the sanitizers in test_platform_comparison for that walk alone.
class GuardedDomBuilder {
 public:
  using number_integer_t = json::number_integer_t;
  using number_unsigned_t = json::number_unsigned_t;
  using number_float_t = json::number_float_t;
  using string_t = json::string_t;
  using binary_t = json::binary_t;

  GuardedDomBuilder(json& result, const ImportLimits& limits, const CancelToken* cancel)
      : dom_(result, /*allow_exceptions=*/true), limits_(limits), cancel_(cancel) {}

  bool null() {
    scalar(DuplicateKeyGuard::print_of(json::value_t::null, 0));
    return dom_.null();
  }
  bool boolean(bool b) {
    scalar(DuplicateKeyGuard::print_of(json::value_t::boolean, b ? 1u : 2u));
    return dom_.boolean(b);
  }
  bool number_integer(number_integer_t v) {
    scalar(DuplicateKeyGuard::print_of(json::value_t::number_integer, static_cast<std::uint64_t>(v)));
    return dom_.number_integer(v);
  }
  bool number_unsigned(number_unsigned_t v) {
    scalar(DuplicateKeyGuard::print_of(json::value_t::number_unsigned, v));
    return dom_.number_unsigned(v);
  }
  bool number_float(number_float_t v, const string_t& text) {
    scalar(DuplicateKeyGuard::print_of(v));
    return dom_.number_float(v, text);
  }
  bool string(string_t& v) {
    scalar(DuplicateKeyGuard::print_of(json::value_t::string, std::hash<std::string>{}(v)));
    return dom_.string(v);
  }
  bool binary(binary_t& v) {  // never from JSON text; counted like any value
    count();
    return dom_.binary(v);
  }
  bool start_object(std::size_t elements) {
    open(true);
    return dom_.start_object(elements);
  }
  bool key(string_t& k) {
    duplicates_.key(k);
    count();
    return dom_.key(k);
  }
  bool end_object() {
    close();
    return dom_.end_object();
  }
  bool start_array(std::size_t elements) {
    open(false);
    return dom_.start_array(elements);
  }
  bool end_array() {
    close();
    return dom_.end_array();
  }
  template <class Exception>
  bool parse_error(std::size_t position, const std::string& last_token, const Exception& ex) {
    return dom_.parse_error(position, last_token, ex);  // throws `ex`: the DOM parser allows exceptions
  }

 private:
  void count() {
    if (++values_ > limits_.max_json_values)
      throw StopParsing{ImportErrorCategory::TooLarge, "more than " + std::to_string(limits_.max_json_values) +
                                                           " JSON values in one document (the documented limit)"};
    if (cancel_ && (values_ & 0xFFFF) == 0) cancel_->throw_if_cancelled();
  }
  void scalar(std::uint64_t print) {
    duplicates_.value(print);
    count();
  }
  // `depth_` is the nesting of the container being opened (0: the document's own), checked before it exists.
  void open(bool is_object) {
    if (depth_ >= limits_.max_json_depth)
      throw StopParsing{ImportErrorCategory::TooDeep,
                        "JSON nesting deeper than the limit of " + std::to_string(limits_.max_json_depth) + " levels"};
    ++depth_;
    count();
    duplicates_.open(is_object);
  }
  void close() {
    --depth_;
    duplicates_.close();
  }

  nlohmann::detail::json_sax_dom_parser<json> dom_;
  const ImportLimits& limits_;
  const CancelToken* cancel_;
  DuplicateKeyGuard duplicates_;
  std::size_t values_ = 0;
  std::size_t depth_ = 0;
};

bool enter_element(Scanner& s, const std::string& token) {
  if (token.empty() || token.find_first_not_of("0123456789") != std::string::npos) return false;
  const std::size_t index = std::stoull(token);
  s.advance();  // '['
  for (std::size_t k = 0;; ++k) {
    s.skip_space();
    if (s.at(']')) return false;
    if (k == index) return true;
    s.skip_value();
    s.skip_space();
    if (!s.at(',')) return false;
    s.advance();
  }
}

}  // namespace

ErrorLocation location_of_offset(const std::string& file, std::string_view text, std::size_t offset) {
  ErrorLocation loc{file, 1, 1, {}};
  const std::size_t end = std::min(offset, text.size());
  for (std::size_t i = 0; i < end; ++i) {
    const auto byte = static_cast<unsigned char>(text[i]);
    if (byte == '\n') {
      ++loc.line;
      loc.column = 1;
    } else if ((byte & 0xC0) != 0x80) {  // UTF-8 continuation bytes belong to the previous character
      ++loc.column;
    }
  }
  return loc;
}

std::size_t offset_of_pointer(std::string_view text, std::string_view pointer) {
  Scanner s(text);
  s.skip_space();
  std::size_t found = s.pos();
  if (pointer.empty() || pointer == "/") return found;
  std::size_t start = pointer.front() == '/' ? 1 : 0;
  while (start <= pointer.size()) {
    const std::size_t slash = std::min(pointer.find('/', start), pointer.size());
    const std::string token = unescape_pointer_token(pointer.substr(start, slash - start));
    start = slash + 1;
    const bool entered = s.at('{') ? enter_member(s, token) : s.at('[') ? enter_element(s, token) : false;
    if (!entered) return found;
    found = s.pos();
  }
  return found;
}

json parse(std::string_view text, const std::string& file, const ImportLimits& limits, const CancelToken* cancel) {
  try {
    json result;
    GuardedDomBuilder builder(result, limits, cancel);
    json::sax_parse(text.begin(), text.end(), &builder, json::input_format_t::json, /*strict=*/true,
                    /*ignore_comments=*/false);
    return result;
  } catch (const StopParsing& stop) {
    if (stop.duplicate) {
      const std::size_t object = offset_of_pointer(text, stop.pointer);
      ErrorLocation loc = location_of_offset(file, text, offset_of_member(text, object, stop.duplicate_key, 1));
      loc.field = child(stop.pointer, stop.duplicate_key);
      throw ImportError(stop.category, loc, stop.reason);
    }
    const std::size_t at =
        stop.category == ImportErrorCategory::TooDeep ? offset_of_depth(text, limits.max_json_depth) : text.size();
    ErrorLocation loc = location_of_offset(file, text, at);
    if (stop.category == ImportErrorCategory::TooLarge) loc.line = loc.column = 0;
    throw ImportError(stop.category, loc, stop.reason);
  } catch (const json::parse_error& e) {
    // e.byte is 1-based and points just past the character that stopped the parser.
    throw ImportError(ImportErrorCategory::Syntax, location_of_offset(file, text, e.byte > 0 ? e.byte - 1 : 0),
                      describe_syntax_error(e.what()));
  } catch (const json::out_of_range& e) {
    // 406: "number overflow parsing '1e999'"; find the literal to say where it is.
    const std::string what = e.what();
    const auto open = what.find('\'');
    const auto close = what.rfind('\'');
    std::string token;
    if (open != std::string::npos && close > open) token = what.substr(open + 1, close - open - 1);
    ErrorLocation loc{file, 0, 0, {}};
    if (!token.empty()) {
      const std::size_t at = offset_of_number(text, token);
      if (at < text.size()) loc = location_of_offset(file, text, at);
    }
    throw ImportError(ImportErrorCategory::InvalidValue, loc,
                      "number out of range: " + (token.empty() ? what : token) + " does not fit a double");
  } catch (const json::exception& e) {
    throw ImportError(ImportErrorCategory::Syntax, {file, 0, 0, {}}, e.what());
  }
}

std::string child(const std::string& pointer, std::string_view key) {
  std::string out = pointer;
  out += '/';
  for (char c : key) {
    if (c == '~') {
      out += "~0";
    } else if (c == '/') {
      out += "~1";
    } else {
      out += c;
    }
  }
  return out;
}

ErrorLocation Reader::locate(const std::string& pointer) const {
  ErrorLocation loc{file_, 0, 0, {}};
  if (!text_.empty()) loc = location_of_offset(file_, text_, offset_of_pointer(text_, pointer));
  loc.field = pointer.empty() ? std::string("/") : pointer;
  return loc;
}

void Reader::fail(ImportErrorCategory category, const std::string& pointer, const std::string& reason) const {
  throw ImportError(category, locate(pointer), reason);
}

std::string Reader::where(const std::string& pointer) const {
  const ErrorLocation loc = locate(pointer);
  std::string out = file_;
  if (loc.line > 0) out += ':' + std::to_string(loc.line) + ':' + std::to_string(loc.column);
  return out + ": " + loc.field;
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
    fail(ImportErrorCategory::WrongType, child(pointer, key),
         std::string("expected a string, found ") + v->type_name());
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

std::int64_t Reader::integer(const json& v, const std::string& at, std::int64_t min, std::int64_t max) const {
  const std::string range = " (allowed: " + std::to_string(min) + " to " + std::to_string(max) + ")";
  if (v.is_number_float()) {
    // 4e4 is an integer written in exponent form; 2.5 is not.
    const double d = v.get<double>();
    if (!std::isfinite(d) || d != std::floor(d))
      fail(ImportErrorCategory::WrongType, at, "expected an integer, found " + v.dump());
    if (d < static_cast<double>(min) || d > static_cast<double>(max))
      fail(ImportErrorCategory::InvalidValue, at, v.dump() + " is out of range" + range);
    return static_cast<std::int64_t>(d);
  }
  if (!v.is_number_integer())
    fail(ImportErrorCategory::WrongType, at, std::string("expected an integer, found ") + v.type_name());
  if (v.is_number_unsigned() && v.get<std::uint64_t>() > static_cast<std::uint64_t>(max))
    fail(ImportErrorCategory::InvalidValue, at, v.dump() + " is out of range" + range);
  const std::int64_t i = v.get<std::int64_t>();
  if (i < min || i > max) fail(ImportErrorCategory::InvalidValue, at, std::to_string(i) + " is out of range" + range);
  return i;
}

std::int64_t Reader::require_integer(const json& object, const std::string& pointer, std::string_view key,
                                     std::int64_t min, std::int64_t max) const {
  return integer(require(object, pointer, key), child(pointer, key), min, max);
}

}  // namespace bs::json_access
