// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// --events jsonl: a command writes BenchScope's event stream (docs/remote-events-v1.md) on stdout instead of its
// text, which then goes to stderr. The desk follows a robot's measurement through it (`benchscope-cli remote`).
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

#include "remote/events.h"

namespace bs::sensors {
class PowerRecorder;
}

namespace bs::cli {

inline constexpr const char* kEventsUsage =
    "  --events jsonl: write the event stream (docs/remote-events-v1.md: progress, points, power readings, the\n"
    "  result, errors; one JSON object per line) on stdout instead of the text, which goes to stderr.";

// Whether `raw` (before a "--") asks for --events jsonl. Throws UsageError for --events with another value.
bool wants_events(const std::vector<std::string>& raw);
// Runs a command's body with an event writer on `out`: a "start" event first, an "end" event with the status
// (cancelled when Ctrl+C stopped it) last, and an exception as an "error" and an "end" event before it goes on to
// main's report.
int with_event_stream(const std::string& command, const std::vector<std::string>& raw, std::ostream& out,
                      const std::function<int(remote::EventWriter& events)>& body);
// with_event_stream when `raw` has --events jsonl, else the body with no writer.
int run_with_events(const std::string& command, const std::vector<std::string>& raw, std::ostream& out,
                    const std::function<int(remote::EventWriter* events)>& body);

// Sends each of the recorder's samples as a "power" event. Call before the recorder starts (see start_power's
// `on_recorder`).
void stream_power(sensors::PowerRecorder& recorder, remote::EventWriter& events);

}  // namespace bs::cli
