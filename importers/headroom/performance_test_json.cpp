// SPDX-License-Identifier: GPL-3.0-or-later
#include "headroom/performance_test_json.h"

#include "common/json_access.h"
#include "common/text_file.h"
#include "headroom/imported_latency.h"
#include "headroom/performance_test_rows.h"

namespace bs {
namespace {

using json_access::child;
using json_access::json;
using json_access::Reader;

// The configuration keys kept in the provenance, in the log's own words.
constexpr std::string_view kSettings[] = {"perf_test_version",
                                          "com_mean_str",
                                          "rmw_implementation",
                                          "qos_reliability",
                                          "qos_durability",
                                          "qos_history_kind",
                                          "qos_history_depth",
                                          "rate",
                                          "topic_name",
                                          "msg_name",
                                          "max_runtime",
                                          "number_of_publishers",
                                          "number_of_subscribers",
                                          "is_zero_copy_transfer",
                                          "roundtrip_mode",
                                          "is_rt_init_required",
                                          "id"};

std::string setting_text(const json& v) { return v.is_string() ? v.get<std::string>() : v.dump(); }

}  // namespace

static ImportBatch parse_performance_test_json(const std::string& text, const std::string& file,
                                               const ParseOptions& /*options*/, const ImportLimits& limits,
                                               const CancelToken& cancel) {
  const json doc = json_access::parse(text, file, limits, &cancel);
  const Reader r(file, text);
  r.require_object(doc, "");
  std::vector<std::pair<std::string, std::string>> settings;
  for (std::string_view key : kSettings)
    if (const json* v = r.optional(doc, key)) settings.emplace_back(std::string(key), setting_text(*v));
  std::optional<double> rate;
  if (auto v = r.optional_number(doc, "", "rate"); v && *v > 0) rate = *v;
  if (const json* rt = r.optional(doc, "roundtrip_mode"); rt && rt->is_string() && rt->get<std::string>() != "NONE")
    settings.emplace_back("note", "round-trip mode: latencies are round trips (relay), not one way");
  const json& results = r.require_array(r.require(doc, "", "analysis_results"), "/analysis_results");
  std::vector<headroom_import::PerfTestRow> rows;
  rows.reserve(results.size());
  for (std::size_t k = 0; k < results.size(); ++k) {
    if ((k & 0xFFF) == 0) cancel.throw_if_cancelled();
    const std::string at = child("/analysis_results", k);
    const json& row = r.require_object(results[k], at);
    headroom_import::PerfTestRow p;
    p.at = json_access::location_of_offset(file, text, json_access::offset_of_pointer(text, at));
    p.at.field = at;
    p.t_experiment_s = r.require_number(row, at, "experiment_start") * 1e-9;
    p.t_loop_s = r.require_number(row, at, "loop_start") * 1e-9;
    p.received = r.require_number(row, at, "num_samples_received");
    p.sent = r.optional_number(row, at, "num_samples_sent").value_or(0);
    p.latency_n = r.optional_number(row, at, "latency_n");
    p.min_s = r.require_number(row, at, "latency_min");
    p.max_s = r.require_number(row, at, "latency_max");
    p.mean_s = r.require_number(row, at, "latency_mean");
    p.variance_s2 = r.require_number(row, at, "latency_variance");
    rows.push_back(p);
  }
  if (rows.empty())
    r.fail(ImportErrorCategory::MissingField, "/analysis_results",
           "holds no statistics row (the experiment ended before its first second)");
  settings.emplace_back("latency unit", "s");
  const headroom_import::CombinedLatency combined = headroom_import::combine_rows(rows, rate);
  return headroom_import::batch_of(headroom_import::perf_test_measurement(combined, std::move(settings), file), file);
}

static int sniff_performance_test_json(std::string_view head, std::string_view) {
  const auto has = [&](std::string_view w) { return head.find(w) != std::string_view::npos; };
  const std::size_t start = head.find_first_not_of(" \t\r\n");
  if (start == std::string_view::npos || head[start] != '{') return 0;
  if (has("\"analysis_results\"") && (has("\"perf_test_version\"") || has("\"com_mean_str\""))) return 95;
  if (has("\"analysis_results\"") && has("\"latency_mean\"")) return 85;
  return 0;
}

const FileFormat kPerformanceTestJsonFileFormat{
    "performance-test-json",     "Apex.AI performance_test JSON log",
    sniff_performance_test_json, parse_text_file_with<parse_performance_test_json>,
    parse_performance_test_json, ".json"};

}  // namespace bs
