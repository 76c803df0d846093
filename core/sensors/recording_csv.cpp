// SPDX-License-Identifier: GPL-3.0-or-later
#include "sensors/recording_csv.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace bs::sensors {
namespace {

// Comment values are one line without commas: a newline would end the comment and start a bogus row, and a
// comma-separated comment that happened to name "time" and "power" would pass for a CSV header.
std::string one_line(std::string s) {
  for (char& c : s)
    if (c == '\n' || c == '\r')
      c = ' ';
    else if (c == ',')
      c = ';';
  return s;
}

}  // namespace

std::string recording_column(const std::string& channel) { return one_line(channel) + " power (W)"; }

void write_recording_csv(std::ostream& out, const PowerTrace& trace) {
  const Provenance& p = trace.provenance;
  out << kRecordingMagic << '\n';
  out << "# sensor: " << one_line(p.sensor) << '\n';
  for (const auto& [k, v] : p.settings)
    if (k == "sensor kind") out << "# kind: " << one_line(v) << '\n';
  out << "# host: " << one_line(p.host) << '\n';
  out << "# platform: " << one_line(trace.platform) << '\n';
  out << "# start_time: " << one_line(trace.start_time) << '\n';
  out << "# measurement: " << to_string(p.measurement) << '\n';
  if (!p.tool.empty()) out << "# tool: " << one_line(p.tool) << '\n';
  if (!trace.label.empty()) out << "# label: " << one_line(trace.label) << '\n';
  out << "# total_channel: " << one_line(trace.total_channel) << '\n';
  for (const auto& [k, v] : p.settings) out << "# setting: " << one_line(k) << " = " << one_line(v) << '\n';
  char buf[64];
  for (const TracePhase& ph : trace.phases) {
    std::snprintf(buf, sizeof buf, "%.6f .. %.6f", ph.start_s, ph.end_s);
    out << "# phase: " << one_line(ph.name) << " = " << buf << '\n';
  }
  // A row where a read failed is left out (CSV readers take no NaN cells); the trace's integrals bridge it.
  std::size_t skipped = 0;
  const auto complete = [&](std::size_t i) {
    for (const PowerChannel& c : trace.channels)
      if (i >= c.values.size() || !std::isfinite(c.values[i])) return false;
    return true;
  };
  for (std::size_t i = 0; i < trace.time_s.size(); ++i) skipped += !complete(i);
  if (skipped) out << "# skipped_rows: " << skipped << " (a sensor read failed)\n";
  out << "time_s";
  for (const PowerChannel& c : trace.channels) out << ',' << recording_column(c.name);
  out << '\n';
  for (std::size_t i = 0; i < trace.time_s.size(); ++i) {
    if (!complete(i)) continue;
    std::snprintf(buf, sizeof buf, "%.6f", trace.time_s[i]);
    out << buf;
    for (const PowerChannel& c : trace.channels) {
      std::snprintf(buf, sizeof buf, "%.9g", c.values[i]);
      out << ',' << buf;
    }
    out << '\n';
  }
}

void save_recording_csv(const std::string& path, const PowerTrace& trace) {
  const std::string tmp = path + ".part";
  {
    std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
    if (!f) throw std::runtime_error("cannot write " + tmp);
    write_recording_csv(f, trace);
    f.flush();
    if (!f) throw std::runtime_error("write error on " + tmp);
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) throw std::runtime_error("cannot rename " + tmp + " to " + path + ": " + ec.message());
}

}  // namespace bs::sensors
