// SPDX-License-Identifier: GPL-3.0-or-later
#include "sustain/sustain_json.h"

#include <cmath>
#include <limits>

#include "model/json_fields.h"
#include "model/provenance_json.h"

namespace bs::sustain {
namespace {

using nlohmann::json;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

json value_or_null(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

json series(const std::vector<double>& values) {
  json a = json::array();
  for (double v : values) a.push_back(value_or_null(v));
  return a;
}

json optional_number(const std::optional<double>& v) { return v ? json(*v) : json(nullptr); }

using Fields = JsonFields<SustainJsonError>;

double number(const json& v, const std::string& where, double lo, double hi) {
  if (!v.is_number()) Fields::fail(where, "'" + v.dump().substr(0, 40) + "' is not a number");
  const double x = v.get<double>();
  if (!(x >= lo && x <= hi))
    Fields::fail(where, v.dump() + " is outside " + json(lo).dump() + " .. " + json(hi).dump());
  return x;
}

std::optional<double> optional_number(const json& obj, const char* key, const std::string& where, double lo,
                                      double hi) {
  const auto it = obj.find(key);
  if (it == obj.end() || it->is_null()) return std::nullopt;
  return number(*it, where + "." + key, lo, hi);
}

const json& array(const json& obj, const char* key, const std::string& where, std::size_t max) {
  const json& v = Fields::array(obj, key, where);
  if (v.size() > max)
    Fields::fail(where + "." + key, std::to_string(v.size()) + " entries, more than " + std::to_string(max));
  return v;
}

// Numbers or nulls (NaN), exactly `n` of them (or none when `may_be_empty`).
std::vector<double> values(const json& obj, const char* key, const std::string& where, std::size_t n, double lo,
                           double hi, bool may_be_empty) {
  const json& a = array(obj, key, where, kMaxIntervals);
  if (!(a.size() == n || (may_be_empty && a.empty())))
    Fields::fail(where + "." + key, std::to_string(a.size()) + " values for " + std::to_string(n) + " intervals");
  std::vector<double> out;
  out.reserve(a.size());
  for (std::size_t i = 0; i < a.size(); ++i)
    out.push_back(a[i].is_null() ? kNaN : number(a[i], where + "." + key + "[" + std::to_string(i) + "]", lo, hi));
  return out;
}

std::vector<std::string> texts(const json& obj, const char* key, const std::string& where) {
  const json& a = array(obj, key, where, kMaxSeries);
  std::vector<std::string> out;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!a[i].is_string()) Fields::fail(where + "." + key + "[" + std::to_string(i) + "]", "is not a string");
    out.push_back(a[i].get<std::string>());
  }
  return out;
}

constexpr double kMaxSeconds = 1e9, kMaxRate = 1e18, kMaxHz = 1e12, kMaxWatts = 1e6;

// Calls each(series, at) for every object of the array obj[key] (the clocks, the temperatures: at most kMaxSeries),
// `at` naming it in messages ("sustain.clocks[2]").
template <class Each>
void each_series(const json& obj, const char* key, const std::string& where, Each each) {
  const json& a = array(obj, key, where, kMaxSeries);
  for (std::size_t k = 0; k < a.size(); ++k) {
    const std::string at = where + "." + key + "[" + std::to_string(k) + "]";
    if (!a[k].is_object()) Fields::fail(at, "is not an object");
    each(a[k], at);
  }
}

}  // namespace

json record_to_json(const SustainRun& r) {
  json clocks = json::array(), temps = json::array();
  for (const ClockSeries& c : r.clocks)
    clocks.push_back({{"name", c.name}, {"max_hz", optional_number(c.max_hz)}, {"hz", series(c.hz)}});
  for (const TemperatureSeries& t : r.temperatures)
    temps.push_back({{"name", t.name}, {"trip_c", optional_number(t.trip_c)}, {"celsius", series(t.celsius)}});
  return {{"platform", r.platform},
          {"label", r.label},
          {"load", r.load},
          {"rate_unit", r.rate_unit},
          {"interval_s", r.interval_s},
          {"t_s", series(r.t_s)},
          {"rate", series(r.rate)},
          {"clocks", clocks},
          {"temperatures", temps},
          {"power_w", series(r.power_w)},
          {"power_sensor", r.power_sensor},
          {"not_exposed", r.not_exposed},
          {"provenance", provenance_to_json(r.provenance, true)}};
}

