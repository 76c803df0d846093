// SPDX-License-Identifier: GPL-3.0-or-later
#include "mlperf/loadgen_summary.h"

#include <cctype>
#include <charconv>
#include <cmath>

#include "util/text.h"

namespace bs {
namespace {

[[noreturn]] void fail(ImportErrorCategory c, const std::string& file, std::size_t line, const std::string& field,
                       const std::string& why) {
  throw ImportError(c, {file, line, 0, field}, why);
}

// A LoadGen number: decimal, optionally with a fraction or exponent ("667.53", "1637569", "1.5e+06").
std::optional<double> number(std::string_view text) {
  text = trim(text);
  if (text.empty()) return std::nullopt;
  double v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

bool yes_no(std::string_view v) { return trim(v) == "Yes"; }

// Lines LoadGen writes as text even though they have a colon: banners, the early-stopping explanation.
bool numeric_key(std::string_view key) {
  return key.find("latency") != std::string_view::npos || key.find("percentile") != std::string_view::npos ||
         key.find("QPS") != std::string_view::npos || key.find("per second") != std::string_view::npos ||
         key.find("per query") != std::string_view::npos || key == "samples_per_query" || key == "target_qps" ||
         key.find("count") != std::string_view::npos;
}

}  // namespace

std::string canonical_scenario(std::string_view text) {
  std::string squeezed;
  for (char c : text)
    if (!std::isspace(static_cast<unsigned char>(c))) squeezed += c;
  for (const char* s : {"SingleStream", "MultiStream", "Offline", "Server"})
    if (squeezed == s) return s;
  return {};
}

const LoadgenValue* official_result(const LoadgenSummary& s) {
  const char* key = s.scenario == "SingleStream"  ? "Early stopping 90th percentile estimate"
                    : s.scenario == "MultiStream" ? "Early stopping 99th percentile estimate"
                                                  : nullptr;
  if (key)
    for (const LoadgenValue& v : s.early_stopping)
      if (v.key == key) return &v;
  return s.result ? &*s.result : nullptr;
}

const LoadgenValue* LoadgenSummary::find(std::string_view key, bool per_query) const {
  for (const LoadgenValue& v : values)
    if (v.key == key && v.per_query == per_query) return &v;
  return nullptr;
}

LoadgenSummary parse_loadgen_summary(std::string_view text, const std::string& file) {
  LoadgenSummary s;
  bool banner = false, per_query = false;
  std::size_t scenario_line = 0;
  std::size_t line_no = 0;
  while (!text.empty()) {
    const std::size_t nl = text.find('\n');
    const std::string_view raw = text.substr(0, nl);
    text = nl == std::string_view::npos ? std::string_view{} : text.substr(nl + 1);
    ++line_no;
    const std::string_view line = trim(raw);
    if (line == "MLPerf Results Summary") {
      banner = true;
      continue;
    }
    if (line.starts_with("Per-query latency")) per_query = true;
    if (line.starts_with("Per-sample latency")) per_query = false;
    const std::size_t colon = line.find(':');
    if (banner && line.starts_with("*") && line.find("Early stopping") != std::string_view::npos &&
        line.find("percentile estimate") != std::string_view::npos && colon != std::string_view::npos) {
      const std::string_view key = trim(line.substr(1, colon - 1));
      const auto v = number(line.substr(colon + 1));
      if (!v || *v < 0)
        fail(ImportErrorCategory::InvalidValue, file, line_no, std::string(key),
             "'" + std::string(trim(line.substr(colon + 1))) + "' is not a latency in ns");
      s.early_stopping.push_back({std::string(key), *v, line_no, false});
      continue;
    }
    if (colon == std::string_view::npos || line.starts_with("*")) continue;
    const std::string_view key = trim(line.substr(0, colon));
    const std::string_view value = trim(line.substr(colon + 1));
    if (!banner) continue;  // nothing before the banner belongs to the summary
    if (key == "SUT name") {
      s.sut_name = std::string(value);
    } else if (key == "Scenario") {
      s.scenario = canonical_scenario(value);
      scenario_line = line_no;
      if (s.scenario.empty())
        fail(ImportErrorCategory::Unsupported, file, line_no, "Scenario",
             "'" + std::string(value) + "' is not a LoadGen scenario (SingleStream, MultiStream, Offline, Server)");
    } else if (key == "Mode") {
      s.mode = std::string(value);
    } else if (key == "Result is") {
      s.validity = std::string(value);
      s.valid = value == "VALID";
      s.validity_line = line_no;
      if (value != "VALID" && value != "INVALID")
        fail(ImportErrorCategory::InvalidValue, file, line_no, "Result is",
             "'" + std::string(value) + "' is neither VALID nor INVALID");
    } else if (key.ends_with("satisfied")) {
      s.checks.emplace_back(std::string(key), yes_no(value));
    } else if (numeric_key(key) && !value.empty() && value.front() != '"') {
      const auto v = number(value);
      if (!v)
        fail(ImportErrorCategory::InvalidValue, file, line_no, std::string(key),
             "'" + std::string(value) + "' is not a number");
      if (*v < 0 && key.find("seed") == std::string_view::npos)
        fail(ImportErrorCategory::InvalidValue, file, line_no, std::string(key), "negative value");
      s.values.push_back({std::string(key), *v, line_no, per_query});
      if (key == "samples_per_query" || key == "Samples per query") s.samples_per_query = *v;
    }
  }
  if (!banner)
    fail(ImportErrorCategory::Syntax, file, 0, {}, "no \"MLPerf Results Summary\" banner: not a LoadGen summary");
  if (scenario_line == 0) fail(ImportErrorCategory::MissingField, file, 0, "Scenario", "no Scenario line");
  if (s.mode.empty()) fail(ImportErrorCategory::MissingField, file, 0, "Mode", "no Mode line");
  if (s.validity_line == 0)
    fail(ImportErrorCategory::Syntax, file, line_no, "Result is",
         "the summary ends before its \"Result is\" line (truncated log?)");
  // The headline metric of each scenario, by the names every round used.
  const auto first_of = [&](std::initializer_list<std::string_view> keys) -> std::optional<LoadgenValue> {
    for (std::string_view k : keys)
      if (const LoadgenValue* v = s.find(k)) return *v;
    return std::nullopt;
  };
  if (s.scenario == "SingleStream")
    s.result = first_of({"90th percentile latency (ns)", "90.00 percentile latency (ns)"});
  else if (s.scenario == "MultiStream")
    s.result = first_of({"99th percentile latency (ns)", "Samples per query"});
  else if (s.scenario == "Offline")
    s.result = first_of({"Samples per second"});
  else
    s.result = first_of({"Completed samples per second", "Scheduled samples per second"});
  const bool performance = s.mode.starts_with("Performance");
  if (performance && !s.result)
    fail(ImportErrorCategory::MissingField, file, line_no, s.scenario,
         "no result line for the " + s.scenario + " scenario (truncated log?)");
  return s;
}

}  // namespace bs
