// SPDX-License-Identifier: GPL-3.0-or-later
#include "power/perf_stat.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <vector>

#include "analysis/power/power_time.h"
#include "model/reading_samples.h"
#include "power/meter_log_text.h"
#include "power/power_line_reader.h"

namespace bs {
namespace {

using meter::trim;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// "power/energy-pkg/" -> "pkg"; empty for any other event.
std::string_view rapl_domain(std::string_view event) {
  if (!event.starts_with("power/energy-") || !event.ends_with('/')) return {};
  event.remove_prefix(13);
  event.remove_suffix(1);
  return event;
}

// One count as perf printed it: the raw number text (converted once the file's decimal mark is known) or missing.
struct Record {
  std::optional<std::string_view> time;  // -I: seconds since perf started, as text
  std::string channel;                   // "pkg", "S0 pkg"; "duration_time" for that event
  std::string value;                     // empty: <not counted> / <not supported>
  std::string_view unit;
};

bool not_counted(std::string_view v) { return v == "<not counted>" || v == "<not supported>"; }

bool plain_number(std::string_view s) {
  double v = 0;
  return meter::number(s, v);
}

// Digits only, at least one.
bool all_digits(std::string_view d) {
  return !d.empty() && std::all_of(d.begin(), d.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// An interval time: digits, one decimal mark ('.' or a locale's ','), digits ("1.001078602", "1,001078602").
bool interval_time(std::string_view s) {
  const auto mark = s.find_first_of(".,");
  return mark != std::string_view::npos && all_digits(s.substr(0, mark)) && all_digits(s.substr(mark + 1));
}

// The prefix before the value: an interval time (a number first), then aggregation ids ("S0", "S0-D0-C1",
// "CPU3") and the count of CPUs aggregated (a number, dropped).
void read_prefix(const std::vector<std::string_view>& prefix, Record& r) {
  std::size_t i = 0;
  if (!prefix.empty() && interval_time(prefix[0])) {
    r.time = prefix[0];
    i = 1;
  }
  std::string id;
  for (; i < prefix.size(); ++i)
    if (!prefix[i].empty() && !plain_number(prefix[i])) id += (id.empty() ? "" : "-") + std::string(prefix[i]);
  if (!id.empty()) r.channel = id + " " + r.channel;
}

// The index of the first field naming an event read here (a RAPL domain, or duration_time); 0 when none. Both
// output forms write the value and its unit in the two fields before the event, so the search starts at the third.
std::size_t event_field(const std::vector<std::string_view>& f) {
  for (std::size_t k = 2; k < f.size(); ++k)
    if (!rapl_domain(f[k]).empty() || f[k] == "duration_time") return k;
  return 0;
}

// The record of the event at f[k]: its channel, and its unit from the field before; the caller reads the value.
Record event_record(const std::vector<std::string_view>& f, std::size_t k) {
  const std::string_view domain = rapl_domain(f[k]);
  Record r;
  r.channel = domain.empty() ? "duration_time" : std::string(domain);
  r.unit = f[k - 1];
  return r;
}

// "-x," output: [time,][aggregation,]value,unit,event,run time,percent,...
std::optional<Record> csv_record(std::string_view line, std::vector<std::string_view>& f) {
  if (line.find(',') == std::string_view::npos) return std::nullopt;
  meter::split(line, ',', f);
  const std::size_t k = event_field(f);
  if (k == 0) return std::nullopt;
  Record r = event_record(f, k);
  if (!not_counted(f[k - 2])) r.value = std::string(f[k - 2]);
  read_prefix({f.begin(), f.begin() + static_cast<std::ptrdiff_t>(k - 2)}, r);
  return r;
}

// Human-readable: [time] [aggregation count] value unit event [# ...] [(100.00%)]
std::optional<Record> human_record(std::string_view line, std::vector<std::string_view>& t) {
  meter::tokens(line, t);
  const std::size_t k = event_field(t);
  if (k == 0) return std::nullopt;
  Record r = event_record(t, k);
  std::size_t value_at = k - 2;
  if ((t[k - 2] == "counted>" || t[k - 2] == "supported>") && k >= 3 && t[k - 3] == "<not") {
    value_at = k - 3;
  } else {
    r.value = std::string(t[k - 2]);
    // A locale that groups thousands with a space splits "5 005,68" in two tokens: put the groups back together
    // (only where no aggregation id precedes them, so the "1" of "S0 1 3.73" stays a CPU count).
    const std::size_t first = !t.empty() && interval_time(t[0]) && value_at > 0 ? 1 : 0;
    bool ids = false;
    for (std::size_t i = first; i < value_at; ++i) ids = ids || !all_digits(t[i]);
    while (!ids && value_at > first && t[value_at - 1].size() <= 3 && all_digits(t[value_at - 1]) &&
           r.value.size() >= 3 && all_digits(std::string_view(r.value).substr(0, 3)) &&
           (r.value.size() == 3 || r.value[3] == ',' || r.value[3] == '.')) {
      r.value = std::string(t[value_at - 1]) + r.value;
      --value_at;
    }
  }
  read_prefix({t.begin(), t.begin() + static_cast<std::ptrdiff_t>(value_at)}, r);
  return r;
}

// perf prints numbers with the locale's grouping: "2,306.32" (C), "1.373,00" or "5 005,68" (decimal comma).
bool locale_number(std::string_view text, bool decimal_comma, double& v) {
  std::string s;
  for (char c : text) {
    if (decimal_comma ? (c == '.' || c == ' ' || (c & 0x80)) : c == ',') continue;  // grouping (incl. U+202F bytes)
    s += decimal_comma && c == ',' ? '.' : c;
  }
  return meter::number(s, v);
}

bool has_decimal_comma(std::string_view number) {
  return number.find(',') != std::string_view::npos && number.find('.') == std::string_view::npos;
}

// "# started on Sun Aug 24 12:00:00 2026" -> seconds since the epoch (local time, as written).
std::optional<double> started_on(std::string_view line) {
  static constexpr std::string_view months[] = {"Jan", "Feb", "Mar", "Apr", "May", "Jun",
                                                "Jul", "Aug", "Sep", "Oct", "Nov", "Dec"};
  std::vector<std::string_view> t;
  meter::tokens(line, t);
  if (t.size() != 8) return std::nullopt;  // "#" "started" "on" weekday month day time year
  unsigned month = 0;
  for (unsigned m = 0; m < 12; ++m)
    if (t[4] == months[m]) month = m + 1;
  double day = 0, year = 0;
  if (month == 0 || !meter::number(t[5], day) || !meter::number(t[7], year) || day < 1 || day > 31 || year < 1970 ||
      year > 9999 || t[6].size() != 8)
    return std::nullopt;
  char iso[32];
  std::snprintf(iso, sizeof iso, "%04d-%02u-%02dT", static_cast<int>(year), month, static_cast<int>(day));
  return parse_iso8601(std::string(iso) + std::string(t[6]));
}

struct Channel {
  std::string name;
  std::vector<double> joules;  // per interval (NaN: not counted)
};

class PerfStatParser : meter::LineParserBase {
 public:
  using LineParserBase::LineParserBase;
  void line(std::string_view raw, std::size_t line_no, bool last);
  ImportBatch finish();

 private:
  void interval_record(const Record& r, std::size_t line_no);
  void close_block(std::optional<double> elapsed, std::size_t line_no);
  Channel& channel(const std::string& name, std::size_t intervals);
  PowerTrace make_trace(const std::vector<double>& ends) const;

  std::vector<std::string_view> scratch_;
  std::optional<bool> interval_mode_;
  bool decimal_comma_ = false, comma_known_ = false;
  std::optional<double> start_epoch_;
  std::string runs_;
  // Interval mode: the end time of each interval; summary mode: the records of the open block.
  std::vector<double> ends_;
  std::vector<Channel> channels_;
  struct Pending {
    std::string channel, value, unit;
    std::size_t line_no;
  };
  std::vector<Pending> block_;
  std::size_t records_ = 0;
};

Channel& PerfStatParser::channel(const std::string& name, std::size_t intervals) {
  for (Channel& c : channels_)
    if (c.name == name) return c;
  Channel& c = channels_.emplace_back();
  c.name = name;
  c.joules.assign(intervals, kNaN);
  return c;
}

void PerfStatParser::interval_record(const Record& r, std::size_t line_no) {
  if (!comma_known_) {
    decimal_comma_ = has_decimal_comma(*r.time);
    comma_known_ = true;
  }
  double t = 0;
  if (!locale_number(*r.time, decimal_comma_, t) || t < 0)
    fail(ImportErrorCategory::InvalidValue, line_no, "time", "'" + std::string(*r.time) + "' is not an interval time");
  if (ends_.empty() || t > ends_.back()) {
    if (ends_.size() >= limits_.max_samples)
      fail(ImportErrorCategory::TooLarge, line_no, "",
           "more than " + std::to_string(limits_.max_samples) + " intervals");
    ends_.push_back(t);
  } else if (t < ends_.back()) {
    fail(ImportErrorCategory::InvalidValue, line_no, "time", "time goes backwards (" + std::string(*r.time) + " s)");
  }
  Channel& c = channel(r.channel, ends_.size() - 1);
  if (c.joules.size() == ends_.size())
    fail(ImportErrorCategory::Syntax, line_no, r.channel,
         "the event appears twice in the interval ending at " + std::string(*r.time) + " s");
  c.joules.resize(ends_.size() - 1, kNaN);
  double j = kNaN;
  if (!r.value.empty() && !locale_number(r.value, decimal_comma_, j))
    fail(ImportErrorCategory::InvalidValue, line_no, r.channel, "'" + std::string(r.value) + "' is not a count");
  c.joules.push_back(j);
}

void PerfStatParser::line(std::string_view raw, std::size_t line_no, bool last) {
  const std::string_view l = trim(raw);
  if (l.starts_with("# started on")) {
    start_epoch_ = started_on(l);
    return;
  }
  if (l.starts_with('#')) return;  // the "#  time  counts unit events" header of -I
  if (l.find("Performance counter stats for") != std::string_view::npos) {
    if (!block_.empty()) close_block(std::nullopt, line_no);
    if (const auto open = l.rfind(" runs)"); open != std::string_view::npos) {
      const auto from = l.rfind('(', open);
      if (from != std::string_view::npos) runs_ = std::string(l.substr(from + 1, open - from - 1));
    }
    return;
  }
  if (l.find("seconds time elapsed") != std::string_view::npos) {
    meter::tokens(l, scratch_);
    if (block_.empty()) return;  // a block without RAPL events
    if (!comma_known_) decimal_comma_ = has_decimal_comma(scratch_[0]);
    double elapsed = 0;
    if (!locale_number(scratch_[0], decimal_comma_, elapsed) || !(elapsed > 0))
      fail(ImportErrorCategory::InvalidValue, line_no, "seconds time elapsed",
           "'" + std::string(scratch_[0]) + "' is not an elapsed time in s");
    return close_block(elapsed, line_no);
  }
  std::optional<Record> r = csv_record(l, scratch_);
  if (!r) r = human_record(l, scratch_);
  if (!r) return;  // not a RAPL count: another event, or the measured program's own output
  if (r->channel != "duration_time" && r->unit != "Joules") {
    if (last) return;  // cut off
    fail(ImportErrorCategory::InvalidValue, line_no, r->channel,
         "unit '" + std::string(r->unit) + "' for a RAPL energy event (perf prints Joules)");
  }
  ++records_;
  const bool interval = r->time.has_value();
  if (!interval_mode_) interval_mode_ = interval;
  if (*interval_mode_ != interval)
    fail(ImportErrorCategory::Syntax, line_no, "",
         interval ? "an interval (-I) count after summary counts" : "a summary count after interval (-I) counts");
  if (interval) return interval_record(*r, line_no);
  if (block_.size() >= 4096) fail(ImportErrorCategory::TooLarge, line_no, "", "more than 4096 counts in one block");
  block_.push_back({r->channel, r->value, std::string(r->unit), line_no});
}

// The trace of one interval series: two samples per interval (start, end) holding the interval's mean power.
PowerTrace PerfStatParser::make_trace(const std::vector<double>& ends) const {
  PowerTrace t;
  for (std::size_t i = 0; i < ends.size(); ++i) {
    t.time_s.push_back(i == 0 ? 0.0 : ends[i - 1]);
    t.time_s.push_back(ends[i]);
  }
  for (const Channel& c : channels_) {
    if (c.name == "duration_time") continue;
    PowerChannel pc{c.name, PowerQuantity::Power, {}};
    for (std::size_t i = 0; i < ends.size(); ++i) {
      const double len = ends[i] - (i == 0 ? 0.0 : ends[i - 1]);
      const double j = i < c.joules.size() ? c.joules[i] : kNaN;
      const double p = len > 0 ? j / len : kNaN;
      pc.values.push_back(p);
      pc.values.push_back(p);
    }
    t.channels.push_back(std::move(pc));
  }
  return t;
}

void PerfStatParser::close_block(std::optional<double> elapsed, std::size_t line_no) {
  for (const Pending& p : block_) {
    double ns = 0;  // duration_time: nanoseconds, when -e duration_time was asked for
    if (!elapsed && p.channel == "duration_time" && locale_number(p.value, decimal_comma_, ns) && ns > 0)
      elapsed = ns * 1e-9;
  }
  if (!elapsed)
    fail(ImportErrorCategory::MissingField, line_no, "seconds time elapsed",
         "energy counts without the elapsed time: perf stat -x prints none; record with -I 1000 (or add -e "
         "duration_time), or keep perf's 'seconds time elapsed' line");
  channels_.clear();
  for (const Pending& p : block_) {
    if (p.channel == "duration_time") continue;
    double j = kNaN;
    if (!p.value.empty() && !locale_number(p.value, decimal_comma_, j))
      fail(ImportErrorCategory::InvalidValue, p.line_no, p.channel, "'" + p.value + "' is not a count");
    Channel& c = channel(p.channel, 0);
    if (!c.joules.empty())
      fail(ImportErrorCategory::Syntax, p.line_no, p.channel, "the event appears twice in one block");
    c.joules.push_back(j);
  }
  if (!channels_.empty()) batch_.power_traces.push_back(make_trace({*elapsed}));
  block_.clear();
  channels_.clear();
}

ImportBatch PerfStatParser::finish() {
  if (!block_.empty()) close_block(std::nullopt, 0);
  if (interval_mode_ && *interval_mode_ && !ends_.empty()) {
    for (Channel& c : channels_) c.joules.resize(ends_.size(), kNaN);
    batch_.power_traces.push_back(make_trace(ends_));
  }
  if (batch_.power_traces.empty())
    throw ImportError(ImportErrorCategory::MissingField, {file_, 0, 0, {}},
                      "no RAPL energy counts (power/energy-pkg/, ...); record with perf stat -a -e "
                      "power/energy-pkg/,power/energy-ram/ -I 1000");
  const std::string label = meter::file_name(file_);
  std::size_t missing = 0, n = 0;
  for (PowerTrace& t : batch_.power_traces) {
    ++n;
    t.platform = options_.platform;
    t.label = batch_.power_traces.size() > 1 ? label + " #" + std::to_string(n) : label;
    // The whole platform (psys) when it reads anything, else the CPU package.
    const auto reads = [](const PowerChannel& c) {
      return std::any_of(c.values.begin(), c.values.end(), [](double v) { return v > 0; });
    };
    std::size_t packages = 0;
    for (const PowerChannel& c : t.channels) {
      const bool psys = c.name == "psys" || c.name.ends_with(" psys");
      const bool pkg = c.name == "pkg" || c.name.ends_with(" pkg");
      packages += pkg;
      if (psys && reads(c)) t.total_channel = c.name;
      if (pkg && (t.total_channel.empty())) t.total_channel = c.name;
      for (double v : c.values) missing += std::isnan(v);
    }
    if (packages > 1 && t.total_channel.find("psys") == std::string::npos)
      batch_.warnings.push_back(file_ + ": " + std::to_string(packages) +
                                " packages counted separately; the total "
                                "channel is '" +
                                t.total_channel + "', add the others for the whole machine");
    // The total first as well: readers that take the first power channel (as before total_channel) agree.
    std::stable_partition(t.channels.begin(), t.channels.end(),
                          [&](const PowerChannel& c) { return c.name == t.total_channel; });
    if (start_epoch_) t.start_time = format_iso8601(*start_epoch_);
    meter::stamp_log_provenance(t, file_, "perf stat", MeasurementKind::OnBoardSensor, "RAPL (perf stat)");
    auto& p = t.provenance;
    if (!runs_.empty()) p.settings.emplace_back("runs", runs_);
    p.settings.emplace_back(kSamplesPerReadingSetting, "2");  // each reading is an interval's start and end
    p.note = interval_mode_ && *interval_mode_ ? "mean power of each perf stat -I interval (energy / interval length)"
                                               : "mean power over the run (energy / elapsed time)";
  }
  if (missing > 0)
    batch_.warnings.push_back(file_ + ": " + std::to_string(missing / 2) +
                              " counts <not counted> or <not supported> "
                              "are missing samples");
  return std::move(batch_);
}

}  // namespace

static int sniff_perf_stat(std::string_view head, std::string_view) {
  std::vector<std::string_view> scratch;
  int score = 0;
  for (const std::string& line : meter::head_lines(head, 256)) {
    const std::string_view l = trim(line);
    std::optional<Record> r = csv_record(l, scratch);
    if (!r) r = human_record(l, scratch);
    if (r && r->channel != "duration_time") return 95;
    // perf stat without RAPL events: still ours, so that parse() can say what is missing.
    if (l.find("Performance counter stats for") != std::string_view::npos) score = 30;
  }
  return score;
}

const FileFormat kPerfStatFileFormat{"perf-stat-rapl", "perf stat RAPL energy (power/energy-pkg/ ...)", sniff_perf_stat,
                                     meter::parse_log_file<PerfStatParser>, meter::parse_log_text<PerfStatParser>};

}  // namespace bs
