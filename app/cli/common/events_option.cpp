// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/events_option.h"

#include <unistd.h>

#include <cmath>
#include <ostream>

#include "common/args.h"
#include "common/signals.h"
#include "sensors/recorder.h"
#include "util/host_clock.h"

namespace bs::cli {

bool wants_events(const std::vector<std::string>& raw) {
  bool wanted = false;
  for (std::size_t i = 0; i < raw.size(); ++i) {
    if (raw[i] == "--") break;
    std::string value;
    if (raw[i] == "--events") {
      if (i + 1 >= raw.size()) throw UsageError("--events needs a value (jsonl)");
      value = raw[i + 1];
    } else if (raw[i].starts_with("--events=")) {
      value = raw[i].substr(9);
    } else {
      continue;
    }
    if (value != "jsonl") throw UsageError("--events takes jsonl (got '" + value + "')");
    wanted = true;
  }
  return wanted;
}

int run_with_events(const std::string& command, const std::vector<std::string>& raw, std::ostream& out,
                    const std::function<int(remote::EventWriter* events)>& body) {
  if (!wants_events(raw)) return body(nullptr);
  return with_event_stream(command, raw, out, [&](remote::EventWriter& events) { return body(&events); });
}

int with_event_stream(const std::string& command, const std::vector<std::string>& raw, std::ostream& out,
                      const std::function<int(remote::EventWriter& events)>& body) {
  remote::EventWriter events(out);
  events.write("start", {{"command", command},
                         {"args", raw},
                         {"version", BENCHSCOPE_VERSION},
                         {"host", host_name()},
                         {"pid", static_cast<long long>(getpid())}});
  try {
    const int status = body(events);
    events.end(status, interrupt_token().cancelled());
    return status;
  } catch (const UsageError& e) {
    events.error(std::string("usage: ") + e.what());
    events.end(2, false);
    throw;
  } catch (const std::exception& e) {
    events.error(e.what());
    events.end(1, interrupt_token().cancelled());
    throw;
  }
}

void stream_power(sensors::PowerRecorder& recorder, remote::EventWriter& events) {
  const std::vector<std::string> names = recorder.channel_names();
  const std::string total = names.empty() ? std::string() : names[recorder.total_index()];
  recorder.set_on_sample([&events, names, total](double t, const std::vector<double>& watts) {
    nlohmann::json w = nlohmann::json::object();
    for (std::size_t i = 0; i < names.size() && i < watts.size(); ++i)
      w[names[i]] = std::isfinite(watts[i]) ? nlohmann::json(watts[i]) : nlohmann::json(nullptr);
    events.write("power", {{"time_s", t}, {"watts", std::move(w)}, {"total", total}});
  });
}

}  // namespace bs::cli
