// SPDX-License-Identifier: GPL-3.0-or-later
#include "headroom/cyclictest_json.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cstdint>
#include <map>
#include <vector>

#include "common/json_access.h"
#include "common/text_file.h"
#include "headroom/cyclictest_command.h"
#include "headroom/cyclictest_threads.h"
#include "headroom/imported_latency.h"
#include "headroom/text_lines.h"

namespace bs {
namespace {

using json_access::child;
using json_access::json;
using json_access::Reader;

// cyclictest's own limit on histogram buckets (HIST_MAX).
constexpr std::int64_t kMaxBuckets = 1000000;
// Cycles of one thread: 10^15 is 31 years at 1 MHz; beyond it sums of counts could overflow.
constexpr std::int64_t kMaxCount = 1'000'000'000'000'000;

// Lines of `text` as (start offset, length without the line end).
std::vector<std::pair<std::size_t, std::size_t>> line_spans(std::string_view text) {
  std::vector<std::pair<std::size_t, std::size_t>> out;
  for (std::size_t pos = 0; pos <= text.size();) {
    const std::size_t end = std::min(text.find('\n', pos), text.size());
    out.emplace_back(pos, end - pos);
    if (end == text.size()) break;
    pos = end + 1;
  }
  return out;
}

// write_stats prints "avg": s->avg / s->cycles with %.2f: a thread that ran no cycle gets -nan (or nan), which is
// not JSON. Such a value becomes null (same line, so error locations stay right) and is reported.
std::string null_nan_averages(std::string text, const std::string& file, std::vector<std::string>* warnings) {
  const auto spans = line_spans(text);
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < spans.size(); ++i) {
    std::string line = text.substr(spans[i].first, spans[i].second);
    const std::string_view t = headroom_import::trim(line);
    if (t.starts_with("\"avg\":")) {
      const std::string value(headroom_import::trim(t.substr(6)));  // a copy: `line` changes below
      for (std::string_view bad : {"-nan,", "nan,", "-nan", "nan", "-inf,", "inf,", "-inf", "inf"}) {
        if (value == bad) {
          line.replace(line.find(bad, line.find("\"avg\":")), bad.size(), bad.ends_with(",") ? "null," : "null");
          warnings->push_back(headroom_import::where(file, i + 1) + "\"avg\": " + value.substr(0, value.find(',')) +
                              " (a thread that ran no cycle): read as no average");
          break;
        }
      }
    }
    out += line;
    if (i + 1 < spans.size()) out += '\n';
  }
  return out;
}

// rt_write_json prints "cmdline:" with %s: an argument holding '"' or '\' breaks the document. Returns the text
// with that one string escaped and the line it is on, or nullopt when there is no such line to mend.
std::optional<std::pair<std::string, std::size_t>> escape_command_line(const std::string& text) {
  const auto spans = line_spans(text);
  for (std::size_t i = 0; i < spans.size(); ++i) {
    const std::string_view line = std::string_view(text).substr(spans[i].first, spans[i].second);
    std::size_t open = std::string_view::npos;
    for (std::string_view key : {"\"cmdline:\": \"", "\"cmdline\": \""}) {
      const auto at = line.find(key);
      if (at != std::string_view::npos && headroom_import::trim(line.substr(0, at)).empty()) open = at + key.size();
    }
    if (open == std::string_view::npos) continue;
    std::string_view rest = line.substr(open);
    while (!rest.empty() && (rest.back() == ' ' || rest.back() == '\r')) rest.remove_suffix(1);
    if (rest.ends_with(",")) rest.remove_suffix(1);
    if (!rest.ends_with("\"")) return std::nullopt;
    const std::string_view value = rest.substr(0, rest.size() - 1);
    if (value.find_first_of("\"\\") == std::string_view::npos) return std::nullopt;
    std::string escaped;
    for (char c : value) {
      if (c == '"' || c == '\\') escaped.push_back('\\');
      escaped.push_back(c);
    }
    std::string out = text;
    out.replace(spans[i].first + open, value.size(), escaped);
    return std::make_pair(std::move(out), i + 1);
  }
  return std::nullopt;
}

// "Mon, 31 Aug 2026 00:23:41 -0500" (strftime "%a, %d %b %Y %T %z") as ISO 8601 "2026-08-31T00:23:41-05:00";
// "" when it is not in that form.
std::string iso_date(std::string_view rfc2822) {
  constexpr std::array<std::string_view, 12> months = {"Jan", "Feb", "Mar", "Apr", "May", "Jun",
                                                       "Jul", "Aug", "Sep", "Oct", "Nov", "Dec"};
  const auto comma = rfc2822.find(", ");
  if (comma == std::string_view::npos) return {};
  std::string_view s = rfc2822.substr(comma + 2);
  // "31 Aug 2026 00:23:41 -0500"
  if (s.size() < 26 || s[2] != ' ' || s[6] != ' ' || s[11] != ' ' || s[20] != ' ') return {};
  int month = 0;
  for (std::size_t m = 0; m < months.size(); ++m)
    if (s.substr(3, 3) == months[m]) month = static_cast<int>(m) + 1;
  if (month == 0) return {};
  const std::string mm = (month < 10 ? "0" : "") + std::to_string(month);
  const std::string_view zone = s.substr(21, 5);
  return std::string(s.substr(7, 4)) + "-" + mm + "-" + std::string(s.substr(0, 2)) + "T" +
         std::string(s.substr(12, 8)) + std::string(zone.substr(0, 3)) + ":" + std::string(zone.substr(3, 2));
}

headroom::KernelFacts kernel_of(const Reader& r, const json& sysinfo, const std::string& at) {
  headroom::KernelFacts k;
  k.release = r.optional_string(sysinfo, at, "release");
  k.version = r.optional_string(sysinfo, at, "version");
  // uname -v names the preemption model; /sys/kernel/realtime (the "realtime" key) says PREEMPT_RT for sure.
  const auto has_word = [&](std::string_view w) {
    const std::string padded = " " + k.version + " ";
    return padded.find(" " + std::string(w) + " ") != std::string::npos;
  };
  k.preemption = k.version.empty()             ? ""
                 : has_word("PREEMPT_RT")      ? "PREEMPT_RT"
                 : has_word("PREEMPT_DYNAMIC") ? "PREEMPT_DYNAMIC"
                 : has_word("PREEMPT")         ? "PREEMPT"
                                               : "none";
  if (const json* rt = r.optional(sysinfo, "realtime")) {
    k.preempt_rt = r.integer(*rt, child(at, "realtime"), 0, 1) == 1;
  } else if (!k.preemption.empty()) {
    k.preempt_rt = k.preemption == "PREEMPT_RT";
  }
  return k;
}

ImportBatch parse_document(const json& doc, const Reader& r, const ImportLimits& limits,
                           std::vector<std::string> warnings) {
  r.require_object(doc, "");
  if (const json* v = r.optional(doc, "file_version"))
    if (r.integer(*v, "/file_version", 0, 1000) > 1)
      r.fail(ImportErrorCategory::Unsupported, "/file_version",
             "file_version " + v->dump() + " is newer than the version 1 BenchScope reads");
  // rt-tests writes "cmdline:" and "rt_test_version:" with a colon inside the key.
  const std::string cmd_key = r.optional(doc, "cmdline:") ? "cmdline:" : "cmdline";
  const std::string cmdline = r.optional_string(doc, "", cmd_key);
  std::optional<headroom_import::CyclictestCommand> command;
  if (!cmdline.empty()) {
    command = headroom_import::parse_cyclictest_command(cmdline);
    if (!command) {
      const auto words = headroom_import::shell_words(cmdline);
      r.fail(ImportErrorCategory::Unsupported, child("", cmd_key),
             "an rt-tests JSON of '" + (words.empty() ? cmdline : words.front()) +
                 "', not of cyclictest: BenchScope reads cyclictest's wake-up latencies");
    }
  }
  const std::string version_key = r.optional(doc, "rt_test_version:") ? "rt_test_version:" : "rt_test_version";
  const std::string version = r.optional_string(doc, "", version_key);
  const std::int64_t return_code =
      r.optional(doc, "return_code") ? r.require_integer(doc, "", "return_code", INT32_MIN, INT32_MAX) : 0;
  const std::int64_t n = r.require_integer(doc, "", "num_threads", 1, 4096);
  const bool ns = r.optional(doc, "resolution_in_ns") && r.require_integer(doc, "", "resolution_in_ns", 0, 1) == 1;
  const std::int64_t unit_ns = ns ? 1 : 1000;
  const json& threads = r.require_object(r.require(doc, "", "thread"), "/thread");
  if (static_cast<std::int64_t>(threads.size()) != n)
    r.fail(ImportErrorCategory::InvalidValue, "/thread",
           "holds " + std::to_string(threads.size()) + " threads, num_threads says " + std::to_string(n));

  headroom::HeadroomMeasurement m =
      headroom_import::imported_measurement(headroom::LatencyKind::SystemWakeup, "cyclictest", r.file());
  headroom::Phase& phase = m.phases.front();
  bool limit_unknown = false, summary = false;
  const std::map<int, headroom_import::StatusLine> no_status;
  std::uint64_t histogram_counts = 0;
  for (std::int64_t i = 0; i < n; ++i) {
    const std::string key = std::to_string(i);
    const std::string at = child("/thread", key);
    if (!threads.contains(key))
      r.fail(ImportErrorCategory::MissingField, at,
             "thread " + key + " is missing (threads are \"0\" to \"" + std::to_string(n - 1) + "\")");
    const json& t = r.require_object(threads.at(key), at);
    const auto cycles = static_cast<std::uint64_t>(r.require_integer(t, at, "cycles", 0, kMaxCount));
    const bool ran = cycles > 0;
    // cyclictest starts min at 1000000 and max at 0: only a thread that ran has extremes.
    const std::optional<std::int64_t> min_ns =
        ran ? std::optional<std::int64_t>(r.require_integer(t, at, "min", INT32_MIN, INT32_MAX) * unit_ns)
            : std::nullopt;
    const std::optional<std::int64_t> max_ns =
        ran ? std::optional<std::int64_t>(r.require_integer(t, at, "max", INT32_MIN, INT32_MAX) * unit_ns)
            : std::nullopt;
    std::optional<double> mean_ns;
    if (ran)
      if (auto avg = r.optional_number(t, at, "avg")) mean_ns = *avg * static_cast<double>(unit_ns);
    std::optional<int> cpu;
    if (const json* c = r.optional(t, "cpu")) cpu = static_cast<int>(r.integer(*c, child(at, "cpu"), -1, 1 << 20));
    headroom::ThreadLatency thread;
    if (const json* h = r.optional(t, "histogram")) {
      const std::string hat = child(at, "histogram");
      r.require_object(*h, hat);
      std::int64_t highest = -1;
      std::vector<std::pair<std::int64_t, std::uint64_t>> counts;
      for (const auto& [bucket_text, count] : h->items()) {
        const std::string bat = child(hat, bucket_text);
        std::int64_t bucket = -1;
        const auto [ptr, ec] = std::from_chars(bucket_text.data(), bucket_text.data() + bucket_text.size(), bucket);
        if (ec != std::errc() || ptr != bucket_text.data() + bucket_text.size() || bucket < 0 || bucket >= kMaxBuckets)
          r.fail(ImportErrorCategory::InvalidValue, bat,
                 "bucket \"" + bucket_text + "\" is not a bucket number from 0 to " + std::to_string(kMaxBuckets - 1));
        counts.emplace_back(bucket, static_cast<std::uint64_t>(r.integer(count, bat, 0, kMaxCount)));
        highest = std::max(highest, bucket);
      }
      std::int64_t buckets = highest + 1;
      if (command && command->histogram_bins && *command->histogram_bins > 0) {
        buckets = std::min<std::int64_t>(*command->histogram_bins, kMaxBuckets);
        if (highest >= buckets)
          r.fail(ImportErrorCategory::InvalidValue, child(hat, std::to_string(highest)),
                 "bucket " + std::to_string(highest) + " lies beyond the " + std::to_string(buckets) +
                     " buckets of the command line's histogram");
      } else {
        limit_unknown = true;
      }
      buckets = std::max<std::int64_t>(buckets, 1);
      histogram_counts += static_cast<std::uint64_t>(buckets);
      if (histogram_counts > limits.max_samples)
        r.fail(ImportErrorCategory::TooLarge, hat,
               "the threads' histograms hold more than the import limit of " + std::to_string(limits.max_samples) +
                   " buckets");
      thread.index = static_cast<int>(i);
      thread.histogram.bin_ns = unit_ns;
      thread.histogram.bins.assign(static_cast<std::size_t>(buckets), 0);
      std::uint64_t binned = 0;
      for (const auto& [bucket, count] : counts) {
        thread.histogram.bins[static_cast<std::size_t>(bucket)] = count;
        binned += count;
      }
      if (binned > cycles)
        r.fail(ImportErrorCategory::InvalidValue, child(at, "cycles"),
               "cycles " + std::to_string(cycles) + " is fewer than the " + std::to_string(binned) +
                   " counts of the histogram");
      thread.histogram.overflows = cycles - binned;  // cyclictest's JSON keeps no overflow count
      thread.histogram.cycles = cycles;
      thread.histogram.min_ns = min_ns;
      thread.histogram.max_ns = max_ns;
      thread.mean_ns = mean_ns;
      if (const std::string e = thread.histogram.bookkeeping_error(); !e.empty())
        r.fail(ImportErrorCategory::InvalidValue, child(at, "max"), "disagrees with the histogram: " + e);
    } else {
      thread = headroom_import::summary_only_thread(static_cast<int>(i), cycles, min_ns, max_ns, mean_ns, std::nullopt);
      summary = true;
    }
    headroom_import::apply_thread_facts(&thread, static_cast<int>(i), command, no_status, "", cpu);
    phase.threads.push_back(std::move(thread));
  }
  if (summary) phase.notes.push_back(std::string(headroom_import::kSummaryOnlyNote) + " (cyclictest ran without -h)");
  if (limit_unknown)
    phase.notes.push_back(
        "histogram size not recorded (no -h/-H in the command line): its range is taken as up "
        "to the highest bucket, so overflows lie at least that far out");
  if (return_code != 0)
    warnings.push_back(r.where("/return_code") + ": cyclictest ended with return code " + std::to_string(return_code) +
                       " (the run may have stopped early)");

  m.command = cmdline;
  auto& settings = m.provenance.settings;
  if (!cmdline.empty()) settings.emplace_back("command", cmdline);
  if (!version.empty()) {
    settings.emplace_back("rt-tests version", version);
    m.provenance.tool = "cyclictest " + version;
  }
  settings.emplace_back("latency unit", ns ? "ns (-N)" : "us");
  m.provenance.date = iso_date(r.optional_string(doc, "", "start_time"));
  if (const std::string start = r.optional_string(doc, "", "start_time"); !start.empty())
    settings.emplace_back("start time", start);
  if (const std::string end = r.optional_string(doc, "", "end_time"); !end.empty())
    settings.emplace_back("end time", end);
  if (const json* sysinfo = r.optional(doc, "sysinfo")) {
    r.require_object(*sysinfo, "/sysinfo");
    m.kernel = kernel_of(r, *sysinfo, "/sysinfo");
    // "[redacted]" and the like: a host name someone removed is no platform name.
    if (std::string host = r.optional_string(*sysinfo, "/sysinfo", "nodename"); !host.starts_with("["))
      m.provenance.host = std::move(host);
    const std::string sysname = r.optional_string(*sysinfo, "/sysinfo", "sysname");
    m.provenance.os = sysname + (m.kernel.release.empty() ? "" : " " + m.kernel.release);
    if (const std::string machine = r.optional_string(*sysinfo, "/sysinfo", "machine"); !machine.empty())
      settings.emplace_back("architecture", machine);
  }
  ImportBatch batch = headroom_import::batch_of(std::move(m), r.file());
  batch.warnings = std::move(warnings);
  return batch;
}

}  // namespace

