// SPDX-License-Identifier: GPL-3.0-or-later
#include "ros2/robotperf_yaml.h"

#include <algorithm>
#include <charconv>
#include <cmath>

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

// What RobotPerf's value is, by metric, and its SI unit and scale.
struct Meaning {
  std::string metric, unit;
  double scale = 1;
};

Meaning meaning(const std::string& metric, const std::string& unit, const std::string& file, std::size_t line) {
  if (metric == "latency") {
    if (unit == "ms") return {"latency: maximum of the run (RobotPerf's value)", "s", 1e-3};
    if (unit == "us") return {"latency: maximum of the run (RobotPerf's value)", "s", 1e-6};
    if (unit == "s") return {"latency: maximum of the run (RobotPerf's value)", "s", 1};
  } else if (metric == "throughput") {
    if (unit == "fps" || unit == "Hz") return {"throughput: mean of the run (RobotPerf's value)", "1/s", 1};
  } else if (metric == "power") {
    if (unit == "W") return {"power (as RobotPerf reports it; the statistic is not stated)", "W", 1};
  } else {
    fail(ImportErrorCategory::Unsupported, file, line, "metric",
         "'" + metric + "' is not latency, throughput or power");
  }
  fail(ImportErrorCategory::Unsupported, file, line, "metric_unit", "'" + unit + "' is not a unit of " + metric);
}

bool iso_date(const std::string& d) { return d.size() >= 10 && d[4] == '-' && d[7] == '-'; }

// Hardware names BenchScope can tie to one computer; anything else is free text, said so.
bool named_board(const std::string& h) {
  for (const char* k : {"Orin", "Xavier", "Jetson", "Raspberry", "Thor", "Kria", "TX2", "Nano"})
    if (h.find(k) != std::string::npos) return true;
  return false;
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
    const Meaning m = meaning(metric, unit, file, r->find("metric") ? r->find("metric")->line : r->line);
    if (v <= 0)
      batch.warnings.push_back(file + ":" + std::to_string(line) + ": value: " + value_text + " " + unit + " of " +
                               metric + " on " + hardware + " is impossible (flag: impossible value)");
    const std::string date = text_of(*r, "timestampt").empty() ? text_of(*r, "timestamp") : text_of(*r, "timestampt");
    if (iso_date(date))
      iso = true;
    else if (!date.empty()) {
      dashed = true;
      dashed_lines.push_back(r->find("timestampt") ? r->find("timestampt")->line : r->line);
    }
    auto set = std::find_if(batch.result_sets.begin(), batch.result_sets.end(),
                            [&](const ResultSet& s) { return s.platform == hardware; });
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
                               {"latency value", "maximum of the run"},
                               {"throughput value", "mean of the run"}};
      if (!named_board(hardware)) {
        s.provenance.settings.emplace_back("hardware", "free text: '" + hardware + "' (not tied to one computer)");
        batch.warnings.push_back(file + ":" + std::to_string(r->line) + ": hardware '" + hardware +
                                 "' is free text, not one computer BenchScope knows (flag: free-text hardware)");
      }
      batch.result_sets.push_back(std::move(s));
      set = batch.result_sets.end() - 1;
    }
    Measurement x;
    x.name = id + " " + name + " (" + (date.empty() ? "no date" : date) + ", line " + std::to_string(line) + ")";
    x.metric = m.metric;
    x.unit = m.unit;
    x.values = {v * m.scale};
    set->measurements.push_back(std::move(x));
  }
  if (batch.result_sets.empty()) fail(ImportErrorCategory::MissingField, file, results->line, "results", "empty");
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

bool yaml_extension(std::string_view path) { return path.ends_with(".yaml") || path.ends_with(".yml"); }

}  // namespace

const FileFormat kRobotperfYamlFileFormat{"robotperf-yaml", "RobotPerf benchmark.yaml results",
                                          sniff_robotperf,  parse_text_file_with<parse_robotperf>,
                                          parse_robotperf,  yaml_extension};

}  // namespace bs
