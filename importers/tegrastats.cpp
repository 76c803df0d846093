// SPDX-License-Identifier: GPL-3.0-or-later
#include "tegrastats.h"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <optional>
#include <vector>

namespace bs {
namespace {

std::vector<std::string_view> tokens(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    const std::size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

bool rail_name(std::string_view t) {
  return t.size() >= 3 && std::all_of(t.begin(), t.end(), [](char c) { return (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_'; }) &&
         (t.starts_with("VDD") || t.starts_with("POM_") || t.starts_with("VIN"));
}

// "3981/3981" or "5000mW/5000mW" -> the current value in mW.
std::optional<double> rail_value(std::string_view t) {
  const auto slash = t.find('/');
  if (slash == std::string_view::npos) return std::nullopt;
  std::string_view cur = t.substr(0, slash), avg = t.substr(slash + 1);
  if (cur.ends_with("mW")) cur.remove_suffix(2);
  if (avg.ends_with("mW")) avg.remove_suffix(2);
  double v = 0, a = 0;
  const auto r1 = std::from_chars(cur.data(), cur.data() + cur.size(), v);
  const auto r2 = std::from_chars(avg.data(), avg.data() + avg.size(), a);
  if (r1.ec != std::errc() || r1.ptr != cur.data() + cur.size() || r2.ec != std::errc() || r2.ptr != avg.data() + avg.size())
    return std::nullopt;
  return v;
}

// "11-22-2026" "10:00:01" -> seconds since an arbitrary epoch (days from a civil calendar + time of day).
std::optional<double> timestamp(std::string_view date, std::string_view time) {
  int mo = 0, d = 0, y = 0, h = 0, mi = 0;
  double s = 0;
  if (std::sscanf(std::string(date).c_str(), "%d-%d-%d", &mo, &d, &y) != 3) return std::nullopt;
  if (std::sscanf(std::string(time).c_str(), "%d:%d:%lf", &h, &mi, &s) != 3) return std::nullopt;
  if (mo < 1 || mo > 12 || d < 1 || d > 31 || h > 23 || mi > 59 || s >= 61) return std::nullopt;
  // Days from civil (Howard Hinnant's algorithm): exact across month and year boundaries.
  y -= mo <= 2;
  const int era = (y >= 0 ? y : y - 399) / 400;
  const int yoe = y - era * 400;
  const int doy = (153 * (mo + (mo > 2 ? -3 : 9)) + 2) / 5 + d - 1;
  const int doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
  const double days = era * 146097.0 + doe - 719468;
  return days * 86400 + h * 3600 + mi * 60 + s;
}

}  // namespace

int TegrastatsImporter::sniff(std::string_view head, std::string_view) const {
  const bool ram = head.find("RAM ") != std::string_view::npos;
  const bool rails = head.find("VDD_") != std::string_view::npos || head.find("POM_") != std::string_view::npos;
  return ram && rails ? 90 : 0;
}

ImportBatch TegrastatsImporter::parse(const std::string& path, const ImportLimits& limits, const CancelToken& cancel) const {
  const std::string text = read_whole_file(path, limits.max_json_bytes);
  cancel.throw_if_cancelled();
  return parse_tegrastats(text, path);
}

ImportBatch parse_tegrastats(std::string_view text, const std::string& file, double interval_s) {
  ImportBatch batch;
  PowerTrace trace;
  trace.platform = "Jetson";
  trace.label = file.substr(file.find_last_of('/') == std::string::npos ? 0 : file.find_last_of('/') + 1);
  trace.provenance.origin = DataOrigin::Measured;
  trace.provenance.tool = "tegrastats";
  trace.provenance.source_file = file;
  std::vector<std::string> rails;
  std::optional<double> first_time;
  std::size_t pos = 0, line_no = 0, sample = 0;
  while (pos < text.size()) {
    const std::size_t end = std::min(text.find('\n', pos), text.size());
    const std::string_view line = text.substr(pos, end - pos);
    pos = end + 1;
    ++line_no;
    const auto tok = tokens(line);
    if (tok.empty()) continue;
    std::vector<std::pair<std::string, double>> values;
    for (std::size_t i = 0; i + 1 < tok.size(); ++i)
      if (rail_name(tok[i]))
        if (const auto v = rail_value(tok[i + 1])) values.emplace_back(std::string(tok[i]), *v / 1000.0);
    if (values.empty()) {
      batch.warnings.push_back(file + ":" + std::to_string(line_no) + ": no power rails on this line; skipped");
      continue;
    }
    // The board's input rail first: power_series() takes the first power channel as the platform's power.
    std::stable_partition(values.begin(), values.end(), [](const auto& r) {
      return r.first == "VDD_IN" || r.first == "POM_5V_IN" || r.first.starts_with("VIN");
    });
    if (rails.empty()) {
      for (const auto& [name, v] : values) {
        rails.push_back(name);
        trace.channels.push_back({name, PowerQuantity::Power, {}});
      }
    } else if (values.size() != rails.size() ||
               !std::equal(values.begin(), values.end(), rails.begin(), [](const auto& a, const auto& b) { return a.first == b; })) {
      if (pos >= text.size()) {  // a last line cut short when tegrastats was stopped
        batch.warnings.push_back(file + ":" + std::to_string(line_no) + ": incomplete last line; skipped");
        break;
      }
      throw ImportError(ImportErrorCategory::InvalidValue, {file, line_no, 1, "rails"},
                        "the rails differ from the first line's (" + std::to_string(values.size()) + " vs " +
                            std::to_string(rails.size()) + ")");
    }
    double t = static_cast<double>(sample) * interval_s;
    if (tok.size() >= 2) {
      if (const auto ts = timestamp(tok[0], tok[1])) {
        if (!first_time) first_time = *ts;
        t = *ts - *first_time;
        if (!trace.time_s.empty() && t < trace.time_s.back())
          throw ImportError(ImportErrorCategory::InvalidValue, {file, line_no, 1, "timestamp"}, "time goes backwards");
      }
    }
    trace.time_s.push_back(t);
    for (std::size_t k = 0; k < values.size(); ++k) trace.channels[k].values.push_back(values[k].second);
    ++sample;
  }
  if (trace.time_s.empty()) throw ImportError(ImportErrorCategory::MissingField, {file, 0, 0, {}}, "no lines with power rails (VDD_*, POM_*)");
  batch.power_traces.push_back(std::move(trace));
  return batch;
}

}  // namespace bs
