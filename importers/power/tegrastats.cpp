// SPDX-License-Identifier: GPL-3.0-or-later
#include "power/tegrastats.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <optional>
#include <vector>

#include "analysis/power/power_time.h"
#include "power/jetson_rail_limits.h"
#include "power/meter_log_text.h"
#include "power/power_line_reader.h"
#include "power/tegrastats_sensors.h"

namespace bs {
namespace {

// Past this many, skipped lines are counted instead of listed one by one.

// Rail names are upper case: VDD_IN, POM_5V_GPU, VIN_SYS_5V0, and on AGX Xavier plain GPU, CPU, SOC, SYS5V.
bool rail_name(std::string_view t) {
  return t.size() >= 2 && t.front() >= 'A' && t.front() <= 'Z' && std::all_of(t.begin(), t.end(), [](char c) {
           return (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
         });
}

// One number of a rail reading: "3981", "5000mW", "-392mW" (AGX Thor near zero). std::from_chars reads any
// length, so a 20-digit value parses (as 1e20) and is caught by the plausibility bound, never wrapped.
enum class Reading { NotANumber, Ok, OutOfRange };

Reading milliwatts(std::string_view s, double& v) {
  if (s.ends_with("mW")) s.remove_suffix(2);
  const bool negative = !s.empty() && s.front() == '-';
  const std::string_view digits = negative ? s.substr(1) : s;
  if (digits.empty() || digits.front() < '0' || digits.front() > '9') return Reading::NotANumber;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  if (r.ptr != s.data() + s.size()) return Reading::NotANumber;
  if (r.ec == std::errc::result_out_of_range || !std::isfinite(v) || !plausible_rail_milliwatts(v))
    return Reading::OutOfRange;
  return r.ec == std::errc() ? Reading::Ok : Reading::NotANumber;
}

// "3981/3981" (JetPack 4, mW), "5000mW/5000mW" (JetPack 5/6, cur/avg) or "4385mW/3787mW/4385mW" (JetPack 7,
// cur/avg/max) -> the instantaneous (first) value in mW. "2448/7854MB" is RAM, not a rail.
struct RailValue {
  Reading reading = Reading::NotANumber;
  double cur_mw = 0;
};

RailValue rail_value(std::string_view t) {
  std::string_view parts[3];
  std::size_t n = 0;
  for (std::size_t start = 0;;) {
    const std::size_t slash = t.find('/', start);
    if (n == 3) return {};
    parts[n++] = t.substr(start, slash == std::string_view::npos ? std::string_view::npos : slash - start);
    if (slash == std::string_view::npos) break;
    start = slash + 1;
  }
  if (n < 2) return {};
  RailValue out;
  out.reading = Reading::Ok;
  for (std::size_t k = 0; k < n; ++k) {
    double v = 0;
    const Reading r = milliwatts(parts[k], v);
    if (r == Reading::NotANumber) return {};
    if (r == Reading::OutOfRange) out.reading = Reading::OutOfRange;
    if (k == 0) out.cur_mw = v;
  }
  return out;
}

// A token after a rail name that was meant as a reading but does not parse ("5000mW/abcmW", "3981/-"): an error,
// not a rail to drop silently. RAM/SWAP/IRAM sizes ("2448/7854MB", "0/252kB(lfb") and percentages are not values.
bool malformed_rail_value(std::string_view t) {
  const bool numeric_start = !t.empty() && ((t.front() >= '0' && t.front() <= '9') || t.front() == '-');
  return t.find('/') != std::string_view::npos && numeric_start && t.find_first_of("B%") == std::string_view::npos &&
         rail_value(t).reading == Reading::NotANumber;
}

// The board's input rail, measured before the module and carrier split it: VDD_IN (TX1, TX2, Xavier NX, Orin Nano
// and NX), POM_5V_IN (Nano), VIN (AGX Thor). VIN_SYS_5V0 (AGX Orin, Thor) is the module's 5 V system rail, one
// rail among others, not the input.
bool input_rail(std::string_view name) { return name == "VDD_IN" || name == "POM_5V_IN" || name == "VIN"; }

// Name of the channel BenchScope adds when a board has no input rail (AGX Xavier, AGX Orin): the sum of the rails,
// which is what jetson-stats reports as the total on these boards.
constexpr std::string_view kSumChannel = "sum of rails";

class TegrastatsParser : meter::LineParserBase {
 public:
  TegrastatsParser(const std::string& file, const ParseOptions& options, const ImportLimits& limits)
      : LineParserBase(file, options, limits), sensors_(file) {
    if (!(options.interval_s > 0) || !std::isfinite(options.interval_s))
      throw ImportError(ImportErrorCategory::InvalidValue, {file, 0, 0, "interval"}, "the interval must be > 0 s");
  }
  // `last` says whether this is the file's final line (a cut-off line there is expected, not an error).
  void line(std::string_view raw, std::size_t line_no, bool last);
  ImportBatch finish();

 private:
  std::vector<std::string_view> tok_;
  std::vector<std::pair<std::string_view, double>> values_;
  std::vector<std::string> rails_;  // names in file order; channel k holds rail order_[k]
  std::vector<std::size_t> order_;
  std::optional<bool> timestamped_;
  bool summed_ = false;  // no input rail: channel 0 is the sum of the rails
  double first_time_ = 0;
  std::size_t sample_ = 0;
  PowerTrace trace_;
  TegrastatsSensors sensors_;  // clocks and temperatures of the accepted lines (#53)
};

void TegrastatsParser::line(std::string_view raw, std::size_t line_no, bool last) {
  meter::tokens(raw, tok_);
  if (tok_.empty()) return;
  values_.clear();
  for (std::size_t i = 0; i + 1 < tok_.size(); ++i) {
    if (!rail_name(tok_[i])) continue;
    const std::string_view value = tok_[i + 1];
    const std::size_t column = static_cast<std::size_t>(value.data() - raw.data()) + 1;
    const RailValue v = rail_value(value);
    if (v.reading == Reading::OutOfRange) {
      if (last && i + 2 == tok_.size()) break;  // a cut-off last line ends in a half-written number
      throw ImportError(ImportErrorCategory::InvalidValue, {file_, line_no, column, std::string(tok_[i])},
                        "'" + std::string(value) + "' is not a possible reading (" + std::string(kRailBoundText) +
                            "); the log is corrupt");
    }
    if (v.reading == Reading::Ok) {
      values_.emplace_back(tok_[i], v.cur_mw / 1000.0);
      ++i;
    } else if (malformed_rail_value(value) && !(last && i + 2 == tok_.size())) {  // a cut-off last line is fine
      throw ImportError(ImportErrorCategory::InvalidValue, {file_, line_no, column, std::string(tok_[i])},
                        "'" + std::string(value) +
                            "' is not a power reading (expected cur/avg or cur/avg/max in "
                            "mW, like 5000mW/4980mW, 3981/3981 or 4385mW/3787mW/4385mW)");
    }
  }
  if (values_.empty()) return skip(line_no, "no power rails on this line");
  if (rails_.empty()) {
    for (const auto& [name, v] : values_) rails_.emplace_back(name);
    // The board total first (the input rail, else the sum BenchScope adds), then the rails in file order.
    order_.resize(rails_.size());
    for (std::size_t k = 0; k < order_.size(); ++k) order_[k] = k;
    std::stable_partition(order_.begin(), order_.end(), [&](std::size_t k) { return input_rail(rails_[k]); });
    summed_ = !input_rail(rails_[order_.front()]);
    if (summed_) trace_.channels.push_back({std::string(kSumChannel), PowerQuantity::Power, {}});
    for (std::size_t k : order_) trace_.channels.push_back({rails_[k], PowerQuantity::Power, {}});
  } else if (values_.size() != rails_.size() ||
             !std::equal(values_.begin(), values_.end(), rails_.begin(),
                         [](const auto& a, const std::string& b) { return a.first == b; })) {
    if (last) return skip(line_no, "incomplete last line (tegrastats stopped while writing it)");
    throw ImportError(ImportErrorCategory::InvalidValue, {file_, line_no, 1, "rails"},
                      "the rails differ from the first line's (" + std::to_string(values_.size()) + " rails vs " +
                          std::to_string(rails_.size()) + ")");
  }
  if (sample_ >= limits_.max_samples)
    throw ImportError(ImportErrorCategory::TooLarge, {file_, line_no, 1, {}},
                      "more than " + std::to_string(limits_.max_samples) + " lines (the limit for one log)");
  // A plain flag and value rather than an optional kept across the branches below: GCC 11 at -O1 takes the
  // optional's payload for "maybe uninitialized" in `*stamp - first_time_` (a false positive, fatal with -Werror).
  bool has_stamp = false;
  double stamp = 0;
  if (tok_.size() >= 2)
    if (const std::optional<double> s = parse_month_day_year(tok_[0], tok_[1])) {
      has_stamp = true;
      stamp = *s;
    }
  if (!timestamped_) timestamped_ = has_stamp;
  if (*timestamped_ != has_stamp) {
    if (last) return skip(line_no, "incomplete last line (tegrastats stopped while writing it)");
    throw ImportError(ImportErrorCategory::InvalidValue, {file_, line_no, 1, "timestamp"},
                      *timestamped_ ? "no leading MM-DD-YYYY HH:MM:SS timestamp, unlike the lines before"
                                    : "a timestamp on this line but not on the first");
  }
  double t = static_cast<double>(sample_) * options_.interval_s;
  if (has_stamp) {
    if (sample_ == 0) {
      first_time_ = stamp;
      trace_.start_time = format_iso8601(stamp);
    }
    t = stamp - first_time_;
    if (!trace_.time_s.empty() && t < trace_.time_s.back())
      throw ImportError(ImportErrorCategory::InvalidValue, {file_, line_no, 1, "timestamp"},
                        "time goes backwards (" + std::string(tok_[0]) + " " + std::string(tok_[1]) + ")");
  }
  trace_.time_s.push_back(t);
  const std::size_t first = summed_ ? 1 : 0;
  double sum = 0;
  for (std::size_t k = 0; k < order_.size(); ++k) {
    const double w = values_[order_[k]].second;
    trace_.channels[first + k].values.push_back(w);
    sum += w;
  }
  if (summed_) trace_.channels[0].values.push_back(sum);
  sensors_.line(tok_, raw, line_no, last);  // after every check that can refuse the line: one value per sample
  ++sample_;
}

ImportBatch TegrastatsParser::finish() {
  if (trace_.time_s.empty())
    throw ImportError(ImportErrorCategory::MissingField, {file_, 0, 0, {}},
                      "no lines with power rails (VDD_*, POM_*; tegrastats shows them only when run as root on boards "
                      "with power monitors)");
  if (skipped_ > kListedWarnings)
    batch_.warnings.push_back(file_ + ": " + std::to_string(skipped_ - kListedWarnings) +
                              " more lines skipped (no power rails)");
  std::string rails;
  for (const std::string& r : rails_) rails += (rails.empty() ? "" : " + ") + r;
  std::string how;
  if (summed_) {
    how = "board total = " + std::string(kSumChannel) + " (" + rails +
          "), as jetson-stats reports it; this board has no input rail (VDD_IN, POM_5V_IN, VIN), so the carrier "
          "board and conversion losses are not measured: a lower bound of the power at the supply";
    batch_.warnings.push_back(file_ +
                              ": no board input rail (VDD_IN, POM_5V_IN, VIN): the board total is the sum of "
                              "the rails (" +
                              rails + "), a lower bound of the power at the supply");
  } else {
    how = "board total = " + rails_[order_.front()] + " (the input rail; the other rails are parts of it)";
  }
  trace_.total_channel = trace_.channels.front().name;
  // The log names no board model (only the family, by its format): the platform is what the user gives, else the
  // import asks or guesses (issue #43.3: a TX2's and an Orin's logs must not become one platform "Jetson").
  trace_.platform = options_.platform;
  trace_.label = meter::file_name(file_);
  // AGX Thor's VIN comes from a separate board monitor; every other rail tegrastats prints is an INA3221 channel.
  meter::stamp_log_provenance(
      trace_, file_, "tegrastats", MeasurementKind::OnBoardSensor,
      trace_.total_channel == "VIN" ? "on-board power monitors (tegrastats)" : "INA3221 (tegrastats)");
  trace_.provenance.note = how;
  if (!*timestamped_) {
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%g", options_.interval_s);
    const std::string interval = "no timestamps in the log: times assume one line every " + std::string(seconds) +
                                 " s (tegrastats' default --interval is 1000 ms; set the interval the log was "
                                 "written with if it differs)";
    batch_.warnings.push_back(file_ + ": " + interval);
    trace_.provenance.note += "; " + interval;
  }
  if (auto run = sensors_.finish(trace_, batch_.warnings)) batch_.sustain_runs.push_back(std::move(*run));
  batch_.power_traces.push_back(std::move(trace_));
  return std::move(batch_);
}

}  // namespace

static int sniff_tegrastats(std::string_view head, std::string_view) {
  std::vector<std::string_view> tok;
  int score = 0;
  for (const std::string& line : meter::head_lines(head, 16)) {
    meter::tokens(line, tok);
    const bool ram = std::find(tok.begin(), tok.end(), "RAM") != tok.end();
    for (std::size_t i = 0; ram && i + 1 < tok.size(); ++i)
      if (rail_name(tok[i]) && rail_value(tok[i + 1]).reading == Reading::Ok && tok[i] != "RAM" && tok[i] != "SWAP" &&
          tok[i] != "IRAM")
        return 90;
    // tegrastats without rails (not run as root, or a board without monitors): still ours, so that parse() can say
    // why there is nothing to import instead of "unknown format".
    if (ram && std::find(tok.begin(), tok.end(), "CPU") != tok.end()) score = 30;
  }
  return score;
}

const FileFormat kTegrastatsFileFormat{"tegrastats", "NVIDIA tegrastats log (Jetson rails)", sniff_tegrastats,
                                       meter::parse_log_file<TegrastatsParser>,
                                       meter::parse_log_text<TegrastatsParser>};

}  // namespace bs
