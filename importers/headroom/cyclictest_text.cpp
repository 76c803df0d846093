// SPDX-License-Identifier: GPL-3.0-or-later
#include "headroom/cyclictest_text.h"

#include <algorithm>
#include <charconv>
#include <map>
#include <optional>
#include <vector>

#include "common/text_file.h"
#include "headroom/cyclictest_command.h"
#include "headroom/cyclictest_threads.h"
#include "headroom/imported_latency.h"
#include "headroom/text_lines.h"

namespace bs {
namespace {

using headroom_import::TextLine;
using headroom_import::trim;
using headroom_import::whole_number;
using headroom_import::words_of;

// One numeric line of the footer ("# Max Latencies: 00020 00020 00340"), with where it was.
struct FooterLine {
  std::vector<std::int64_t> values;
  std::size_t line = 0;
};

struct Row {
  std::int64_t bucket = 0;
  std::vector<std::uint64_t> counts;
  std::size_t line = 0;
};

bool all_digits(std::string_view s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

class CyclictestTextParser {
 public:
  CyclictestTextParser(const std::string& file, const ImportLimits& limits) : file_(file), limits_(limits) {}

  void line(const TextLine& raw) {
    last_line_ = raw.number;
    if (!raw.has_line_end) cut_line_ = raw.number;
    const std::string cleaned = headroom_import::strip_terminal_codes(raw.text);
    const std::string_view text = trim(cleaned);
    if (text.empty()) return;
    if (text.starts_with("#")) {
      comment(text, raw.number);
      return;
    }
    if (in_rows() && row(text, raw.number, raw.has_line_end)) return;
    if (auto t = headroom_import::parse_status_line(text, raw.number)) {
      status_[t->index] = *t;
      return;
    }
    if (text.starts_with("policy:")) {
      policy_line_ = std::string(trim(text.substr(7)));
      return;
    }
    if (!command_ && !histogram_line_) {
      if (auto cmd = headroom_import::parse_cyclictest_command(text)) {
        command_ = std::move(cmd);
        return;
      }
    }
    if (in_rows())
      fail(ImportErrorCategory::Syntax, raw.number,
           "expected a histogram row (bucket, then one count per thread) or the '# Min Latencies:' footer, found '" +
               std::string(text.substr(0, 60)) + "'");
    // Anything else outside the histogram (a banner, other programs' output) is not cyclictest's and is skipped.
  }

  ImportBatch finish() {
    const bool footer = min_ || max_ || overflows_;
    if (!histogram_line_ && rows_.empty() && !footer && status_.empty())
      throw ImportError(ImportErrorCategory::MissingField, {file_, last_line_, 0, {}},
                        "no cyclictest output found: no '# Histogram' rows, no '# Min/Avg/Max Latencies' footer and "
                        "no 'T: 0 (pid) P:.. I:.. C:.. Min: Act: Avg: Max:' status lines");
    if ((histogram_line_ || !rows_.empty()) && !(min_ && max_ && overflows_)) {
      const std::size_t last_row = rows_.empty() ? histogram_line_ : rows_.back().line;
      throw ImportError(ImportErrorCategory::Syntax, {file_, last_line_, 0, {}},
                        "the histogram is cut: it starts at line " + std::to_string(histogram_line_) +
                            ", its last row is line " + std::to_string(last_row) + ", and the '" +
                            missing_footer_line() + "' line that ends it is missing (truncated file)");
    }
    if (footer && !(min_ && max_ && overflows_))
      throw ImportError(ImportErrorCategory::MissingField, {file_, last_line_, 0, {}},
                        "the latency footer is incomplete: no '" + missing_footer_line() + "' line");
    headroom::HeadroomMeasurement m =
        headroom_import::imported_measurement(headroom::LatencyKind::SystemWakeup, "cyclictest", file_);
    headroom::Phase& phase = m.phases.front();
    const bool ns = unit_is_ns();
    const std::int64_t unit_ns = ns ? 1 : 1000;
    if (footer) {
      histogram_threads(&phase, unit_ns);
    } else {
      status_threads(&phase, unit_ns);
    }
    describe(&m, ns);
    ImportBatch batch = headroom_import::batch_of(std::move(m), file_);
    batch.warnings = std::move(warnings_);
    if (cut_line_)
      batch.warnings.push_back(headroom_import::where(file_, cut_line_) +
                               "the last line has no line end: the file may have been cut while it was written");
    return batch;
  }

 private:
  [[noreturn]] void fail(ImportErrorCategory category, std::size_t line, const std::string& reason) const {
    throw ImportError(category, {file_, line, 0, {}}, reason);
  }
  void warn(std::size_t line, const std::string& what) {
    warnings_.push_back(headroom_import::where(file_, line) + what);
  }

  bool in_rows() const { return histogram_line_ != 0 && !min_ && !total_; }

  std::string missing_footer_line() const {
    if (!min_) return "# Min Latencies:";
    if (!max_) return "# Max Latencies:";
    return "# Histogram Overflows:";
  }

  FooterLine numbers(std::string_view rest, std::size_t line, std::string_view what) const {
    FooterLine out;
    out.line = line;
    for (std::string_view w : words_of(rest)) {
      std::int64_t v = 0;
      if (!whole_number(w, &v))
        fail(ImportErrorCategory::Syntax, line,
             std::string(what) + ": '" + std::string(w) + "' is not a whole number (the line may be cut)");
      if (v > kMaxValue || v < -kMaxValue)
        fail(ImportErrorCategory::InvalidValue, line, std::string(what) + ": " + std::string(w) + " is out of range");
      out.values.push_back(v);
    }
    if (out.values.empty()) fail(ImportErrorCategory::MissingField, line, std::string(what) + " lists no thread");
    return out;
  }

  void comment(std::string_view text, std::size_t line) {
    const auto after = [&](std::string_view label) { return text.substr(label.size()); };
    if (text == "# Histogram") {
      if (histogram_line_)
        fail(ImportErrorCategory::Unsupported, line,
             "a second '# Histogram' (the first is at line " + std::to_string(histogram_line_) +
                 "): two runs in one file; import each run from a file of its own");
      histogram_line_ = line;
    } else if (text.starts_with("# Total:")) {
      total_ = numbers(after("# Total:"), line, "# Total");
    } else if (text.starts_with("# Min Latencies:")) {
      min_ = numbers(after("# Min Latencies:"), line, "# Min Latencies");
    } else if (text.starts_with("# Avg Latencies:")) {
      avg_ = numbers(after("# Avg Latencies:"), line, "# Avg Latencies");
    } else if (text.starts_with("# Max Latencies:")) {
      max_ = numbers(after("# Max Latencies:"), line, "# Max Latencies");
    } else if (text.starts_with("# Histogram Overflows:")) {
      overflows_ = numbers(after("# Histogram Overflows:"), line, "# Histogram Overflows");
    } else if (text.starts_with("# /dev/cpu_dma_latency set to")) {
      notes_.push_back(std::string(trim(text.substr(2))));
    } else if (text.starts_with("# Break thread:") || text.starts_with("# Break value:")) {
      notes_.push_back("cyclictest stopped at its -b break threshold: " + std::string(trim(text.substr(2))));
    } else if (!command_ && !histogram_line_) {
      // "# cyclictest -m -p99 -h400 > out.txt": a command written as a comment above the output.
      if (auto cmd = headroom_import::parse_cyclictest_command(text.substr(1))) command_ = std::move(cmd);
    }
    // "# Histogram Overflow at cycle number:", "# Thread N: ..." (which cycles overflowed), "# SMIs:",
    // "# Thread Ids:": nothing a latency distribution needs.
  }

  // "000004 013847\t003773": bucket, then one count per thread (and -H's sum). Whitespace is accepted for tabs (a
  // paste may have turned them into spaces). False when the line is not a row at all.
  bool row(std::string_view text, std::size_t line, bool has_line_end) {
    const std::vector<std::string_view> words = words_of(text);
    if (words.size() < 2 || !all_digits(words[0])) return false;
    Row r;
    r.line = line;
    if (!whole_number(words[0], &r.bucket) || r.bucket > kMaxBuckets)
      fail(ImportErrorCategory::InvalidValue, line,
           "histogram bucket '" + std::string(words[0]) + "' is beyond cyclictest's limit of " +
               std::to_string(kMaxBuckets) + " buckets");
    for (std::size_t i = 1; i < words.size(); ++i) {
      std::uint64_t v = 0;
      if (!whole_number(words[i], &v) || v > static_cast<std::uint64_t>(kMaxValue))
        fail(ImportErrorCategory::Syntax, line,
             "histogram row " + std::string(words[0]) + ", column " + std::to_string(i) + ": '" +
                 std::string(words[i]) + "' is not a count");
      r.counts.push_back(v);
    }
    if (!rows_.empty()) {
      const Row& prev = rows_.back();
      if (r.bucket <= prev.bucket)
        fail(ImportErrorCategory::Syntax, line,
             "histogram bucket " + std::to_string(r.bucket) + " follows bucket " + std::to_string(prev.bucket) +
                 " (line " + std::to_string(prev.line) + "): rows must ascend");
      // A last row cut while the file was written is dropped; the missing footer then says the file is cut.
      if (r.counts.size() != prev.counts.size() && !has_line_end) return true;
      if (r.counts.size() != prev.counts.size())
        fail(ImportErrorCategory::Syntax, line,
             "histogram row " + std::to_string(r.bucket) + " has " + std::to_string(r.counts.size()) +
                 " columns, the rows above have " + std::to_string(prev.counts.size()) + " (the row may be cut)");
    }
    rows_.push_back(std::move(r));
    return true;
  }

  bool unit_is_ns() {
    if (command_) return command_->nsecs;
    // cyclictest prints Act and Avg 8 wide with -N and 5 wide without.
    for (const auto& [index, t] : status_)
      if (t.nsecs) return *t.nsecs;
    return false;
  }

  // The histogram's size in buckets: the command's -h/-H when known, else (before 2.7, every row printed) the rows'
  // count, else the highest printed bucket + 1 (a lower bound; the note says so).
  std::size_t bucket_count() {
    const std::int64_t highest = rows_.empty() ? -1 : rows_.back().bucket;
    if (command_ && command_->histogram_bins && *command_->histogram_bins > 0) {
      const std::int64_t bins = std::min<std::int64_t>(*command_->histogram_bins, kMaxBuckets);
      if (highest >= bins)
        fail(ImportErrorCategory::InvalidValue, rows_.back().line,
             "histogram bucket " + std::to_string(highest) + " lies beyond the " + std::to_string(bins) +
                 " buckets the command line asks for");
      return static_cast<std::size_t>(bins);
    }
    if (!total_) limit_unknown_ = true;
    return static_cast<std::size_t>(std::max<std::int64_t>(highest + 1, 1));
  }

  void histogram_threads(headroom::Phase* phase, std::int64_t unit_ns) {
    const std::size_t n = min_->values.size();
    const auto check_columns = [&](const FooterLine& f, std::string_view what, bool may_have_sum) {
      if (f.values.size() == n || (may_have_sum && n > 1 && f.values.size() == n + 1)) return;
      fail(ImportErrorCategory::Syntax, f.line,
           std::string(what) + " lists " + std::to_string(f.values.size()) + " values for the " + std::to_string(n) +
               " threads of '# Min Latencies:' (line " + std::to_string(min_->line) + ")");
    };
    check_columns(*max_, "# Max Latencies", true);
    check_columns(*overflows_, "# Histogram Overflows", true);
    if (avg_) check_columns(*avg_, "# Avg Latencies", false);
    if (total_) check_columns(*total_, "# Total", true);
    const bool have_rows = !rows_.empty();
    if (have_rows) {
      const std::size_t columns = rows_.front().counts.size();
      if (columns != n && columns != n + 1)
        fail(ImportErrorCategory::Syntax, rows_.front().line,
             "histogram rows have " + std::to_string(columns) + " count columns for the " + std::to_string(n) +
                 " threads of the footer (line " + std::to_string(min_->line) + ")");
      if (columns == n + 1) check_sum_column();
    }
    if (overflows_->values.size() == n + 1) check_footer_sum(*overflows_, "# Histogram Overflows", false);
    if (max_->values.size() == n + 1) check_footer_sum(*max_, "# Max Latencies", true);

    // Rows stripped: the footer alone. Without a "# Histogram" line that is plain. With one, it depends on the
    // format: rt-tests before 2.7 prints every row and then "# Total:", so "# Histogram" followed by "# Total:" and
    // no row is a footer whose rows were stripped (the ros-realtime benchmark results publish cyclictest's output
    // so); from 2.7 on (no "# Total:") empty rows are left out, and no row means every cycle overflowed.
    const bool rows_stripped = !have_rows && (!histogram_line_ || total_);
    const bool summary = rows_stripped;
    const std::size_t buckets = summary ? 0 : bucket_count();
    if (!summary && n * buckets > limits_.max_samples)
      throw ImportError(ImportErrorCategory::TooLarge, {file_, histogram_line_, 0, {}},
                        std::to_string(n) + " threads x " + std::to_string(buckets) +
                            " histogram buckets is beyond the import limit of " + std::to_string(limits_.max_samples) +
                            " counts");
    for (std::size_t j = 0; j < n; ++j) {
      const int index = static_cast<int>(j);
      const std::int64_t overflows = overflows_->values[j];
      if (total_ && total_->values[j] < 0)
        fail(ImportErrorCategory::InvalidValue, total_->line, "thread " + std::to_string(j) + ": a negative total");
      if (overflows < 0)
        fail(ImportErrorCategory::InvalidValue, overflows_->line,
             "thread " + std::to_string(j) + ": a negative overflow count");
      headroom::ThreadLatency t;
      if (summary) {
        std::optional<std::uint64_t> cycles;
        if (total_) cycles = static_cast<std::uint64_t>(total_->values[j] + overflows);
        if (auto s = status_.find(index); !cycles && s != status_.end()) cycles = s->second.cycles;
        const bool ran = !cycles || *cycles > 0;
        t = headroom_import::summary_only_thread(
            index, cycles, ran ? std::optional<std::int64_t>(min_->values[j] * unit_ns) : std::nullopt,
            ran ? std::optional<std::int64_t>(max_->values[j] * unit_ns) : std::nullopt,
            avg_ && ran ? std::optional<double>(static_cast<double>(avg_->values[j] * unit_ns)) : std::nullopt,
            std::nullopt);
      } else {
        t.index = index;
        t.histogram.bin_ns = unit_ns;
        t.histogram.bins.assign(buckets, 0);
        for (const Row& r : rows_) t.histogram.bins[static_cast<std::size_t>(r.bucket)] = r.counts[j];
        const std::uint64_t binned = t.histogram.binned();
        if (total_ && static_cast<std::uint64_t>(total_->values[j]) != binned)
          fail(ImportErrorCategory::Syntax, total_->line,
               "thread " + std::to_string(j) + ": '# Total:' says " + std::to_string(total_->values[j]) +
                   " but its rows add up to " + std::to_string(binned) + " (rows missing or edited)");
        t.histogram.overflows = static_cast<std::uint64_t>(overflows);
        t.histogram.cycles = binned + t.histogram.overflows;
        if (t.histogram.cycles > 0) {
          // cyclictest starts min at 1000000 and max at 0: only a thread that ran has extremes.
          t.histogram.min_ns = min_->values[j] * unit_ns;
          t.histogram.max_ns = max_->values[j] * unit_ns;
          // The footer's maximum is exact; the histogram's bucket is its lower edge.
          if (const std::string e = t.histogram.bookkeeping_error(); !e.empty())
            fail(ImportErrorCategory::InvalidValue, max_->line,
                 "thread " + std::to_string(j) + ": the footer disagrees with the histogram: " + e);
        }
      }
      headroom_import::apply_thread_facts(&t, index, command_, status_, policy_line_);
      phase->threads.push_back(std::move(t));
    }
    if (!status_.empty() && status_.size() != n)
      warn(status_.begin()->second.line, std::to_string(status_.size()) + " status lines ('T: ...') for the " +
                                             std::to_string(n) + " threads of the histogram");
    if (summary)
      phase->notes.push_back(std::string(headroom_import::kSummaryOnlyNote) +
                             (histogram_line_ ? " (the histogram rows were stripped: '# Histogram' at line " +
                                                    std::to_string(histogram_line_) +
                                                    " is followed by the footer alone, per thread the cycles of "
                                                    "'# Total:' plus the overflows, min, mean and max)"
                                              : std::string(" (the histogram rows were stripped; only the footer "
                                                            "is left)")));
    if (limit_unknown_)
      phase->notes.push_back(
          "histogram size not recorded (no -h/-H command line): its range is taken as up to the "
          "highest printed bucket, so overflows lie at least that far out");
    if (avg_ && summary)
      phase->notes.push_back(
          "cyclictest's '# Avg Latencies' are whole units (truncated): the mean shown is that, not an exact mean");
    if (avg_ && !summary)
      phase->notes.push_back(
          "cyclictest's '# Avg Latencies' are whole units (truncated); the mean shown is the "
          "histogram's");
  }

  void status_threads(headroom::Phase* phase, std::int64_t unit_ns) {
    for (const auto& [index, s] : status_) {
      const bool ran = s.cycles > 0;
      headroom::ThreadLatency t = headroom_import::summary_only_thread(
          index, s.cycles, ran ? std::optional<std::int64_t>(s.min * unit_ns) : std::nullopt,
          ran ? std::optional<std::int64_t>(s.max * unit_ns) : std::nullopt,
          ran ? std::optional<double>(static_cast<double>(s.avg * unit_ns)) : std::nullopt, std::nullopt);
      headroom_import::apply_thread_facts(&t, index, command_, status_, policy_line_);
      phase->threads.push_back(std::move(t));
    }
    phase->notes.push_back(std::string(headroom_import::kSummaryOnlyNote) +
                           " (cyclictest's status lines: cycles, min, average truncated to whole units, max)");
  }

  void check_sum_column() {
    for (const Row& r : rows_) {
      std::uint64_t sum = 0;
      for (std::size_t j = 0; j + 1 < r.counts.size(); ++j) sum += r.counts[j];
      if (sum != r.counts.back())
        fail(ImportErrorCategory::InvalidValue, r.line,
             "histogram row " + std::to_string(r.bucket) + ": the -H sum column says " +
                 std::to_string(r.counts.back()) + " but the threads add up to " + std::to_string(sum));
    }
  }

  void check_footer_sum(const FooterLine& f, std::string_view what, bool is_max) {
    std::int64_t expected = 0;
    for (std::size_t j = 0; j + 1 < f.values.size(); ++j)
      expected = is_max ? std::max(expected, f.values[j]) : expected + f.values[j];
    if (expected != f.values.back())
      fail(ImportErrorCategory::InvalidValue, f.line,
           std::string(what) + ": the -H summary column says " + std::to_string(f.values.back()) +
               " but the threads' " + (is_max ? "largest is " : "sum is ") + std::to_string(expected));
  }

  void describe(headroom::HeadroomMeasurement* m, bool ns) {
    headroom::Phase& phase = m->phases.front();
    for (std::string& n : notes_) phase.notes.push_back(std::move(n));
    auto& settings = m->provenance.settings;
    if (command_) {
      m->command = command_->text;
      settings.emplace_back("command", command_->text);
    }
    if (!rows_.empty() || (histogram_line_ && !total_))
      settings.emplace_back("histogram format", total_ ? "every row and '# Total:' (rt-tests before 2.7)"
                                                       : "non-empty rows only (rt-tests 2.7 and later)");
    settings.emplace_back("latency unit", ns ? "ns (-N)" : (command_ || !status_.empty()) ? "us" : "us (assumed)");
    if (!policy_line_.empty()) settings.emplace_back("policy line", policy_line_);
    m->provenance.note = ns || command_ || !status_.empty()
                             ? ""
                             : "the file does not record -N: read as microseconds, cyclictest's default";
  }

  static constexpr std::int64_t kMaxBuckets = 1000000;  // cyclictest's HIST_MAX
  // Counts and latencies beyond this are not a real run (a latency of 10^15 us is 31 years), and would overflow
  // on the way to nanoseconds.
  static constexpr std::int64_t kMaxValue = 1'000'000'000'000'000;

  const std::string& file_;
  const ImportLimits& limits_;
  std::size_t last_line_ = 0;
  std::size_t cut_line_ = 0;
  std::size_t histogram_line_ = 0;
  std::vector<Row> rows_;
  std::optional<FooterLine> total_, min_, avg_, max_, overflows_;
  std::map<int, headroom_import::StatusLine> status_;
  std::string policy_line_;
  std::optional<headroom_import::CyclictestCommand> command_;
  std::vector<std::string> notes_;
  std::vector<std::string> warnings_;
  bool limit_unknown_ = false;
};

}  // namespace

static ImportBatch parse_cyclictest_text(const std::string& text, const std::string& file,
                                         const ParseOptions& /*options*/, const ImportLimits& limits,
                                         const CancelToken& cancel) {
  CyclictestTextParser parser(file, limits);
  return headroom_import::parse_lines(parser, text, cancel);
}

static int sniff_cyclictest_text(std::string_view head, std::string_view) {
  const auto has = [&](std::string_view w) { return head.find(w) != std::string_view::npos; };
  const bool footer = has("# Min Latencies:") || has("# Max Latencies:") || has("# Histogram Overflows:");
  if (has("# Histogram\n") || has("# Histogram\r\n")) return footer || has("# Total:") ? 95 : 85;
  if (footer) return 90;
  // A terminal capture: status lines "T: 0 ( 1234) P:99 I:1000 C:" with Min/Act/Avg/Max.
  if (has("T: 0 (") && has(" I:") && has(" C:") && has("Min:") && has("Act:") && has("Max:")) return 85;
  return 0;
}

const FileFormat kCyclictestTextFileFormat{"cyclictest-text",     "cyclictest histogram or terminal output (rt-tests)",
                                           sniff_cyclictest_text, parse_text_file_with<parse_cyclictest_text>,
                                           parse_cyclictest_text, ".hist .txt .log"};

}  // namespace bs
