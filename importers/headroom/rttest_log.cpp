// SPDX-License-Identifier: GPL-3.0-or-later
#include "headroom/rttest_log.h"

#include <algorithm>
#include <charconv>
#include <vector>

#include "common/text_file.h"
#include "headroom/imported_latency.h"
#include "headroom/latency_recorder.h"
#include "headroom/text_lines.h"

namespace bs {
namespace {

using headroom_import::TextLine;
using headroom_import::whole_number;
using headroom_import::words_of;

constexpr std::int64_t kMaxLimitNs = 100'000'000;          // the histogram's range: 100 ms in 1 us bins (100,000 bins)
constexpr std::int64_t kMaxPeriodNs = 100'000'000'000;     // 100 s: a slower "loop" is not a control loop
constexpr std::int64_t kMaxLatencyNs = 1'000'000'000'000;  // 1000 s: a larger latency is not a measurement

struct Iteration {
  std::int64_t iteration = 0, timestamp = 0, latency = 0;
  std::uint64_t minor = 0, major = 0;
  std::size_t line = 0;
};

constexpr std::string_view kFieldNames[5] = {"iteration", "timestamp", "latency", "minor_pagefaults",
                                             "major_pagefaults"};

// The index of the first field of `words` that is not an integer of its kind, 5 when all are.
std::size_t bad_field(const std::vector<std::string_view>& words, Iteration* it) {
  std::int64_t* signed_fields[3] = {&it->iteration, &it->timestamp, &it->latency};
  std::uint64_t* counts[2] = {&it->minor, &it->major};
  for (std::size_t i = 0; i < words.size() && i < 5; ++i) {
    const bool ok = i < 3 ? whole_number(words[i], signed_fields[i]) : whole_number(words[i], counts[i - 3]);
    if (!ok) return i;
  }
  return 5;
}

bool is_header(std::string_view line) { return line.starts_with("iteration timestamp latency minor_pagefaults"); }

}  // namespace

static ImportBatch parse_rttest_log(const std::string& text, const std::string& file, const ParseOptions& /*options*/,
                                    const ImportLimits& limits, const CancelToken& cancel) {
  headroom_import::LineCursor cursor(text, cancel);
  TextLine line;
  std::size_t header_line = 0;
  std::vector<Iteration> rows;
  std::vector<std::string> warnings;
  std::uint64_t minor = 0, major = 0;
  while (cursor.next(&line)) {
    const std::string_view t = headroom_import::trim(line.text);
    if (t.empty()) continue;
    if (!header_line) {
      if (!is_header(t))
        throw ImportError(ImportErrorCategory::MissingField, {file, line.number, 1, {}},
                          "expected rttest's header 'iteration timestamp latency minor_pagefaults "
                          "major_pagefaults', found '" +
                              std::string(t.substr(0, 60)) + "'");
      header_line = line.number;
      continue;
    }
    Iteration it;
    it.line = line.number;
    const std::vector<std::string_view> words = words_of(t);
    const std::size_t bad = bad_field(words, &it);
    if (words.size() != 5 || bad < 5) {
      if (!line.has_line_end && words.size() < 5 && bad == 5) {
        warnings.push_back(headroom_import::where(file, line.number) + "the last line is cut short (no line end, " +
                           std::to_string(words.size()) + " of 5 fields): left out");
        break;
      }
      throw ImportError(ImportErrorCategory::Syntax,
                        {file, line.number, 1, bad < 5 ? std::string(kFieldNames[bad]) : std::string()},
                        bad < 5            ? "'" + std::string(words[bad]) + "' is not an integer"
                        : words.size() > 5 ? "more than the 5 fields 'iteration timestamp latency minor_pagefaults "
                                             "major_pagefaults'"
                                           : "only " + std::to_string(words.size()) +
                                                 " of the 5 fields 'iteration timestamp latency minor_pagefaults "
                                                 "major_pagefaults'");
    }
    if (it.latency > kMaxLatencyNs || it.latency < -kMaxLatencyNs)
      throw ImportError(ImportErrorCategory::InvalidValue, {file, line.number, 0, "latency"},
                        "latency " + std::to_string(it.latency) + " ns is beyond 1000 s: not a measurement");
    const auto expected = static_cast<std::int64_t>(rows.size());
    if (it.iteration != expected)
      throw ImportError(ImportErrorCategory::Syntax, {file, line.number, 1, "iteration"},
                        "iteration " + std::to_string(it.iteration) + " where " + std::to_string(expected) +
                            " was due (rows missing or out of order)");
    if (rows.size() >= limits.max_samples)
      throw ImportError(ImportErrorCategory::TooLarge, {file, line.number, 0, {}},
                        "more than the import limit of " + std::to_string(limits.max_samples) + " iterations");
    if (!line.has_line_end)
      warnings.push_back(headroom_import::where(file, line.number) +
                         "the last line has no line end: its latency may have been cut while it was written");
    minor += it.minor;
    major += it.major;
    rows.push_back(it);
  }
  if (!header_line)
    throw ImportError(ImportErrorCategory::Empty, {file, 0, 0, {}}, "no rttest header and no iterations");
  if (rows.empty())
    throw ImportError(ImportErrorCategory::MissingField, {file, header_line, 0, {}},
                      "the header is not followed by any iteration");

  // The update period is the timestamps' step (rttest writes iteration x period).
  const std::int64_t period = rows.size() > 1 ? rows[1].timestamp - rows[0].timestamp : 0;
  if (period < 0 || period > kMaxPeriodNs || (rows.size() > 1 && rows[0].timestamp != 0))
    throw ImportError(ImportErrorCategory::InvalidValue, {file, rows[rows.size() > 1 ? 1 : 0].line, 0, "timestamp"},
                      "timestamps must start at 0 and rise by an update period of at most 100 s");
  for (std::size_t i = 0; i < rows.size(); ++i)
    if (rows[i].timestamp != static_cast<std::int64_t>(i) * period)
      throw ImportError(ImportErrorCategory::InvalidValue, {file, rows[i].line, 0, "timestamp"},
                        "iteration " + std::to_string(i) + ": timestamp " + std::to_string(rows[i].timestamp) +
                            " is not iteration x period (" + std::to_string(period) + " ns)");

  std::int64_t max_latency = 0;
  std::size_t early = 0;
  for (const Iteration& it : rows) {
    max_latency = std::max(max_latency, it.latency);
    if (it.latency < 0) ++early;
  }
  // The histogram reaches past the largest latency (and at least one period), within 100 ms; beyond that the
  // overflows and the true maximum stand for it.
  const std::int64_t limit =
      std::clamp<std::int64_t>((std::max(max_latency, period) / 1000 + 1) * 1000, 1000, kMaxLimitNs);
  headroom::LatencyRecorder recorder(limit, 1000, period > 0 ? period : INT64_MAX);
  for (const Iteration& it : rows) recorder.add(it.latency);
  headroom::ThreadLatency thread = recorder.result();
  thread.index = 0;
  thread.period_ns = period;
  thread.deadline_ns = period;
  if (period <= 0) {
    thread.misses.reset();  // no period, no deadline
    thread.max_response_ns.reset();
  }

  headroom::HeadroomMeasurement m =
      headroom_import::imported_measurement(headroom::LatencyKind::ApplicationLoop, "rttest", file);
  headroom::Phase& phase = m.phases.front();
  phase.duration_s = static_cast<double>(period) * static_cast<double>(rows.size()) * 1e-9;
  phase.threads.push_back(std::move(thread));
  phase.notes.push_back("page faults during the run: " + std::to_string(minor) + " minor, " + std::to_string(major) +
                        " major");
  phase.notes.push_back("rttest's log does not record the scheduling policy or priority");
  if (early > 0) {
    phase.notes.push_back(std::to_string(early) + " iterations started early (negative latency): counted as 0");
    warnings.push_back(headroom_import::where(file, header_line) + std::to_string(early) +
                       " iterations have a negative latency (the loop woke early): counted as 0 us");
  }
  m.provenance.settings.emplace_back("iterations", std::to_string(rows.size()));
  if (period > 0) m.provenance.settings.emplace_back("update period", std::to_string(period) + " ns");
  ImportBatch batch = headroom_import::batch_of(std::move(m), file);
  batch.warnings = std::move(warnings);
  return batch;
}

static int sniff_rttest_log(std::string_view head, std::string_view) {
  const std::size_t start = head.find_first_not_of(" \t\r\n");
  if (start == std::string_view::npos) return 0;
  return is_header(head.substr(start)) ? 95 : 0;
}

const FileFormat kRttestLogFileFormat{"rttest-log",     "ROS 2 rttest per-iteration log (pendulum_demo -f)",
                                      sniff_rttest_log, parse_text_file_with<parse_rttest_log>,
                                      parse_rttest_log, ".txt .log .csv"};

}  // namespace bs
