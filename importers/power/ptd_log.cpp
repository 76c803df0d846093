// SPDX-License-Identifier: GPL-3.0-or-later
#include "power/ptd_log.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <optional>
#include <vector>

#include "analysis/power/power_time.h"
#include "power/meter_log_text.h"
#include "power/power_line_reader.h"

namespace bs {
namespace {

using meter::trim;

constexpr std::size_t kMaxDates = 100'000;  // distinct days in one log (274 years of continuous logging)

// "12-23-2020" -> {12, 23, 2020}: which of the first two is the month is decided for the whole log at the end.
std::optional<std::array<int, 3>> date_fields(std::string_view d) {
  if (d.size() != 10 || d[2] != '-' || d[5] != '-') return std::nullopt;
  std::array<int, 3> out{};
  const std::array<std::string_view, 3> parts = {d.substr(0, 2), d.substr(3, 2), d.substr(6, 4)};
  for (std::size_t i = 0; i < 3; ++i) {
    double v = 0;
    if (!meter::number(parts[i], v) || parts[i].front() == '+' || parts[i].front() == '-') return std::nullopt;
    out[i] = static_cast<int>(v);
  }
  if (out[0] < 1 || out[1] < 1 || out[0] > 31 || out[1] > 31) return std::nullopt;
  return out;
}

// "10:21:51.496" -> seconds of the day.
std::optional<double> time_of_day(std::string_view t) {
  const auto epoch = parse_iso8601("1970-01-01T" + std::string(t));
  return epoch;
}

struct Slot {
  std::string group;  // "" or "Ch1"
  PowerQuantity quantity;
};

class PtdParser : meter::LineParserBase {
 public:
  using LineParserBase::LineParserBase;
  void line(std::string_view raw, std::size_t line_no, bool last);
  ImportBatch finish();

