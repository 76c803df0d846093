// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/raw_sidecar.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <nlohmann/json.hpp>

namespace bs {
namespace {

using Kind = RawSidecarError::Kind;

[[noreturn]] void fail(Kind kind, const std::string& pointer, const std::string& reason) {
  throw RawSidecarError(kind, pointer, reason);
}

const nlohmann::json* member(const nlohmann::json& doc, const char* key) {
  const auto it = doc.find(key);
  return it == doc.end() || it->is_null() ? nullptr : &*it;
}

// An integer in [lo, hi]; 4e2 written with an exponent counts, 2.5 does not.
int integer(const nlohmann::json& doc, const char* key, long long lo, long long hi) {
  const std::string at = std::string("/") + key;
  const nlohmann::json* v = member(doc, key);
  if (!v) fail(Kind::Missing, at, "missing");
  double d = 0;
  if (v->is_number_integer()) {
    if (v->is_number_unsigned() && v->get<unsigned long long>() > static_cast<unsigned long long>(hi))
      fail(Kind::Invalid, at,
           v->dump() + " is out of range (allowed: " + std::to_string(lo) + " to " + std::to_string(hi) + ")");
    d = static_cast<double>(v->get<long long>());
  } else if (v->is_number_float() && std::isfinite(v->get<double>()) &&
             v->get<double>() == std::floor(v->get<double>())) {
    d = v->get<double>();
  } else {
    fail(Kind::WrongType, at,
         std::string("expected an integer, found ") + (v->is_number() ? v->dump() : v->type_name()));
  }
  if (d < static_cast<double>(lo) || d > static_cast<double>(hi))
    fail(Kind::Invalid, at,
         v->dump() + " is out of range (allowed: " + std::to_string(lo) + " to " + std::to_string(hi) + ")");
  return static_cast<int>(d);
}

std::optional<std::string> text(const nlohmann::json& doc, const char* key) {
  const nlohmann::json* v = member(doc, key);
  if (!v) return std::nullopt;
  if (!v->is_string())
    fail(Kind::WrongType, std::string("/") + key, std::string("expected a string, found ") + v->type_name());
  return v->get<std::string>();
}

}  // namespace

RawSidecar raw_sidecar_from_json(const nlohmann::json& doc) {
  if (!doc.is_object()) fail(Kind::WrongType, "", std::string("expected a JSON object, found ") + doc.type_name());
  if (const auto f = text(doc, "format"); f && *f != "benchscope-raw")
    fail(Kind::Unsupported, "/format", "sidecar format must be \"benchscope-raw\"");
  if (member(doc, "version") && integer(doc, "version", 1, 1000) > 1)
    fail(Kind::Unsupported, "/version", "sidecar version is newer than 1, which this build reads");
  RawSidecar s;
  s.width = integer(doc, "width", 1, 1 << 30);
  s.height = integer(doc, "height", 1, 1 << 30);
  if (auto p = text(doc, "pattern")) {
    std::string up = *p;
    std::transform(up.begin(), up.end(), up.begin(),
                   [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    if (up != "BGGR" && up != "RGGB" && up != "GRBG" && up != "GBRG")
      fail(Kind::Invalid, "/pattern",
           "Bayer pattern \"" + p->substr(0, 40) + "\" is not one of BGGR, RGGB, GRBG, GBRG");
    s.pattern = up;
  }
  s.bit_depth = integer(doc, "bit_depth", 1, 16);
  const auto endian = text(doc, "endianness");
  if (!endian && s.bit_depth > 8)
    fail(Kind::Missing, "/endianness", "a sidecar for samples above 8 bits must say \"little\" or \"big\"");
  if (endian && *endian != "little" && *endian != "big")
    fail(Kind::Invalid, "/endianness", "must be \"little\" or \"big\"");
  s.big_endian = endian && *endian == "big";
  if (const nlohmann::json* syn = member(doc, "synthetic")) {
    if (!syn->is_boolean()) fail(Kind::WrongType, "/synthetic", "must be true or false");
    s.synthetic = syn->get<bool>();
  }
  if (const nlohmann::json* lens = member(doc, "lens")) {
    if (!lens->is_object())
      fail(Kind::WrongType, "/lens", std::string("expected an object, found ") + lens->type_name());
    s.lens_json = lens->dump();
  }
  s.truth = text(doc, "truth").value_or("");
  return s;
}

nlohmann::json raw_sidecar_to_json(const RawSidecar& s) {
  nlohmann::json j = {{"format", "benchscope-raw"}, {"version", 1}, {"width", s.width}, {"height", s.height}};
  if (s.pattern) j["pattern"] = *s.pattern;
  j["bit_depth"] = s.bit_depth;
  j["endianness"] = s.big_endian ? "big" : "little";
  j["synthetic"] = s.synthetic;
  if (!s.truth.empty()) j["truth"] = s.truth;
  if (!s.lens_json.empty()) j["lens"] = nlohmann::json::parse(s.lens_json);
  return j;
}

std::string raw_sidecar_path(const std::string& raw_path) {
  return std::filesystem::path(raw_path).replace_extension(".json").string();
}

std::optional<std::string> find_raw_sidecar(const std::string& raw_path) {
  std::error_code ec;
  for (const std::string& candidate : {raw_sidecar_path(raw_path), raw_path + ".json"})
    if (std::filesystem::is_regular_file(candidate, ec)) return candidate;
  return std::nullopt;
}

}  // namespace bs
