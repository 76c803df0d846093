// SPDX-License-Identifier: GPL-3.0-or-later
#include "power/power_recording.h"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "power/power_csv.h"
#include "sensors/recording_csv.h"
#include "util/text.h"

namespace bs {
namespace {

bool number(std::string_view s, double& v) {
  s = trim(s);
  const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  return !s.empty() && ec == std::errc() && p == s.data() + s.size() && std::isfinite(v);
}

// What the comment block says, with the line of each phase for errors.
struct Header {
  std::vector<std::pair<std::string, std::string>> keys;    // in file order
  std::vector<std::pair<std::string, std::size_t>> phases;  // "NAME = A .. B", line
  std::vector<std::pair<std::string, std::string>> settings;
};

Header read_header(std::string_view text, const std::string& file) {
  Header h;
  std::size_t line_no = 0, pos = 0;
  while (pos < text.size()) {
    const auto nl = text.find('\n', pos);
    const std::string_view line =
        trim(text.substr(pos, nl == std::string_view::npos ? std::string_view::npos : nl - pos));
    pos = nl == std::string_view::npos ? text.size() : nl + 1;
    ++line_no;
    if (line.empty()) continue;
    if (line.front() != '#') break;  // the column header: comments are over
    if (line_no == 1) continue;      // the magic line
    std::string_view body = trim(line.substr(1));
    const auto colon = body.find(':');
    if (colon == std::string_view::npos) continue;
    const std::string key(trim(body.substr(0, colon)));
    const std::string value(trim(body.substr(colon + 1)));
    if (key == "phase")
      h.phases.emplace_back(value, line_no);
    else if (key == "setting") {
      const auto eq = value.find(" = ");
      if (eq == std::string::npos)
        throw ImportError(ImportErrorCategory::Syntax, {file, line_no, 1, "setting"},
                          "expected '# setting: NAME = VALUE', found '" + value.substr(0, 60) + "'");
      h.settings.emplace_back(value.substr(0, eq), value.substr(eq + 3));
    } else {
      h.keys.emplace_back(key, value);
    }
  }
  return h;
}

std::string key(const Header& h, std::string_view name) {
  for (const auto& [k, v] : h.keys)
    if (k == name) return v;
  return {};
}

ImportBatch finish(ImportBatch batch, const Header& h, const std::string& file) {
  if (batch.power_traces.size() != 1)
    throw ImportError(ImportErrorCategory::Syntax, {file, 0, 0, {}}, "expected one power trace");
  PowerTrace& t = batch.power_traces.front();
  // Columns are "<channel> power (W)": the channel's own name back.
  constexpr std::string_view suffix = " power (W)";
  for (PowerChannel& c : t.channels)
    if (c.name.ends_with(suffix)) c.name.resize(c.name.size() - suffix.size());
  const std::string measurement = key(h, "measurement");
  if (measurement_kind_from_string(measurement) != MeasurementKind::OnBoardSensor)
    throw ImportError(ImportErrorCategory::InvalidValue, {file, 0, 0, "measurement"},
                      "'" + measurement + "': a BenchScope recording is from an on-board sensor");
  t.total_channel = key(h, "total_channel");
  if (!t.total_channel.empty() && std::none_of(t.channels.begin(), t.channels.end(),
                                               [&](const PowerChannel& c) { return c.name == t.total_channel; }))
    throw ImportError(ImportErrorCategory::MissingField, {file, 0, 0, "total_channel"},
                      "total channel '" + t.total_channel + "' is not one of the columns");
  // The header names the total, so the CSV reader's guess at it from the column names ("statistics use ...") does
  // not apply and is not passed on.
  if (!t.total_channel.empty())
    std::erase_if(batch.warnings, [](const std::string& w) { return w.find("statistics use '") != std::string::npos; });
  for (const auto& [value, line] : h.phases) {
    const auto eq = value.rfind(" = ");
    const auto dots = value.find(" .. ", eq == std::string::npos ? 0 : eq);
    double a = 0, b = 0;
    if (eq == std::string::npos || dots == std::string::npos ||
        !number(std::string_view(value).substr(eq + 3, dots - eq - 3), a) ||
        !number(std::string_view(value).substr(dots + 4), b))
      throw ImportError(ImportErrorCategory::Syntax, {file, line, 1, "phase"},
                        "expected '# phase: NAME = START .. END' (seconds), found '" + value.substr(0, 60) + "'");
    if (b < a || a < 0)
      throw ImportError(ImportErrorCategory::InvalidValue, {file, line, 1, "phase"},
                        "phase '" + value.substr(0, eq) + "' ends before it starts or starts before 0 s");
    t.phases.push_back({value.substr(0, eq), a, b});
  }
  Provenance& p = t.provenance;
  p.measurement = MeasurementKind::OnBoardSensor;
  p.sensor = key(h, "sensor");
  p.host = key(h, "host");
  p.tool = key(h, "tool");
  p.settings = h.settings;
  const std::string start = key(h, "start_time");
  if (!start.empty()) {
    t.start_time = start;
    p.date = start;
  }
  if (const std::string label = key(h, "label"); !label.empty()) t.label = label;
  if (t.platform.empty()) t.platform = p.host;
  p.note = "recorded by BenchScope from " + (p.sensor.empty() ? std::string("an on-board sensor") : p.sensor);
  if (const std::string skipped = key(h, "skipped_rows"); !skipped.empty())
    batch.warnings.push_back(file + ": " + skipped + " rows where a sensor read failed were not written");
  return batch;
}

}  // namespace

static int sniff_power_recording(std::string_view head, std::string_view) {
  return head.starts_with(sensors::kRecordingMagic) ? 95 : 0;
}

// The settings come from the comment block, never from the options: the power-CSV parser gets the defaults.
static ImportBatch parse_power_recording_file(const std::string& path, const ParseOptions& /*options*/,
                                              const ImportLimits& limits, const CancelToken& cancel) {
  // The comment block is in the first 64 KiB (a few hundred phases at most); the rows stream through power-csv.
  const std::string head = read_head(path);
  const Header h = read_header(strip_utf8_bom(head), path);
  return finish(kPowerCsvFileFormat.parse(path, ParseOptions{}, limits, cancel), h, path);
}

static ImportBatch parse_power_recording(const std::string& text, const std::string& file,
                                         const ParseOptions& /*options*/, const ImportLimits& limits,
                                         const CancelToken& cancel) {
  const Header h = read_header(std::string_view(text).substr(0, 64 * 1024), file);
  return finish(kPowerCsvFileFormat.parse_text(text, file, ParseOptions{}, limits, cancel), h, file);
}

const FileFormat kPowerRecordingFileFormat{
    "benchscope-power-recording", "BenchScope on-board sensor power recording (CSV)",
    sniff_power_recording,        parse_power_recording_file,
    parse_power_recording,        ".csv"};

}  // namespace bs
