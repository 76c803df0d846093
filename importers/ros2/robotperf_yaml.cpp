// SPDX-License-Identifier: GPL-3.0-or-later
#include "ros2/robotperf_yaml.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <string_view>
#include <utility>

#include "ros2/yaml_subset.h"

namespace bs {
namespace {

[[noreturn]] void fail(ImportErrorCategory c, const std::string& file, std::size_t line, const std::string& field,
                       const std::string& why) {
  throw ImportError(c, {file, line, 0, field}, why);
}

std::string text_of(const YamlNode& result, const char* key) {
  const YamlNode* n = result.find(key);
  return n && n->kind == YamlNode::Kind::Scalar ? n->scalar : std::string();
}

// Which statistic of the run RobotPerf's value is: the one of its note ("mean_benchmark 30.2, ... max_benchmark
// 36.46", "mean 5.41 ms, ... max 9.23 ms", "max_latency ...") whose number is the value to the digits both print.
// a2's and a5's throughputs are the run's maximum, c1's its mean; a note without numbers leaves it not stated. The
// same rule as scripts/build-library.py's robotperf_statistic.
std::string statistic_of(std::string_view value_text, std::string_view note) {
  static constexpr std::pair<std::string_view, std::string_view> kStats[] = {{"mean", "mean of the run"},
                                                                             {"max", "maximum of the run"},
                                                                             {"min", "minimum of the run"},
                                                                             {"rms", "root mean square of the run"}};
  const auto decimals = [](std::string_view t) {
    const std::size_t dot = t.find('.');
    return dot == std::string_view::npos ? std::size_t{0} : t.size() - dot - 1;
  };
  const auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; };
  double v = 0;
  if (std::from_chars(value_text.data(), value_text.data() + value_text.size(), v).ec != std::errc()) return {};
  for (std::size_t i = 0; i < note.size(); ++i) {
    if (i > 0 && word(note[i - 1])) continue;
    for (const auto& [key, what] : kStats) {
      if (!note.substr(i).starts_with(key)) continue;
      std::size_t j = i + key.size();
      for (std::string_view suffix : {"_benchmark", "_latency"})
        if (note.substr(j).starts_with(suffix)) j += suffix.size();
      const std::string_view name = note.substr(i, j - i);
      if (j >= note.size() || !std::isspace(static_cast<unsigned char>(note[j]))) continue;
      while (j < note.size() && std::isspace(static_cast<unsigned char>(note[j]))) ++j;
      std::size_t k = j;
      while (k < note.size() && std::isdigit(static_cast<unsigned char>(note[k]))) ++k;
      if (k == j) continue;
      if (k + 1 < note.size() && note[k] == '.' && std::isdigit(static_cast<unsigned char>(note[k + 1])))
        for (++k; k < note.size() && std::isdigit(static_cast<unsigned char>(note[k]));) ++k;
      const std::string_view number = note.substr(j, k - j);
      double x = 0;
      std::from_chars(number.data(), number.data() + number.size(), x);
      const double tolerance =
          0.5 * std::pow(10.0, -static_cast<double>(std::min(decimals(number), decimals(value_text)))) + 1e-12;
      if (std::abs(x - v) <= tolerance)
        return std::string(what) + " (RobotPerf's value; its note's " + std::string(name) + ")";
    }
  }
  return "statistic not stated (RobotPerf's value; its note gives none equal to it)";
}

// What RobotPerf's value is, by metric, and its SI unit and scale.
struct Meaning {
  std::string metric, unit;
  double scale = 1;
};

Meaning meaning(const std::string& metric, const std::string& unit, const std::string& statistic,
                const std::string& file, std::size_t line) {
  if (metric == "latency") {
    if (unit == "ms") return {"latency: " + statistic, "s", 1e-3};
    if (unit == "us") return {"latency: " + statistic, "s", 1e-6};
    if (unit == "s") return {"latency: " + statistic, "s", 1};
  } else if (metric == "throughput") {
    if (unit == "fps" || unit == "Hz") return {"throughput: " + statistic, "1/s", 1};
  } else if (metric == "power") {
    if (unit == "W") return {"power (as RobotPerf reports it; the statistic is not stated)", "W", 1};
  } else {
    fail(ImportErrorCategory::Unsupported, file, line, "metric",
         "'" + metric + "' is not latency, throughput or power");
  }
  fail(ImportErrorCategory::Unsupported, file, line, "metric_unit", "'" + unit + "' is not a unit of " + metric);
}

bool iso_date(const std::string& d) { return d.size() >= 10 && d[4] == '-' && d[7] == '-'; }

// One machine under two spellings ("NVIDIA AGX Orin Dev. Kit", "NVIDIA AGX Orin Developer Kit"; "Intel® Core™
// i5-8250U CPU @ 1.60GHz × 8", "Intel Core i5-8250U"): the key that merges them. Marks, "Dev. Kit"/"Developer Kit",
// the clock and core count and case do not tell machines apart; an added GPU ("+ NVIDIA GeForce RTX 3060") does.
std::string machine_key(std::string_view hardware) {
  std::string s;
  for (std::size_t i = 0; i < hardware.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(hardware[i]);
    if (c >= 0x80) continue;  // ®, ™, × and other marks (UTF-8 bytes)
    s.push_back(static_cast<char>(std::tolower(c)));
  }
  for (const char* noise : {"(r)", "(tm)", " developer kit", " dev. kit", " dev kit", " cpu"})
    for (std::size_t at; (at = s.find(noise)) != std::string::npos;) s.erase(at, std::string_view(noise).size());
  if (const std::size_t at = s.find(" @ "); at != std::string::npos) s.erase(at);  // "@ 1.60GHz x 8"
  std::string out;
  for (char c : s)
    if (c != ' ' || (!out.empty() && out.back() != ' ')) out.push_back(c);
  while (!out.empty() && out.back() == ' ') out.pop_back();
  return out;
}

// Below this no computer runs: a value such as 8.97e-44 W is a reading of nothing (a denormal from an unset
// counter), flagged like 0 W.
constexpr double kLeastPowerW = 0.01;

// Hardware names BenchScope can tie to one computer; anything else is free text, said so.
bool named_board(const std::string& h) {
  for (const char* k : {"Orin", "Xavier", "Jetson", "Raspberry", "Thor", "Kria", "TX2", "Nano"})
    if (h.find(k) != std::string::npos) return true;
  return false;
}

// A "throughput" that is the same whole number on every machine (c1's joint trajectory controller: 10/s on an
// i7-8700K and on an AGX Orin) is the rate the loop was configured to run at, not what the machine can do: renamed
// and flagged, so it is never ranked as a capacity.
void configured_rates(ImportBatch& batch, const std::string& file) {
  std::vector<Measurement*> rates;
  for (ResultSet& s : batch.result_sets)
    for (Measurement& m : s.measurements)
      if (m.metric.starts_with("throughput") && !m.values.empty()) rates.push_back(&m);
  if (rates.size() < 2 || batch.result_sets.size() < 2) return;
  const double first = rates.front()->values.front();
  for (const Measurement* m : rates)
    if (m->values.front() != first) return;
  if (first <= 0 || first != std::floor(first)) return;
  for (Measurement* m : rates)
    m->metric = "update rate as configured (the same " + std::to_string(static_cast<long long>(first)) +
                "/s on every machine: not a throughput)";
  batch.warnings.push_back(file + ": every machine's 'throughput' is " + std::to_string(static_cast<long long>(first)) +
                           "/s: the rate the loop was configured to run at, not a throughput (flag: configured rate)");
}

ImportBatch parse_robotperf(const std::string& text, const std::string& file, const ParseOptions&,
                            const ImportLimits& limits, const CancelToken& cancel) {
  const YamlNode doc = parse_yaml_subset(text, file, limits);
  if (doc.kind != YamlNode::Kind::Map) fail(ImportErrorCategory::Syntax, file, doc.line, "", "not a mapping");
  const YamlNode* results = doc.find("results");
  if (!results || results->kind != YamlNode::Kind::Seq)
    fail(ImportErrorCategory::MissingField, file, doc.line, "results", "no results list: not a RobotPerf benchmark");
  const std::string id = text_of(doc, "id"), name = text_of(doc, "name");
  if (name.empty()) fail(ImportErrorCategory::MissingField, file, doc.line, "name", "missing");
  ImportBatch batch;
  bool iso = false, dashed = false;
  std::vector<std::size_t> dashed_lines;
  for (const YamlNode& item : results->seq) {
    cancel.throw_if_cancelled();
    const YamlNode* r = item.find("result");
    if (!r || r->kind != YamlNode::Kind::Map)
      fail(ImportErrorCategory::Syntax, file, item.line, "result", "a results entry without its 'result:' mapping");
    const std::string hardware = text_of(*r, "hardware"), metric = text_of(*r, "metric");
    const std::string unit = text_of(*r, "metric_unit"), value_text = text_of(*r, "value");
    const YamlNode* vnode = r->find("value");
    const std::size_t line = vnode ? vnode->line : r->line;
    if (hardware.empty()) fail(ImportErrorCategory::MissingField, file, r->line, "hardware", "missing");
    double v = 0;
    const auto [end, ec] = std::from_chars(value_text.data(), value_text.data() + value_text.size(), v);
    if (value_text.empty() || ec != std::errc() || end != value_text.data() + value_text.size() || !std::isfinite(v))
      fail(ImportErrorCategory::InvalidValue, file, line, "value", "'" + value_text + "' is not a number");
    const Meaning m = meaning(metric, unit, statistic_of(value_text, text_of(*r, "note")), file,
                              r->find("metric") ? r->find("metric")->line : r->line);
    if (v <= 0 || (metric == "power" && v * m.scale < kLeastPowerW))
      batch.warnings.push_back(file + ":" + std::to_string(line) + ": value: " + value_text + " " + unit + " of " +
                               metric + " on " + hardware + " is impossible" +
                               (v > 0 ? std::string(" (below 0.01 W, which no computer draws)") : std::string()) +
                               " (flag: impossible value)");
    // RobotPerf's grey-box (the graph instrumented with tracepoints) and black-box (measured from outside) results
    // are different measurements of one graph: the type stays with each value.
    const std::string type = text_of(*r, "type");
    const std::string date = text_of(*r, "timestampt").empty() ? text_of(*r, "timestamp") : text_of(*r, "timestampt");
    if (iso_date(date))
      iso = true;
    else if (!date.empty()) {
      dashed = true;
      dashed_lines.push_back(r->find("timestampt") ? r->find("timestampt")->line : r->line);
    }
    auto set = std::find_if(batch.result_sets.begin(), batch.result_sets.end(),
                            [&](const ResultSet& s) { return machine_key(s.platform) == machine_key(hardware); });
    if (set != batch.result_sets.end() && set->platform != hardware) {
      auto& st = set->provenance.settings;
      const std::string alias = "also spelled '" + hardware + "'";
      if (std::none_of(st.begin(), st.end(), [&](const auto& kv) { return kv.second == alias; }))
        st.emplace_back("hardware alias", alias);
    }
    if (set == batch.result_sets.end()) {
      ResultSet s;
      s.platform = hardware;
      s.device = hardware;
      s.backend = "ROS 2 (RobotPerf)";
      s.source_format = "robotperf-yaml";
      s.provenance.origin = DataOrigin::Published;
      s.provenance.tool = "RobotPerf";
      s.provenance.source_file = file;
      s.provenance.settings = {{"benchmark", id + " " + name},
                               {"category", text_of(*r, "category")},
                               {"datasource", text_of(*r, "datasource")},
                               {"release", "not stated in the file"},
                               {"latency and throughput values", "the statistic of the run each note gives"}};
      if (!named_board(hardware)) {
        s.provenance.settings.emplace_back("hardware", "free text: '" + hardware + "' (not tied to one computer)");
        batch.warnings.push_back(file + ":" + std::to_string(r->line) + ": hardware '" + hardware +
                                 "' is free text, not one computer BenchScope knows (flag: free-text hardware)");
      }
      batch.result_sets.push_back(std::move(s));
      set = batch.result_sets.end() - 1;
    }
    Measurement x;
    x.name = id + " " + name + (type.empty() ? std::string() : " [" + type + "-box]") + " (" +
             (date.empty() ? "no date" : date) + ", line " + std::to_string(line) + ")";
    x.metric = m.metric;
    x.unit = m.unit;
    x.values = {v * m.scale};
    set->measurements.push_back(std::move(x));
  }
  if (batch.result_sets.empty()) fail(ImportErrorCategory::MissingField, file, results->line, "results", "empty");
  configured_rates(batch, file);
  if (iso && dashed)
    batch.warnings.push_back(file + ":" + std::to_string(dashed_lines.front()) +
                             ": dates in two formats: ISO beside day-or-month-first (08-07-2023 is August 7 or July "
                             "8), kept as written (flag: mixed date formats)");
  return batch;
}

int sniff_robotperf(std::string_view head, std::string_view) {
  return head.find("\nresults:") != std::string_view::npos && head.find("- result:") != std::string_view::npos &&
                 head.find("metric:") != std::string_view::npos
             ? 90
             : 0;
}

}  // namespace

const FileFormat kRobotperfYamlFileFormat{"robotperf-yaml", "RobotPerf benchmark.yaml results",
                                          sniff_robotperf,  parse_text_file_with<parse_robotperf>,
                                          parse_robotperf,  ".yaml .yml"};

}  // namespace bs
