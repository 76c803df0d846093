// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Reading a stored JSON record field by field (a headroom measurement, a sustained run), every flaw thrown as the
// record's own error type and naming where it is: "sustain.clocks: is not an array". The readers share the words
// of these messages; what a field may hold (ranges, sizes) stays each reader's.
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace bs {

template <class Error>
struct JsonFields {
  using json = nlohmann::json;

  [[noreturn]] static void fail(const std::string& where, const std::string& why) { throw Error(where + ": " + why); }

  static const json& member(const json& obj, const char* key, const std::string& where) {
    const auto it = obj.find(key);
    if (it == obj.end()) fail(where, "'" + std::string(key) + "' is missing");
    return *it;
  }

  static std::string text(const json& obj, const char* key, const std::string& where) {
    const json& v = member(obj, key, where);
    if (!v.is_string()) fail(where + "." + key, "is not a string");
    return v.get<std::string>();
  }

  // A word of an enumeration, read back by `parse` (its *_from_id); an unknown word fails as
  // "unknown <what> '<word>'" followed by `known` (e.g. " (known: wakeup, loop, message)").
  template <class E>
  static E word(const json& obj, const char* key, const std::string& where, std::optional<E> (*parse)(std::string_view),
                const std::string& what, const std::string& known = {}) {
    const std::string w = text(obj, key, where);
    const std::optional<E> v = parse(w);
    if (!v) fail(where + "." + key, "unknown " + what + " '" + w + "'" + known);
    return *v;
  }

  // An array, of any length.
  static const json& array(const json& obj, const char* key, const std::string& where) {
    const json& v = member(obj, key, where);
    if (!v.is_array()) fail(where + "." + key, "is not an array");
    return v;
  }
};

}  // namespace bs
