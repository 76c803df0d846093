// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/peaks/device_table.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "util/resource_table.h"
#include "util/resources.h"

namespace bs {
namespace {

using nlohmann::json;

[[noreturn]] void fail(const std::string& origin, const std::string& where, const std::string& why) {
  resource_table_fail(origin, where, why);
}

std::optional<double> optional_positive(const json& e, const char* key, const std::string& origin,
                                        const std::string& where) {
  const auto it = e.find(key);
  if (it == e.end() || it->is_null()) return std::nullopt;
  if (!it->is_number() || !(it->get<double>() > 0) || !std::isfinite(it->get<double>()))
    fail(origin, where + "." + key, "not a positive number");
  return it->get<double>();
}

constexpr const char* kVerifiableFields[] = {"units",           "flop_per_unit_per_cycle",      "clock_ghz",
                                             "fp32_peak_flops", "memory_bandwidth_bytes_per_s", "tdp_w"};

std::vector<PeakTerm> peak_terms(const json& e, const std::string& origin, const std::string& where) {
  std::vector<PeakTerm> terms;
  const auto it = e.find("peak_terms");
  if (it == e.end()) return terms;
  if (!it->is_array()) fail(origin, where + ".peak_terms", "not an array");
  for (std::size_t i = 0; i < it->size(); ++i) {
    const json& t = (*it)[i];
    const std::string at = where + ".peak_terms[" + std::to_string(i) + "]";
    if (!t.is_object()) fail(origin, at, "not an object");
    PeakTerm term;
    const auto need = [&](const char* key) {
      const auto v = optional_positive(t, key, origin, at);
      if (!v) fail(origin, at + "." + key, "missing");
      return *v;
    };
    term.units = need("units");
    term.unit = resource_table_string(t, "unit", origin, at);
    term.flop_per_unit_per_cycle = need("flop_per_unit_per_cycle");
    term.clock_ghz = need("clock_ghz");
    terms.push_back(std::move(term));
  }
  return terms;
}

bool is_noise_word(const std::string& w) {
  static const char* const kNoise[] = {"r",       "tm",     "intel", "nvidia",   "amd",
                                       "geforce", "radeon", "core",  "graphics", "corporation"};
  return std::any_of(std::begin(kNoise), std::end(kNoise), [&](const char* n) { return w == n; });
}

// Length in tokens of the longest name of `spec` found as consecutive tokens in `hay`; 0 when none is.
std::size_t best_match_length(const DeviceSpec& spec, const std::vector<std::string>& hay) {
  std::size_t best = 0;
  auto try_name = [&](const std::string& name) {
    const std::vector<std::string> needle = device_name_tokens(name);
    if (needle.empty() || needle.size() > hay.size() || needle.size() <= best) return;
    if (std::search(hay.begin(), hay.end(), needle.begin(), needle.end()) != hay.end()) best = needle.size();
  };
  try_name(spec.name);
  for (const std::string& a : spec.aliases) try_name(a);
  return best;
}

// Entries tied for the longest match of `text` (kind-filtered), and that length.
std::vector<const DeviceSpec*> best_matches(const DeviceTable& table, std::string_view text, DeviceKind kind) {
  const std::vector<std::string> hay = device_name_tokens(text);
  std::vector<const DeviceSpec*> best;
  std::size_t best_len = 0;
  if (hay.empty()) return best;
  for (const DeviceSpec& spec : table.devices) {
    if (kind != DeviceKind::Other && spec.kind != kind) continue;
    const std::size_t len = best_match_length(spec, hay);
    if (len == 0 || len < best_len) continue;
    if (len > best_len) best.clear();
    best_len = len;
    best.push_back(&spec);
  }
  return best;
}

}  // namespace

DeviceTable parse_device_table(std::string_view json_text, const std::string& origin) {
  DeviceTable table;
  table.path = origin;
  for_each_resource_entry(
      json_text, origin, "benchscope-device-specs", "devices", [&](const json& e, const std::string& where) {
        DeviceSpec s;
        s.id = resource_table_string(e, "id", origin, where);
        s.name = resource_table_string(e, "name", origin, where);
        const std::string kind = resource_table_string(e, "kind", origin, where);
        if (kind != "cpu" && kind != "gpu") fail(origin, where + ".kind", "must be \"cpu\" or \"gpu\"");
        s.kind = device_kind_from_string(kind);
        if (const auto a = e.find("aliases"); a != e.end()) {
          if (!a->is_array()) fail(origin, where + ".aliases", "not an array");
          for (const json& alias : *a) {
            if (!alias.is_string() || alias.get<std::string>().empty())
              fail(origin, where + ".aliases", "an alias is not a non-empty string");
            s.aliases.push_back(alias.get<std::string>());
          }
        }
        const auto peak = optional_positive(e, "fp32_peak_flops", origin, where);
        if (!peak) fail(origin, where + ".fp32_peak_flops", "missing");
        s.fp32_peak_flops = *peak;
        s.derivation = resource_table_string(e, "derivation", origin, where);
        s.memory_bandwidth_bytes_per_s = optional_positive(e, "memory_bandwidth_bytes_per_s", origin, where);
        s.tdp_w = optional_positive(e, "tdp_w", origin, where);
        const auto src = e.find("source");
        if (src == e.end() || !src->is_object())
          fail(origin, where + ".source", "missing: every entry names its source");
        s.source_title = resource_table_string(*src, "title", origin, where + ".source");
        s.source_url = src->value("url", "");
        s.source_more_urls = resource_table_strings(*src, "more", origin, where + ".source");
        s.note = e.value("note", "");
        s.peak_terms = peak_terms(e, origin, where);
        s.peak_exempt = e.value("peak_exempt", "");
        s.unverified = resource_table_strings(e, "unverified", origin, where);
        for (const std::string& field : s.unverified)
          if (std::none_of(std::begin(kVerifiableFields), std::end(kVerifiableFields),
                           [&](const char* f) { return field == f; }))
            fail(origin, where + ".unverified", "unknown field " + field);
        for (const DeviceSpec& other : table.devices)
          if (other.id == s.id) fail(origin, where + ".id", "duplicate id " + s.id);
        table.devices.push_back(std::move(s));
      });
  return table;
}

bool DeviceSpec::is_unverified(std::string_view field) const {
  return std::find(unverified.begin(), unverified.end(), field) != unverified.end();
}

bool DeviceSpec::peak_unverified() const {
  return is_unverified("fp32_peak_flops") || is_unverified("units") || is_unverified("flop_per_unit_per_cycle") ||
         is_unverified("clock_ghz");
}

double DeviceSpec::peak_from_terms() const {
  double sum = 0;
  for (const PeakTerm& t : peak_terms) sum += t.units * t.flop_per_unit_per_cycle * t.clock_ghz * 1e9;
  return sum;
}

DeviceTable load_device_table(const std::filesystem::path& path) {
  return parse_device_table(read_resource_file(path), path.string());
}

const BundledDeviceTable& bundled_device_table() {
  static const BundledDeviceTable bundled =
      load_bundled(&BundledDeviceTable::table, [] { return load_device_table(find_resource("devices/devices.json")); });
  return bundled;
}

std::vector<std::string> device_name_tokens(std::string_view name) {
  std::vector<std::string> tokens;
  std::string cur;
  auto flush = [&] {
    if (!cur.empty() && !is_noise_word(cur)) tokens.push_back(cur);
    cur.clear();
  };
  for (const char raw : name) {
    const auto c = static_cast<unsigned char>(raw);
    if (!std::isalnum(c) || c >= 0x80) {
      flush();  // punctuation, spaces and the bytes of UTF-8 signs such as (R) and TM
      continue;
    }
    if (!cur.empty() && (std::isdigit(c) != 0) != (std::isdigit(static_cast<unsigned char>(cur.back())) != 0)) flush();
    cur.push_back(static_cast<char>(std::tolower(c)));
  }
  flush();
  return tokens;
}

const DeviceSpec* match_device(const DeviceTable& table, std::string_view device, DeviceKind kind,
                               std::string_view platform) {
  for (const std::string_view text : {device, platform}) {
    const std::vector<const DeviceSpec*> best = best_matches(table, text, kind);
    if (best.size() == 1) return best.front();
    if (best.size() > 1) return nullptr;  // ambiguous: claiming one would be a guess
  }
  return nullptr;
}

std::optional<double> platform_tdp_w(const DeviceTable& table, std::string_view platform) {
  std::optional<double> tdp;
  for (const DeviceSpec* s : best_matches(table, platform, DeviceKind::Other))
    if (s->tdp_w && (!tdp || *s->tdp_w > *tdp)) tdp = s->tdp_w;
  return tdp;
}

}  // namespace bs
