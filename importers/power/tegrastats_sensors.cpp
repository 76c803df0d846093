// SPDX-License-Identifier: GPL-3.0-or-later
#include "power/tegrastats_sensors.h"

#include <algorithm>
#include <cmath>

#include "power/log_sustain.h"
#include "power/meter_log_text.h"

namespace bs {
namespace {

// Past this many, unreadable tokens are counted instead of listed one by one.
constexpr std::size_t kListedWarnings = 10;
// Beyond any Jetson clock (Thor's CPU runs below 3 GHz, its EMC near 4 GHz): a larger MHz value is corrupt.
constexpr double kMaxMhz = 100'000;
// tegrastats' (and jetson-stats') value for a thermal zone it cannot read.
constexpr double kNoReadingC = -256;
constexpr double kMinC = -100, kMaxC = 200;  // outside: not a reading of a working sensor

bool letter(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }
bool digit(char c) { return c >= '0' && c <= '9'; }

// A sensor or engine name as tegrastats prints it: "CPU", "tj", "soc0", "Tdiode", "GR3D_FREQ", "PVA0_FREQ".
bool sensor_name(std::string_view t) {
  return !t.empty() && letter(t.front()) &&
         std::all_of(t.begin(), t.end(), [](char c) { return letter(c) || digit(c) || c == '_' || c == '-'; });
}
// Engine names are upper case ("APE", "NVDLA0", "EMC_FREQ"); lower-case words ("fg", "lfb") are not engines.
bool engine_name(std::string_view t) {
  return !t.empty() && t.front() >= 'A' && t.front() <= 'Z' &&
         std::all_of(t.begin(), t.end(), [](char c) { return (c >= 'A' && c <= 'Z') || digit(c) || c == '_'; });
}
bool all_digits(std::string_view t) { return !t.empty() && std::all_of(t.begin(), t.end(), digit); }
// "12%" (a load without its clock).
bool load_only(std::string_view t) { return t.size() >= 2 && t.back() == '%' && all_digits(t.substr(0, t.size() - 1)); }

std::optional<double> mhz(std::string_view t) {
  double v = 0;
  if (!all_digits(t) || !meter::number(t, v) || v > kMaxMhz) return std::nullopt;
  return v;
}

std::string_view clock_name(std::string_view engine) {
  if (engine.size() > 5 && engine.ends_with("_FREQ")) engine.remove_suffix(5);
  return engine;
}

}  // namespace

void TegrastatsSensors::bad(std::size_t column, std::string_view field, const std::string& why) {
  if (last_) return;  // the file's last line may be cut mid-token; the power importer warns about that line
  if (++bad_ <= kListedWarnings)
    warnings_.push_back(file_ + ":" + std::to_string(line_no_) + ":" + std::to_string(column) + ": " +
                        std::string(field) + ": " + why + "; kept as missing");
}

void TegrastatsSensors::set_off(std::string_view name) {
  if (clocks_.set(name, std::nan("")) == meter::SampleSeries::Set::TooManyNames) too_many_ = true;
}

void TegrastatsSensors::set_clock(std::string_view name, double v) {
  if (v == 0) {  // a stopped clock (power-gated engine), not a slow one
    ++stopped_;
    v = std::nan("");
  }
  if (clocks_.set(name, v) == meter::SampleSeries::Set::TooManyNames) too_many_ = true;
}

// "[12%@2035,off,3%@2035]" (per-core clock) or JetPack 3's "[12%,off,3%]@2035" (one clock for every core on).
void TegrastatsSensors::cpu_list(std::string_view t, std::size_t column) {
  const std::size_t close = t.find(']');
  if (close == std::string_view::npos) return bad(column, "CPU", "'" + std::string(t) + "' has no closing ']'");
  std::optional<double> shared;
  if (const std::string_view tail = t.substr(close + 1); !tail.empty()) {
    shared = tail.front() == '@' ? mhz(tail.substr(1)) : std::nullopt;
    if (!shared) return bad(column, "CPU", "'" + std::string(t) + "' is not a CPU list (expected [12%@2035,off,...])");
  }
  std::vector<std::string_view> cores;
  meter::split(t.substr(1, close - 1), ',', cores);
  for (std::size_t k = 0; k < cores.size(); ++k) {
    const std::string_view c = cores[k];
    const std::string name = "cpu" + std::to_string(k);
    if (c == "off") {
      set_off(name);  // a core powered down: no clock, never 0 Hz
      continue;
    }
    const std::size_t at = c.find("%@");
    if (at == std::string_view::npos && load_only(c)) {
      if (shared) set_clock(name, *shared);
      continue;  // a load without a clock (no cpufreq): nothing to record
    }
    const auto v = at == std::string_view::npos || !all_digits(c.substr(0, at)) ? std::nullopt : mhz(c.substr(at + 2));
    if (!v) {
      bad(column, name, "'" + std::string(c) + "' is not a core's load and clock (expected 12%@2035 or off)");
      set_off(name);
      continue;
    }
    set_clock(name, *v);
  }
}

// "off", "174" (MHz), "99%@1300", "0%@[1300,1300]" (one clock per GPC).
void TegrastatsSensors::engine_clock(std::string_view engine, std::string_view v, std::size_t column) {
  const std::string name(clock_name(engine));
  if (v == "off") {
    set_off(name);
    return;
  }
  if (all_digits(v)) {
    if (const auto m = mhz(v)) return set_clock(name, *m);
    return bad(column, engine, "'" + std::string(v) + "' MHz is not a possible clock");
  }
  const std::size_t at = v.find("%@");
  const std::string_view clocks = v.substr(at + 2);
  if (!all_digits(v.substr(0, at)))
    return bad(column, engine, "'" + std::string(v) + "' is not a load and clock (expected 99%@1300)");
  if (clocks.size() >= 2 && clocks.front() == '[' && clocks.back() == ']') {
    std::vector<std::string_view> each;
    meter::split(clocks.substr(1, clocks.size() - 2), ',', each);
    for (std::size_t k = 0; k < each.size(); ++k) {
      const std::string part = name + (name == "GR3D" ? " GPC" : " ") + std::to_string(k);
      if (const auto m = mhz(each[k]))
        set_clock(part, *m);
      else
        bad(column, engine, "'" + std::string(each[k]) + "' in '" + std::string(v) + "' is not a clock in MHz");
    }
    return;
  }
  if (const auto m = mhz(clocks)) return set_clock(name, *m);
  bad(column, engine, "'" + std::string(v) + "' is not a load and clock (expected 99%@1300 or 0%@[1300,1300])");
}

// "45.5C", "-256C", JetPack 7's "51.968C/51.968C" (current/maximum: the current one is the sample).
void TegrastatsSensors::temperature(std::string_view name, std::string_view v, std::size_t column) {
  if (name == "PMIC") {  // a threshold state, not a measurement (see the header)
    pmic_ = true;
    return;
  }
  std::string_view cur = v.substr(0, v.find('/'));
  double c = 0;
  if (!cur.ends_with('C') || !meter::number(cur.substr(0, cur.size() - 1), c)) {
    bad(column, name, "'" + std::string(name) + "@" + std::string(v) + "' is not a temperature (expected NAME@45.5C)");
    c = std::nan("");
  } else if (c == kNoReadingC) {
    ++no_reading_;
    c = std::nan("");
  } else if (c < kMinC || c > kMaxC) {
    bad(column, name, std::string(cur) + " is not a possible temperature");
    c = std::nan("");
  }
  if (temps_.set(name, c) == meter::SampleSeries::Set::TooManyNames) too_many_ = true;
}

void TegrastatsSensors::line(const std::vector<std::string_view>& tok, std::string_view raw, std::size_t line_no,
                             bool last) {
  line_no_ = line_no;
  last_ = last;
  for (std::size_t i = 0; i < tok.size(); ++i) {
    const std::string_view t = tok[i];
    const std::size_t column = static_cast<std::size_t>(t.data() - raw.data()) + 1;
    const bool has_next = i + 1 < tok.size();
    if (t == "CPU" && has_next && tok[i + 1].starts_with('[')) {
      ++i;
      cpu_list(tok[i], static_cast<std::size_t>(tok[i].data() - raw.data()) + 1);
    } else if (const std::size_t at = t.find('@'); at != std::string_view::npos && sensor_name(t.substr(0, at))) {
      temperature(t.substr(0, at), t.substr(at + 1), column);
    } else if (engine_name(t) && has_next) {
      const std::string_view v = tok[i + 1];
      if (v == "off" || all_digits(v) || v.find("%@") != std::string_view::npos) {
        engine_clock(t, v, static_cast<std::size_t>(v.data() - raw.data()) + 1);
        ++i;
      } else if (load_only(v) && clock_name(t) == "GR3D") {
        gpu_load_only_ = true;
      }
    }
  }
  clocks_.end_sample();
  temps_.end_sample();
}

std::optional<SustainRun> TegrastatsSensors::finish(const PowerTrace& trace, std::vector<std::string>& warnings) {
  meter::LogSensors s;
  s.clocks_mhz = std::move(clocks_.series());
  s.celsius = std::move(temps_.series());
  const bool gpu_clock = std::any_of(s.clocks_mhz.begin(), s.clocks_mhz.end(), [](const auto& c) {
    return c.name.starts_with("GR3D") &&
           std::any_of(c.values.begin(), c.values.end(), [](double v) { return !std::isnan(v); });
  });
  if (!gpu_clock)
    s.not_exposed.push_back(gpu_load_only_ ? "no GPU clock: this tegrastats prints GR3D_FREQ as a load only (like "
                                             "22%), without the clock"
                                           : "no GPU clock in the log (no GR3D_FREQ clock)");
  s.notes.push_back("tegrastats clocks in MHz; 'off' (a core or engine powered down) kept as missing, never 0 Hz");
  if (stopped_)
    s.notes.push_back(std::to_string(stopped_) +
                      " clock readings of 0 MHz (a stopped clock: power-gated GPU or engine) kept as missing");
  if (no_reading_)
    s.notes.push_back(std::to_string(no_reading_) +
                      " temperatures of -256 C (tegrastats' 'no reading': the sensor's zone is off) kept as missing");
  if (pmic_)
    s.notes.push_back("PMIC@...C left out: not a measurement (the PMIC reports only whether it crossed 120 or 140 C)");
  std::move(warnings_.begin(), warnings_.end(), std::back_inserter(warnings));
  if (bad_ > kListedWarnings)
    warnings.push_back(file_ + ": " + std::to_string(bad_ - kListedWarnings) +
                       " more clock or temperature tokens that do not parse, kept as missing");
  if (too_many_)
    warnings.push_back(file_ +
                       ": more clock or temperature names than any Jetson has (or one first seen late in a "
                       "long log); those beyond the limit are not imported");
  return meter::log_sustain_run(trace, std::move(s));
}

}  // namespace bs