SustainRun record_from_json(const json& j) {
  const std::string w = "sustain";
  if (!j.is_object()) Fields::fail(w, "is not an object");
  SustainRun r;
  r.platform = Fields::text(j, "platform", w);
  r.label = Fields::text(j, "label", w);
  r.load = Fields::text(j, "load", w);
  r.rate_unit = Fields::text(j, "rate_unit", w);
  r.interval_s = number(Fields::member(j, "interval_s", w), w + ".interval_s", 0, kMaxSeconds);
  const json& times = array(j, "t_s", w, kMaxIntervals);
  const std::size_t n = times.size();
  r.t_s.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::string at = w + ".t_s[" + std::to_string(i) + "]";
    if (times[i].is_null()) Fields::fail(at, "is null (an interval's end must be known)");
    r.t_s.push_back(number(times[i], at, 0, kMaxSeconds));
    if (i > 0 && !(r.t_s[i] > r.t_s[i - 1])) Fields::fail(at, "does not increase");
  }
  r.rate = values(j, "rate", w, n, 0, kMaxRate, true);
  if (!r.rate.empty() && r.rate_unit.empty()) Fields::fail(w + ".rate_unit", "is empty for a record with a rate");
  each_series(j, "clocks", w, [&](const json& s, const std::string& at) {
    ClockSeries c;
    c.name = Fields::text(s, "name", at);
    c.max_hz = optional_number(s, "max_hz", at, 0, kMaxHz);
    c.hz = values(s, "hz", at, n, 0, kMaxHz, false);
    r.clocks.push_back(std::move(c));
  });
  each_series(j, "temperatures", w, [&](const json& s, const std::string& at) {
    TemperatureSeries t;
    t.name = Fields::text(s, "name", at);
    t.trip_c = optional_number(s, "trip_c", at, -273.15, 1000);
    t.celsius = values(s, "celsius", at, n, -273.15, 1000, false);
    r.temperatures.push_back(std::move(t));
  });
  r.power_w = values(j, "power_w", w, n, 0, kMaxWatts, true);
  r.power_sensor = Fields::text(j, "power_sensor", w);
  r.not_exposed = texts(j, "not_exposed", w);
  const json& prov = Fields::member(j, "provenance", w);
  if (!prov.is_object()) Fields::fail(w + ".provenance", "is not an object");
  r.provenance = provenance_from_json(prov);
  return r;
}

json interval_json(const SustainRun& r, std::size_t i) {
  const auto at = [i](const std::vector<double>& v) { return i < v.size() ? value_or_null(v[i]) : json(nullptr); };
  json clocks = json::object(), temps = json::object();
  for (const ClockSeries& c : r.clocks) clocks[c.name] = at(c.hz);
  for (const TemperatureSeries& t : r.temperatures) temps[t.name] = at(t.celsius);
  return {{"index", i},          {"t_s", at(r.t_s)},        {"rate", at(r.rate)},      {"rate_unit", r.rate_unit},
          {"clocks_hz", clocks}, {"temperatures_c", temps}, {"power_w", at(r.power_w)}};
}

json result_json(const SustainRun& r, const SustainAnalysis& a) {
  json intervals = json::array();
  for (std::size_t i = 0; i < r.t_s.size(); ++i) intervals.push_back(interval_json(r, i));
  json clock_max = json::object(), trips = json::object();
  for (const ClockSeries& c : r.clocks) clock_max[c.name] = optional_number(c.max_hz);
  for (const TemperatureSeries& t : r.temperatures) trips[t.name] = optional_number(t.trip_c);
  const auto reading = [](const std::optional<OnsetReading>& o) -> json {
    if (!o) return nullptr;
    return {{"name", o->name}, {"value", o->value}, {"limit", optional_number(o->limit)}, {"throttled", o->throttled}};
  };
  json throttle = {{"known", a.throttle.known}, {"detected", a.throttle.detected}};
  if (!a.throttle.known) throttle["unknown"] = a.throttle.unknown_reason;
  throttle["onset_s"] = optional_number(a.throttle.onset_s);
  throttle["onset_index"] = a.throttle.onset_index ? json(*a.throttle.onset_index) : json(nullptr);
  throttle["what"] = a.throttle.what;
  throttle["clock_at_onset"] = reading(a.throttle.clock_at_onset);
  throttle["temperature_at_onset"] = reading(a.throttle.temperature_at_onset);
  json spans = json::array();
  for (const auto& [s, e] : a.throttle.spans) spans.push_back({s, e});
  throttle["spans_s"] = spans;
  throttle["throttled_s"] = a.throttle.throttled_s;
  throttle["threshold"] = a.options.throttle_threshold;
  throttle["notes"] = a.throttle.notes;
  const auto summary = [&](const Summary& s) -> json {
    if (s.n == 0) return nullptr;
    return {{"mean", s.mean}, {"sd", s.sd}, {"n", s.n}, {"min", s.min}, {"max", s.max}};
  };
  json first_slow = nullptr;
  if (a.first_slow)
    first_slow = {{"index", a.first_slow->index},
                  {"start_s", a.first_slow->start_s},
                  {"end_s", a.first_slow->end_s},
                  {"rate", a.first_slow->rate}};
  return {{"platform", r.platform},
          {"label", r.label},
          {"load", r.load},
          {"rate_unit", r.rate_unit},
          {"interval_s", r.interval_s},
          {"intervals", intervals},
          {"clock_max_hz", clock_max},
          {"trip_c", trips},
          {"power_sensor", r.power_sensor},
          {"stability_percent", optional_number(a.stability_percent)},
          {"stable_percent", a.options.stable_percent},
          {"stable", a.stable},
          {"peak_rate", optional_number(a.peak_rate)},
          {"rate", summary(a.rate)},
          {"sustained_rate", a.sustained.n ? json(a.sustained.mean) : json(nullptr)},
          {"sustained", summary(a.sustained)},
          {"sustained_percent_of_peak", optional_number(a.sustained_percent_of_peak)},
          {"steady_s", optional_number(a.steady_s)},
          {"steady_percent", a.options.steady_percent},
          {"first_slow", first_slow},
          {"throttle", throttle},
          {"not_exposed", r.not_exposed},
          {"provenance", provenance_to_json(r.provenance, false)}};
}

}  // namespace bs::sustain