 private:
  std::vector<std::string_view> f_;
  std::vector<Slot> slots_;  // fixed by the first sample
  std::vector<double> values_;
  std::vector<std::array<int, 3>> dates_;
  std::vector<std::uint32_t> date_of_;  // per sample, index into dates_
  std::vector<double> seconds_;         // per sample, seconds of its day
  struct Run {
    std::string mark;
    std::size_t first, last;
  };
  std::vector<Run> runs_;
  PowerTrace trace_;
  std::size_t missing_ = 0;
  bool analyzers_ = false, unknown_keys_ = false;
};

void PtdParser::line(std::string_view raw, std::size_t line_no, bool last) {
  meter::split(trim(raw), ',', f_);
  if (f_.size() < 2 || f_[0] != "Time") return skip(line_no, "not a PTDaemon sample (no leading Time,)");
  const auto space = f_[1].find(' ');
  const auto date = space == std::string_view::npos ? std::nullopt : date_fields(f_[1].substr(0, space));
  const auto sod = space == std::string_view::npos ? std::nullopt : time_of_day(trim(f_[1].substr(space + 1)));
  if (!date || !sod) {
    if (last) return skip(line_no, "incomplete last line");
    fail(ImportErrorCategory::InvalidValue, line_no, "Time",
         "'" + std::string(f_[1]) + "' is not a PTDaemon time (expected MM-DD-YYYY HH:MM:SS.mmm)");
  }
  // Key/value pairs; "ChN" starts a channel group; "AnalyzerN" starts another analyzer's copy of the line.
  std::vector<Slot> slots;
  values_.clear();
  std::string group, mark;
  for (std::size_t i = 2; i < f_.size(); ++i) {
    const std::string_view key = f_[i];
    if (key.starts_with("Analyzer")) {
      analyzers_ = true;
      break;
    }
    if (key.size() > 2 && key.starts_with("Ch") && key.find_first_not_of("0123456789", 2) == std::string_view::npos) {
      group = std::string(key);
      continue;
    }
    if (i + 1 >= f_.size()) {
      if (last) return skip(line_no, "incomplete last line");
      fail(ImportErrorCategory::Syntax, line_no, std::string(key), "no value after '" + std::string(key) + "'");
    }
    const std::string_view value = f_[++i];
    if (key == "Mark") {
      if (group.empty()) mark = std::string(value);
      continue;
    }
    std::optional<PowerQuantity> q;
    if (key == "Watts")
      q = PowerQuantity::Power;
    else if (key == "Volts")
      q = PowerQuantity::Voltage;
    else if (key == "Amps")
      q = PowerQuantity::Current;
    if (!q) {
      unknown_keys_ = unknown_keys_ || key != "PF";
      continue;
    }
    double v = 0;
    if (!meter::number(value, v)) {
      if (last) return skip(line_no, "incomplete last line");
      fail(ImportErrorCategory::InvalidValue, line_no, (group.empty() ? "" : group + " ") + std::string(key),
           "'" + std::string(value) + "' is not a number");
    }
    if (v == -1.0) {  // PTDaemon's "no reading"
      v = std::numeric_limits<double>::quiet_NaN();
      ++missing_;
    }
    slots.push_back({group, *q});
    values_.push_back(v);
  }
  if (slots.empty()) {
    if (last) return skip(line_no, "incomplete last line");
    fail(ImportErrorCategory::MissingField, line_no, "Watts", "a Time without Watts, Volts or Amps");
  }
  if (slots_.empty()) {
    slots_ = slots;
    for (const Slot& s : slots_) {
      const char* what = s.quantity == PowerQuantity::Power     ? "power"
                         : s.quantity == PowerQuantity::Voltage ? "voltage"
                                                                : "current";
      trace_.channels.push_back({s.group.empty() ? what : s.group + " " + what, s.quantity, {}});
    }
  } else if (slots.size() != slots_.size() ||
             !std::equal(slots.begin(), slots.end(), slots_.begin(),
                         [](const Slot& a, const Slot& b) { return a.group == b.group && a.quantity == b.quantity; })) {
    if (last) return skip(line_no, "incomplete last line");
    fail(ImportErrorCategory::InvalidValue, line_no, "",
         "the channels differ from the first sample's (" + std::to_string(slots.size()) + " readings vs " +
             std::to_string(slots_.size()) + ")");
  }
  if (seconds_.size() >= limits_.max_samples)
    fail(ImportErrorCategory::TooLarge, line_no, "", "more than " + std::to_string(limits_.max_samples) + " samples");
  if (dates_.empty() || dates_.back() != *date) {
    if (dates_.size() >= kMaxDates) fail(ImportErrorCategory::TooLarge, line_no, "Time", "too many distinct days");
    dates_.push_back(*date);
  } else if (*sod < seconds_.back()) {
    fail(ImportErrorCategory::InvalidValue, line_no, "Time", "time goes backwards (" + std::string(f_[1]) + ")");
  }
  const std::size_t n = seconds_.size();
  date_of_.push_back(static_cast<std::uint32_t>(dates_.size() - 1));
  seconds_.push_back(*sod);
  for (std::size_t k = 0; k < values_.size(); ++k) trace_.channels[k].values.push_back(values_[k]);
  if (runs_.empty() || runs_.back().mark != mark) runs_.push_back({mark, n, n});
  runs_.back().last = n;
}

ImportBatch PtdParser::finish() {
  if (seconds_.empty())
    throw ImportError(ImportErrorCategory::MissingField, {file_, 0, 0, {}},
                      "no PTDaemon samples (lines Time,MM-DD-YYYY HH:MM:SS.mmm,Watts,...)");
  // PTDaemon writes month-day-year; a first field above 12 can only be a day.
  bool day_first = false, month_first = false;
  for (const auto& d : dates_) {
    day_first = day_first || d[0] > 12;
    month_first = month_first || d[1] > 12;
  }
  if (day_first && month_first)
    throw ImportError(ImportErrorCategory::InvalidValue, {file_, 0, 0, "Time"},
                      "dates fit neither MM-DD-YYYY nor DD-MM-YYYY throughout");
  std::vector<double> day_epoch(dates_.size());
  for (std::size_t i = 0; i < dates_.size(); ++i) {
    const auto& d = dates_[i];
    const int month = day_first ? d[1] : d[0], day = day_first ? d[0] : d[1];
    char iso[16];
    std::snprintf(iso, sizeof iso, "%04d-%02d-%02d", d[2] % 10000, month, day);
    const auto e = parse_iso8601(std::string(iso) + "T00:00:00");
    if (!e)
      throw ImportError(ImportErrorCategory::InvalidValue, {file_, 0, 0, "Time"}, std::string("no such date: ") + iso);
    day_epoch[i] = *e;
  }
  const double first = day_epoch[date_of_[0]] + seconds_[0];
  trace_.time_s.resize(seconds_.size());
  for (std::size_t i = 0; i < seconds_.size(); ++i) {
    trace_.time_s[i] = day_epoch[date_of_[i]] + seconds_[i] - first;
    if (i > 0 && trace_.time_s[i] < trace_.time_s[i - 1])
      throw ImportError(ImportErrorCategory::InvalidValue, {file_, 0, 0, "Time"},
                        "time goes backwards at sample " + std::to_string(i + 1));
  }
  trace_.start_time = format_iso8601(first);
  for (const Run& r : runs_)
    if (!r.mark.empty()) trace_.phases.push_back({r.mark, trace_.time_s[r.first], trace_.time_s[r.last]});
  more_skipped_warning();
  if (missing_ > 0)
    batch_.warnings.push_back(file_ + ": " + std::to_string(missing_) +
                              " readings of -1 (PTDaemon: no reading) are missing samples");
  if (analyzers_)
    batch_.warnings.push_back(file_ +
                              ": merged multi-analyzer lines: only the combined values before the first "
                              "AnalyzerN group are read");
  if (unknown_keys_) batch_.warnings.push_back(file_ + ": fields other than Watts, Volts, Amps, PF and Mark ignored");
  if (day_first) batch_.warnings.push_back(file_ + ": dates read as DD-MM-YYYY (a first field above 12)");
  trace_.platform = options_.platform;
  trace_.label = meter::file_name(file_);
  trace_.total_channel = "power";
  meter::stamp_log_provenance(trace_, file_, "SPEC PTDaemon", MeasurementKind::ExternalMeter,
                              "SPEC PTDaemon power analyzer: AC wall power of the whole system at the mains plug");
  // Alone, a PTDaemon log has no power window: MLPerf's mean is over LoadGen's power_begin..power_end only.
  batch_.warnings.push_back(file_ +
                            ": read on its own, without LoadGen's power window (mlperf_log_detail.txt's "
                            "power_begin/power_end): the mean is over the whole log, not MLPerf's; it is AC "
                            "wall power of a whole system, not a robot's DC supply");
  batch_.power_traces.push_back(std::move(trace_));
  return std::move(batch_);
}

}  // namespace

static int sniff_ptd_log(std::string_view head, std::string_view) {
  for (const std::string& line : meter::head_lines(head, 16)) {
    const std::string_view l = trim(line);
    if (l.starts_with("Time,") && l.find(",Watts,") != std::string_view::npos) return 95;
  }
  return 0;
}

const FileFormat kPtdLogFileFormat{"ptdaemon", "SPEC PTDaemon power log (MLPerf spl.txt)", sniff_ptd_log,
                                   meter::parse_log_file<PtdParser>, meter::parse_log_text<PtdParser>};

}  // namespace bs
