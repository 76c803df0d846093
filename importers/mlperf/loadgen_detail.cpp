// SPDX-License-Identifier: GPL-3.0-or-later
#include "mlperf/loadgen_detail.h"

#include <array>
#include <string_view>

#include "analysis/power/power_time.h"
#include "common/json_access.h"

namespace bs {

LoadgenDetail parse_loadgen_detail(std::string_view text, const std::string& file, const ImportLimits& limits) {
  constexpr std::string_view kPrefix = ":::MLLOG ";
  constexpr std::array<std::string_view, 6> kKeys = {"loadgen_version",    "test_datetime",
                                                     "result_query_count", "power_begin",
                                                     "power_end",          "result_qps_with_loadgen_overhead"};
  LoadgenDetail d;
  std::size_t line_no = 0;
  while (!text.empty()) {
    const std::size_t nl = text.find('\n');
    std::string_view line = text.substr(0, nl);
    text = nl == std::string_view::npos ? std::string_view{} : text.substr(nl + 1);
    ++line_no;
    if (!line.starts_with(kPrefix)) continue;
    line.remove_prefix(kPrefix.size());
    // The key is the first member LoadGen writes: {"key": "power_begin", ...}.
    std::string_view wanted;
    for (std::string_view k : kKeys)
      if (line.starts_with("{\"key\": \"") && line.substr(9).starts_with(k) &&
          line.substr(9 + k.size()).starts_with("\""))
        wanted = k;
    if (wanted.empty()) continue;
    json_access::json j;
    try {
      j = json_access::parse(line, file, limits);
    } catch (const ImportError& e) {
      throw ImportError(e.category(), {file, line_no, 0, std::string(wanted)},
                        "malformed :::MLLOG line: " + e.reason());
    }
    const auto value = j.find("value");
    if (value == j.end())
      throw ImportError(ImportErrorCategory::MissingField, {file, line_no, 0, std::string(wanted)},
                        ":::MLLOG line without a value");
    const bool text_value = value->is_string();
    // The two counts the power metric needs: positive numbers.
    if (wanted == "result_qps_with_loadgen_overhead" || wanted == "result_query_count") {
      if (!value->is_number() || value->get<double>() <= 0)
        throw ImportError(ImportErrorCategory::InvalidValue, {file, line_no, 0, std::string(wanted)},
                          std::string(wanted) + " is not a positive number");
      const bool qps = wanted == "result_qps_with_loadgen_overhead";
      (qps ? d.qps_with_loadgen_overhead : d.result_query_count) = value->get<double>();
      (qps ? d.qps_with_line : d.query_count_line) = line_no;
      continue;
    }
    if (!text_value)
      throw ImportError(ImportErrorCategory::WrongType, {file, line_no, 0, std::string(wanted)},
                        std::string(wanted) + " is not a string");
    const std::string v = value->get<std::string>();
    if (wanted == "loadgen_version") d.loadgen_version = v;
    if (wanted == "test_datetime") d.test_datetime = v;
    if (wanted == "power_begin" || wanted == "power_end") {
      if (!ptd_time_to_epoch(v))
        throw ImportError(ImportErrorCategory::InvalidValue, {file, line_no, 0, std::string(wanted)},
                          "'" + v + "' is not a MM-DD-YYYY hh:mm:ss.fff time");
      (wanted == "power_begin" ? d.power_begin : d.power_end) = v;
      (wanted == "power_begin" ? d.power_begin_line : d.power_end_line) = line_no;
    }
  }
  return d;
}

std::optional<double> ptd_time_to_epoch(std::string_view t) {
  if (t.size() < 19 || t[2] != '-' || t[5] != '-') return std::nullopt;  // month first, as PTDaemon writes it
  return parse_date_time(t);
}

}  // namespace bs
