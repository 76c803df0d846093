// SPDX-License-Identifier: GPL-3.0-or-later
#include "power/jtop_csv.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <optional>
#include <set>
#include <vector>

#include "analysis/power/power_time.h"
#include "power/jetson_rail_limits.h"
#include "power/log_sustain.h"
#include "power/meter_log_text.h"
#include "power/power_line_reader.h"
#include "util/text.h"

namespace bs {
namespace {

// Past this many, warnings of one kind are counted instead of listed one by one.
constexpr std::size_t kListedWarnings = 10;

struct Cell {
  std::string text;
  std::size_t column = 1;  // 1-based byte column of the cell's start in the line
};

// One CSV row as Python's csv module writes it (excel dialect): ',' separated, '"' quotes a cell that holds a
// comma or a quote, '""' is a quote inside one. Returns false on an unterminated quote.
bool split_row(std::string_view line, std::vector<Cell>& out) {
  out.clear();
  std::size_t i = 0;
  while (true) {
    Cell cell;
    cell.column = i + 1;
    if (i < line.size() && line[i] == '"') {
      i = meter::read_quoted(line, i, cell.text);
      if (i == std::string_view::npos) return false;
      // Text after the closing quote up to the separator belongs to the cell, as Python reads it.
      while (i < line.size() && line[i] != ',') cell.text += line[i++];
    } else {
      const std::size_t end = std::min(line.find(',', i), line.size());
      cell.text.assign(line.substr(i, end - i));
      i = end;
    }
    out.push_back(std::move(cell));
    if (i >= line.size()) return true;
    ++i;  // the comma
    if (i == line.size()) {
      out.push_back({std::string(), i + 1});
      return true;
    }
  }
}

using meter::trim;

std::optional<double> number(std::string_view s) {
  s = trim(s);
  if (s.empty()) return std::nullopt;
  double v = 0;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  if (r.ptr != s.data() + s.size()) return std::nullopt;
  if (r.ec == std::errc::result_out_of_range) return std::numeric_limits<double>::infinity();
  if (r.ec != std::errc()) return std::nullopt;
  return v;
}

// str(datetime.timedelta): "22:47:52.710000", "1 day, 2:03:04", "3 days, 0:07:35.540000" -> seconds.
std::optional<double> parse_timedelta(std::string_view s) {
  s = trim(s);
  double days = 0;
  if (const std::size_t comma = s.find(','); comma != std::string_view::npos) {
    std::string_view d = trim(s.substr(0, comma));
    if (d.ends_with("days"))
      d.remove_suffix(4);
    else if (d.ends_with("day"))
      d.remove_suffix(3);
    else
      return std::nullopt;
    const auto n = number(d);
    if (!n || !std::isfinite(*n) || *n != std::floor(*n)) return std::nullopt;
    days = *n;
    s = trim(s.substr(comma + 1));
  }
  const std::size_t c1 = s.find(':');
  const std::size_t c2 = c1 == std::string_view::npos ? c1 : s.find(':', c1 + 1);
  if (c2 == std::string_view::npos) return std::nullopt;
  const auto h = number(s.substr(0, c1));
  const auto m = number(s.substr(c1 + 1, c2 - c1 - 1));
  const auto sec = number(s.substr(c2 + 1));
  if (!h || !m || !sec || *h < 0 || *h > 23 || *m < 0 || *m > 59 || *sec < 0 || *sec >= 60) return std::nullopt;
  return days * 86400.0 + *h * 3600.0 + *m * 60.0 + *sec;
}

enum class Role { Ignored, Time, Uptime, Total, Rail, Setting, Temperature, Clock };

struct Column {
  std::string name;
  Role role = Role::Ignored;
  std::size_t channel = 0;  // Total/Rail: index into trace.channels; Setting: into settings; Temperature/Clock: series
};

// jetson-stats' value for a sensor it cannot read (jtop/core/temperature.py TEMPERATURE_OFFLINE).
constexpr double kNoReadingC = -256;
constexpr double kMinC = -100, kMaxC = 200;  // outside: not a reading of a working sensor
constexpr double kMaxMhz = 100'000;

// The engine columns jetson-stats writes, each its engine's clock ("OFF" when the engine is off): jtop.py's stats
// puts engine['cur'] there. The CPU, GPU and EMC columns are loads, not clocks.
bool engine_column(std::string_view n) {
  for (std::string_view e : {"APE", "NVENC", "NVDEC", "NVJPG", "NVJPG1", "VIC", "OFA", "SE", "MSENC", "CVNAS"})
    if (n == e) return true;
  for (std::string_view prefix : {"DLA", "NVDLA", "PVA"})
    if (n.starts_with(prefix)) return true;
  return false;
}

bool is_total(std::string_view name) { return name == "Power TOT" || name == "power cur"; }

class JtopParser {
 public:
  JtopParser(const std::string& file, const ParseOptions& options, const ImportLimits& limits)
      : file_(file), options_(options), limits_(limits) {}
  void line(std::string_view raw, std::size_t line_no, bool last);
  ImportBatch finish();

