// SPDX-License-Identifier: GPL-3.0-or-later
#include "remote/events.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <ostream>

namespace bs::remote {

EventWriter::EventWriter(std::ostream& out) : out_(out), t0_(std::chrono::steady_clock::now()) {}

void EventWriter::write(std::string_view type, nlohmann::json fields) {
  // Ordered: "v", "type" and "t" lead every line, for a person reading the stream.
  nlohmann::ordered_json line = nlohmann::ordered_json::object();
  line["v"] = kEventsVersion;
  line["type"] = std::string(type);
  const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
  line["t"] = std::round(t * 1e6) / 1e6;
  if (fields.is_object())
    for (auto& [key, value] : fields.items()) line[key] = std::move(value);
  // Text from the system (a sensor label, an error) may not be UTF-8: replaced, never an exception mid-run.
  const std::string text = line.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  std::lock_guard lock(mutex_);
  out_ << text << '\n' << std::flush;
}

void EventWriter::progress(double fraction, std::string_view step) {
  write("progress",
        {{"fraction", std::clamp(std::isfinite(fraction) ? fraction : 0.0, 0.0, 1.0)}, {"step", std::string(step)}});
}

void EventWriter::message(std::string_view level, std::string_view text) {
  write("message", {{"level", std::string(level)}, {"text", std::string(text)}});
}

void EventWriter::error(std::string_view text) { write("error", {{"message", std::string(text)}}); }

void EventWriter::end(int status, bool cancelled) { write("end", {{"status", status}, {"cancelled", cancelled}}); }

Event parse_event(std::string_view line) {
  if (line.size() > kMaxEventLineBytes)
    throw EventError("a line of " + std::to_string(line.size()) + " bytes, longer than the " +
                     std::to_string(kMaxEventLineBytes) + " an event may have");
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
  if (j.is_discarded()) throw EventError("not JSON");
  if (!j.is_object()) throw EventError("JSON but not an object");
  const auto v = j.find("v");
  if (v == j.end() || !v->is_number_integer()) throw EventError("no version field \"v\"");
  if (v->get<std::int64_t>() != kEventsVersion)
    throw EventError("event format version " + v->dump() + ", this BenchScope reads version " +
                     std::to_string(kEventsVersion));
  const auto type = j.find("type");
  if (type == j.end() || !type->is_string() || type->get<std::string>().empty())
    throw EventError("no event type \"type\"");
  return Event{type->get<std::string>(), std::move(j)};
}

std::string string_field(const Event& e, const char* key) {
  const auto it = e.body.find(key);
  if (it == e.body.end() || !it->is_string())
    throw EventError(e.type + " event: '" + key + "' is missing or not a string");
  return it->get<std::string>();
}

double number_field(const Event& e, const char* key) {
  const auto it = e.body.find(key);
  if (it == e.body.end() || !it->is_number() || !std::isfinite(it->get<double>()))
    throw EventError(e.type + " event: '" + key + "' is missing or not a finite number");
  return it->get<double>();
}

std::int64_t integer_field(const Event& e, const char* key, std::int64_t min, std::int64_t max) {
  const auto it = e.body.find(key);
  if (it == e.body.end() || !it->is_number_integer() || it->get<std::int64_t>() < min || it->get<std::int64_t>() > max)
    throw EventError(e.type + " event: '" + key + "' must be an integer from " + std::to_string(min) + " to " +
                     std::to_string(max));
  return it->get<std::int64_t>();
}

nlohmann::json point_fields(const FlopsRun& run) {
  nlohmann::json j = {
      {"platform", run.platform},     {"device", run.device}, {"device_kind", std::string(to_string(run.device_kind))},
      {"backend", run.backend},       {"kernel", run.kernel}, {"variant", run.variant},
      {"iterations", run.iterations}, {"dims", run.dims}};
  if (!run.samples.empty()) {
    const WorkerSample& s = run.samples.back();
    j["workers"] = s.workers;
    j["seconds"] = s.seconds;
    double sum = 0;
    for (double t : s.seconds) sum += t;
    const double mean = s.seconds.empty() ? 0 : sum / static_cast<double>(s.seconds.size());
    // FLOPS = 6 D N W / t, for a reader that only prints; the desk recomputes it from the timings.
    if (mean > 0)
      j["flops"] = 6.0 * run.dims * static_cast<double>(run.iterations) * static_cast<double>(s.workers) / mean;
  }
  return j;
}

const FlopsRun& apply_point(std::vector<FlopsRun>& runs, const Event& e) {
  constexpr std::int64_t kMaxCount = std::int64_t{1} << 40;
  const int dims = static_cast<int>(integer_field(e, "dims", 1, 64));
  const std::int64_t workers = integer_field(e, "workers", 1, kMaxCount);
  const auto seconds = e.body.find("seconds");
  if (seconds == e.body.end() || !seconds->is_array() || seconds->empty() || seconds->size() > 100000)
    throw EventError("point event: 'seconds' must be a list of 1 to 100000 timings");
  WorkerSample sample{workers, {}};
  for (const auto& t : *seconds) {
    if (!t.is_number() || !(t.get<double>() > 0) || !std::isfinite(t.get<double>()))
      throw EventError("point event: a timing in 'seconds' is not a number > 0");
    sample.seconds.push_back(t.get<double>());
  }
  auto run = std::find_if(runs.begin(), runs.end(), [&](const FlopsRun& r) { return r.dims == dims; });
  if (run == runs.end()) {
    FlopsRun r;
    r.platform = string_field(e, "platform");
    r.device = string_field(e, "device");
    r.device_kind = device_kind_from_string(string_field(e, "device_kind"));
    r.backend = string_field(e, "backend");
    r.kernel = string_field(e, "kernel");
    r.variant = string_field(e, "variant");
    r.iterations = integer_field(e, "iterations", 1, kMaxCount);
    r.dims = dims;
    r.provenance.origin = DataOrigin::Measured;
    runs.push_back(std::move(r));
    run = std::prev(runs.end());
  }
  // Workers ascend within a run; a repeated point replaces the earlier one.
  auto at = std::lower_bound(run->samples.begin(), run->samples.end(), workers,
                             [](const WorkerSample& s, std::int64_t w) { return s.workers < w; });
  if (at != run->samples.end() && at->workers == workers)
    *at = std::move(sample);
  else
    run->samples.insert(at, std::move(sample));
  return *run;
}

}  // namespace bs::remote