static ImportBatch parse_cyclictest_json(const std::string& text_in, const std::string& file,
                                         const ParseOptions& /*options*/, const ImportLimits& limits,
                                         const CancelToken& cancel) {
  std::vector<std::string> warnings;
  std::string text = null_nan_averages(text_in, file, &warnings);
  json doc;
  try {
    doc = json_access::parse(text, file, limits, &cancel);
  } catch (const ImportError& e) {
    if (e.category() != ImportErrorCategory::Syntax) throw;
    auto mended = escape_command_line(text);
    if (!mended) throw;
    try {
      doc = json_access::parse(mended->first, file, limits, &cancel);
    } catch (const ImportError&) {
      throw e;  // the document is broken elsewhere too: the first error is the one to fix
    }
    warnings.push_back(headroom_import::where(file, mended->second) +
                       "the command line holds a '\"' or '\\' that rt-tests wrote without escaping (not valid JSON); "
                       "read with that string escaped");
    text = std::move(mended->first);
  }
  const Reader r(file, text);
  return parse_document(doc, r, limits, std::move(warnings));
}

static int sniff_cyclictest_json(std::string_view head, std::string_view) {
  const auto has = [&](std::string_view w) { return head.find(w) != std::string_view::npos; };
  const std::size_t start = head.find_first_not_of(" \t\r\n");
  if (start == std::string_view::npos || head[start] != '{') return 0;
  const bool rt_tests = has("\"rt_test_version") || (has("\"cmdline") && has("\"num_threads\""));
  if (!rt_tests) return 0;
  // Another rt-tests program writes the same frame; claim it anyway so the error can name the program.
  return has("cyclictest") ? 95 : 40;
}

const FileFormat kCyclictestJsonFileFormat{"cyclictest-json",     "cyclictest --json (rt-tests)",
                                           sniff_cyclictest_json, parse_text_file_with<parse_cyclictest_json>,
                                           parse_cyclictest_json, ".json"};

}  // namespace bs