 private:
  [[noreturn]] void fail(ImportErrorCategory category, std::size_t line_no, std::size_t column, std::string field,
                         const std::string& why) const {
    throw ImportError(category, {file_, line_no, column, std::move(field)}, why);
  }
  void header(std::size_t line_no);
  void warn(std::size_t& count, std::size_t line_no, const std::string& what) {
    if (++count <= kListedWarnings) batch_.warnings.push_back(file_ + ":" + std::to_string(line_no) + ": " + what);
  }

  const std::string& file_;
  const ParseOptions& options_;
  const ImportLimits& limits_;
  std::vector<Cell> cells_;
  std::vector<Column> columns_;
  bool have_header_ = false;
  bool old_format_ = false;  // "power cur" (jetson-stats up to 4.1) instead of "Power TOT"
  std::size_t time_col_ = 0;
  Role time_role_ = Role::Ignored;
  double first_time_ = 0;
  std::size_t missing_ = 0, setting_changes_ = 0;
  std::vector<std::string> setting_last_;
  // Clocks (MHz) and temperatures (C) of the rows (#53); one value per row.
  std::vector<meter::SampleSeries::Series> clocks_, temps_;
  std::size_t bad_sensor_ = 0, no_reading_ = 0;
  void sensor_cell(const Column& c, const Cell& cell, std::size_t line_no);
  PowerTrace trace_;
  ImportBatch batch_;
};

void JtopParser::header(std::size_t line_no) {
  std::size_t total = 0;
  std::size_t time = 0, uptime = 0;
  std::set<std::string> seen;  // a set, not a scan: a fuzzed header can have a million columns
  for (std::size_t k = 0; k < cells_.size(); ++k) {
    Column c;
    c.name = std::string(trim(cells_[k].text));
    if (!c.name.empty() && !seen.insert(c.name).second)
      fail(ImportErrorCategory::Syntax, line_no, cells_[k].column, c.name, "the column name appears twice");
    if (c.name == "time") {
      c.role = Role::Time;
      time = k + 1;
    } else if (c.name == "uptime") {
      c.role = Role::Uptime;
      uptime = k + 1;
    } else if (is_total(c.name)) {
      c.role = Role::Total;
      old_format_ = c.name == "power cur";
      ++total;
    } else if (c.name.starts_with("Power ") && c.name.size() > 6) {
      c.role = Role::Rail;
    } else if (c.name == "nvp model" || c.name == "jetson_clocks") {
      c.role = Role::Setting;
    } else if (c.name.starts_with("Temp ") && c.name.size() > 5 && c.name != "Temp PMIC") {
      // PMIC is not a measurement (it reports only crossing 120 or 140 C); jetson-stats drops it, so do we.
      c.role = Role::Temperature;
    } else if (engine_column(c.name)) {
      c.role = Role::Clock;
    }
    columns_.push_back(std::move(c));
  }
  if (total != 1)
    fail(ImportErrorCategory::MissingField, line_no, 1, "Power TOT",
         total == 0 ? "no board total column (\"Power TOT\", or \"power cur\" before jetson-stats 4.2): not a jtop "
                      "power log, or jtop ran without access to the power monitors"
                    : "both \"Power TOT\" and \"power cur\": two totals");
  if (time == 0 && uptime == 0)
    fail(ImportErrorCategory::MissingField, line_no, 1, "time", "no \"time\" or \"uptime\" column");
  time_role_ = time ? Role::Time : Role::Uptime;
  time_col_ = (time ? time : uptime) - 1;
  // The total first: power_series() and every view take it as the board's power.
  for (Column& c : columns_)
    if (c.role == Role::Total) {
      c.channel = trace_.channels.size();
      trace_.channels.push_back({c.name, PowerQuantity::Power, {}});
    }
  for (Column& c : columns_)
    if (c.role == Role::Rail) {
      c.channel = trace_.channels.size();
      trace_.channels.push_back({c.name, PowerQuantity::Power, {}});
    } else if (c.role == Role::Temperature) {
      c.channel = temps_.size();
      temps_.push_back({c.name.substr(5), {}});
    } else if (c.role == Role::Clock) {
      c.channel = clocks_.size();
      clocks_.push_back({c.name, {}});
    } else if (c.role == Role::Setting) {
      c.channel = trace_.provenance.settings.size();
      trace_.provenance.settings.emplace_back(c.name, std::string());
      setting_last_.emplace_back();
    }
  have_header_ = true;
}

void JtopParser::line(std::string_view raw, std::size_t line_no, bool last) {
  if (!split_row(raw, cells_)) {
    if (last && have_header_) {
      batch_.warnings.push_back(file_ + ":" + std::to_string(line_no) +
                                ": cut-off last row (unterminated quote); skipped");
      return;
    }
    fail(ImportErrorCategory::Syntax, line_no, raw.size() + 1, {}, "unterminated quote");
  }
  if (!have_header_) return header(line_no);
  if (cells_.size() != columns_.size()) {
    if (last && cells_.size() < columns_.size()) {
      batch_.warnings.push_back(file_ + ":" + std::to_string(line_no) + ": cut-off last row (" +
                                std::to_string(cells_.size()) + " of " + std::to_string(columns_.size()) +
                                " cells; the logger stopped while writing it); skipped");
      return;
    }
    fail(ImportErrorCategory::Syntax, line_no, cells_.size() > columns_.size() ? cells_[columns_.size()].column : 1, {},
         std::to_string(cells_.size()) + " cells, the header has " + std::to_string(columns_.size()));
  }
  if (trace_.time_s.size() >= limits_.max_samples)
    fail(ImportErrorCategory::TooLarge, line_no, 1, {},
         "more than " + std::to_string(limits_.max_samples) + " rows (the limit for one log)");

  const Cell& tc = cells_[time_col_];
  const Column& tcol = columns_[time_col_];
  const std::optional<double> stamp =
      time_role_ == Role::Time ? parse_iso8601(trim(tc.text)) : parse_timedelta(tc.text);
  if (!stamp)
    fail(ImportErrorCategory::InvalidValue, line_no, tc.column, tcol.name,
         "'" + tc.text + "' is not a " +
             (time_role_ == Role::Time ? std::string("date-time (like 2025-12-16 17:14:33.703152)")
                                       : std::string("duration (like 3 days, 0:07:35.540000)")));
  if (trace_.time_s.empty()) {
    first_time_ = *stamp;
    if (time_role_ == Role::Time) trace_.start_time = format_iso8601(*stamp);
  }
  const double t = *stamp - first_time_;
  if (!trace_.time_s.empty() && t < trace_.time_s.back())
    fail(ImportErrorCategory::InvalidValue, line_no, tc.column, tcol.name, "time goes backwards ('" + tc.text + "')");

  // Check every cell before storing any, so the channels stay the same length whatever throws.
  for (std::size_t k = 0; k < columns_.size(); ++k) {
    const Column& c = columns_[k];
    if (c.role != Role::Total && c.role != Role::Rail) continue;
    if (trim(cells_[k].text).empty()) continue;
    const auto mw = number(cells_[k].text);
    if (!mw || std::isnan(*mw))
      fail(ImportErrorCategory::InvalidValue, line_no, cells_[k].column, c.name,
           "'" + cells_[k].text + "' is not a power in mW");
    if (!plausible_rail_milliwatts(*mw))
      fail(ImportErrorCategory::InvalidValue, line_no, cells_[k].column, c.name,
           "'" + cells_[k].text + "' mW is not a possible reading (" + std::string(kRailBoundText) +
               "); the log is corrupt");
  }
  trace_.time_s.push_back(t);
  for (std::size_t k = 0; k < columns_.size(); ++k) {
    const Column& c = columns_[k];
    if (c.role == Role::Total || c.role == Role::Rail) {
      const auto mw = number(cells_[k].text);
      if (!mw) warn(missing_, line_no, "'" + c.name + "' is empty; kept as a missing sample");
      trace_.channels[c.channel].values.push_back(mw ? *mw / 1000.0 : std::nan(""));
    } else if (c.role == Role::Setting) {
      const std::string value(trim(cells_[k].text));
      std::string& last_value = setting_last_[c.channel];
      std::string& stated = trace_.provenance.settings[c.channel].second;
      if (trace_.time_s.size() == 1) {
        stated = value;
      } else if (value != last_value) {
        warn(setting_changes_, line_no, c.name + " changed from '" + last_value + "' to '" + value + "'");
        stated += " then " + value;
      }
      last_value = value;
    } else if (c.role == Role::Temperature || c.role == Role::Clock) {
      sensor_cell(c, cells_[k], line_no);
    }
  }
}

// A temperature (C; -256: no sensor) or an engine clock ("OFF", else kHz since jetson-stats 4.2, which reads
// clk_rate / 1000; MHz before, copied from tegrastats). Not power: one that does not parse is a warning and NaN, the
// row's power stays.
void JtopParser::sensor_cell(const Column& c, const Cell& cell, std::size_t line_no) {
  const std::string_view text = trim(cell.text);
  const std::optional<double> v = number(text);
  double value = std::nan("");
  std::string why;
  if (c.role == Role::Temperature) {
    if (v && *v == kNoReadingC)
      ++no_reading_;
    else if (v && *v >= kMinC && *v <= kMaxC)
      value = *v;
    else if (!text.empty())
      why = "'" + cell.text + "' is not a temperature in C";
    temps_[c.channel].values.push_back(value);
  } else {
    const double mhz = v ? (old_format_ ? *v : *v / 1000.0) : std::nan("");
    if (v && mhz > 0 && mhz <= kMaxMhz)
      value = mhz;
    else if (text != "OFF" && !text.empty() && !(v && *v == 0))
      why = "'" + cell.text + "' is not an engine clock (" + (old_format_ ? "MHz" : "kHz") + ", or OFF)";
    clocks_[c.channel].values.push_back(value);
  }
  if (!why.empty() && ++bad_sensor_ <= kListedWarnings)
    batch_.warnings.push_back(file_ + ":" + std::to_string(line_no) + ":" + std::to_string(cell.column) + ": " +
                              c.name + ": " + why + "; kept as missing");
}

ImportBatch JtopParser::finish() {
  if (!have_header_) throw ImportError(ImportErrorCategory::MissingField, {file_, 0, 0, {}}, "no header row");
  if (trace_.time_s.empty())
    throw ImportError(ImportErrorCategory::MissingField, {file_, 0, 0, {}}, "a header but no rows");
  if (missing_ > kListedWarnings)
    batch_.warnings.push_back(file_ + ": " + std::to_string(missing_ - kListedWarnings) + " more empty power cells");
  if (setting_changes_ > kListedWarnings)
    batch_.warnings.push_back(file_ + ": " + std::to_string(setting_changes_ - kListedWarnings) +
                              " more setting changes");
  trace_.total_channel = trace_.channels.front().name;
  // The log names no board model (only the family, by its format): the platform is what the user gives, else the
  // import asks or guesses (issue #43.3: a TX2's and an Orin's logs must not become one platform "Jetson").
  trace_.platform = options_.platform;
  trace_.label = meter::file_name(file_);
  meter::stamp_log_provenance(trace_, file_, old_format_ ? "jetson-stats (jtop) before 4.2" : "jetson-stats (jtop)",
                              MeasurementKind::OnBoardSensor, "INA3221 (jetson-stats)");
  Provenance& p = trace_.provenance;
  p.note = "board total = " + trace_.total_channel +
           " as jetson-stats computes it (the input rail VDD_IN / POM_5V_IN where the board has one, else the sum of "
           "the rails); the rails are its parts and are never added to it";
  if (old_format_) p.note += "; \"power avg\" (jtop's running average since it started) is not imported";
  if (time_role_ == Role::Uptime) p.note += "; times from the uptime column (no \"time\" column)";
  if (bad_sensor_ > kListedWarnings)
    batch_.warnings.push_back(file_ + ": " + std::to_string(bad_sensor_ - kListedWarnings) +
                              " more temperature or clock cells that do not parse, kept as missing");
  meter::LogSensors sensors;
  sensors.clocks_mhz = std::move(clocks_);
  sensors.celsius = std::move(temps_);
  sensors.not_exposed.push_back(
      "no CPU or GPU clock: jetson-stats' CSV holds their loads (CPU1..., GPU), not their clocks");
  sensors.notes.push_back(std::string("engine clocks from the engine columns (") + (old_format_ ? "MHz" : "kHz") +
                          "; OFF kept as missing)");
  if (no_reading_)
    sensors.notes.push_back(std::to_string(no_reading_) +
                            " temperatures of -256 C (jetson-stats' 'no sensor') kept as missing");
  if (auto run = meter::log_sustain_run(trace_, std::move(sensors))) batch_.sustain_runs.push_back(std::move(*run));
  batch_.power_traces.push_back(std::move(trace_));
  return std::move(batch_);
}

}  // namespace

static int sniff_jtop_csv(std::string_view head, std::string_view) {
  PowerLineReader lines(head, {});
  std::vector<Cell> cells;
  while (const auto line = lines.next()) {
    if (trim(*line).empty()) continue;
    if (!split_row(*line, cells)) return 0;
    bool total = false, time = false, jetson = false;
    for (const Cell& c : cells) {
      const std::string_view n = trim(c.text);
      total = total || is_total(n);
      time = time || n == "time" || n == "uptime";
      jetson = jetson || n == "nvp model" || n == "jetson_clocks" || n.starts_with("Temp ") || n == "CPU1";
    }
    // Above power-csv's best (70): a jtop header also has columns power-csv would read as time and power.
    return total && time && jetson ? 95 : total && time ? 60 : 0;
  }
  return 0;
}

const FileFormat kJtopCsvFileFormat{"jtop-csv",
                                    "jetson-stats (jtop) CSV log (Jetson power)",
                                    sniff_jtop_csv,
                                    meter::parse_log_file<JtopParser>,
                                    meter::parse_log_text<JtopParser>,
                                    ".csv"};

}  // namespace bs
