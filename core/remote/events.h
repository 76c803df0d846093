// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// BenchScope's event stream, version 1 (docs/remote-events-v1.md): what `benchscope-cli ... --events jsonl` writes
// on stdout instead of its text, one JSON object per line, so a program at the other end of a pipe or an SSH
// connection (the desk watching a robot) can follow a measurement live: its progress, each sweep point, power
// readings, the result and any error. Every line carries the format version ("v") and its type.
#include <chrono>
#include <cstddef>
#include <iosfwd>
#include <mutex>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/flops_run.h"

namespace bs::remote {

inline constexpr int kEventsVersion = 1;
// The longest line a reader accepts (a file chunk is 64 KiB of base64; a point with 1000 repetitions ~25 KiB).
inline constexpr std::size_t kMaxEventLineBytes = 1 << 20;

// Writes events to a stream, one line each, flushed at once so the reader sees them as they happen. Safe to call
// from several threads (the sweep reports points while the power sampler reports readings).
class EventWriter {
 public:
  explicit EventWriter(std::ostream& out);
  // {"v":1,"type":TYPE,"t":seconds since this writer was made, ...fields}. `fields` must be an object (or null).
  void write(std::string_view type, nlohmann::json fields = nlohmann::json::object());
  // The common ones.
  void progress(double fraction, std::string_view step);
  void message(std::string_view level, std::string_view text);  // "info", "warning"
  void error(std::string_view text);
  void end(int status, bool cancelled);

 private:
  std::ostream& out_;
  std::mutex mutex_;
  std::chrono::steady_clock::time_point t0_;
};

// One event as read back.
struct Event {
  std::string type;
  nlohmann::json body;  // the whole object, "v" and "type" included
};

class EventError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Parses one line (without its line end). Throws EventError saying what is wrong: not JSON, not an object, no
// version or type, a version this reader does not speak, a line beyond kMaxEventLineBytes.
Event parse_event(std::string_view line);

// The FLOPS sweep's "point" event: the run's identity and the point just completed (its workers and timings).
nlohmann::json point_fields(const FlopsRun& run_so_far);
// Adds a "point" event's sample to the run of the same D in `runs` (a new run when none), and returns that run.
// Throws EventError naming the field that is missing or out of range.
const FlopsRun& apply_point(std::vector<FlopsRun>& runs, const Event& point);

// Field access that names what is wrong in an EventError ("point event: 'workers' must be an integer >= 1").
std::string string_field(const Event& e, const char* key);
double number_field(const Event& e, const char* key);
std::int64_t integer_field(const Event& e, const char* key, std::int64_t min, std::int64_t max);

}  // namespace bs::remote
