// SPDX-License-Identifier: GPL-3.0-or-later
#include "headroom/rttest_statistics.h"

#include <charconv>
#include <cmath>
#include <optional>

#include "common/text_file.h"
#include "headroom/imported_latency.h"
#include "headroom/text_lines.h"

namespace bs {
namespace {

using headroom_import::TextLine;
using headroom_import::trim;

// One set of latency statistics and where its lines were.
struct Statistics {
  std::optional<double> min, max, mean, sd;
  std::optional<std::uint64_t> minor_faults, major_faults, missed, early;
  std::size_t first_line = 0;
  bool analyze_py = false;  // the analyze.py form (absolute values)
};

// The number after `label` in `text` ("- Min: 2414 ns", "Mean latency: 11074.75"); a trailing "ns" is allowed.
std::optional<double> value_after(std::string_view text, std::string_view label, const std::string& file,
                                  std::size_t line) {
  if (!text.starts_with(label)) return std::nullopt;
  std::string_view v = trim(text.substr(label.size()));
  if (v.ends_with("ns")) v = trim(v.substr(0, v.size() - 2));
  double d = 0;
  const auto [ptr, ec] = std::from_chars(v.data(), v.data() + v.size(), d);
  if (ec != std::errc() || ptr != v.data() + v.size() || !std::isfinite(d) || std::abs(d) > 1e15)
    throw ImportError(ImportErrorCategory::Syntax, {file, line, label.size() + 1, std::string(trim(label))},
                      "'" + std::string(v) + "' is not a number (the line may be cut)");
  return d;
}

std::optional<std::uint64_t> count_after(std::string_view text, std::string_view label, const std::string& file,
                                         std::size_t line) {
  const auto d = value_after(text, label, file, line);
  if (!d) return std::nullopt;
  if (*d < 0 || *d != std::floor(*d))
    throw ImportError(ImportErrorCategory::InvalidValue, {file, line, 0, std::string(trim(label))},
                      "a count must be a whole number, not " + std::to_string(*d));
  return static_cast<std::uint64_t>(*d);
}

class StatisticsParser {
 public:
  explicit StatisticsParser(const std::string& file) : file_(file) {}

  void line(const TextLine& raw) {
    if (!raw.has_line_end) cut_line_ = raw.number;
    std::string_view t = trim(raw.text);
    if (t.empty()) return;
    const std::size_t n = raw.number;
    // analyze.py's form.
    if (auto v = value_after(t, "Min latency:", file_, n)) {
      start_block(n, true);
      current_.min = v;
    } else if (auto v2 = value_after(t, "Max latency:", file_, n)) {
      start_block(n, true);
      current_.max = v2;
    } else if (auto v3 = value_after(t, "Mean latency:", file_, n)) {
      start_block(n, true);
      current_.mean = v3;
    } else if (t.starts_with("# of samples overrun:")) {
      overrun_line_ = n;
    } else if (t.starts_with("rttest statistics")) {
      // rttest's block: a new one starts here (pendulum_demo may print several; the last is the run's end).
      finish_block();
      current_ = Statistics{};
      current_.first_line = n;
      section_ = Section::Header;
      ++blocks_;
    } else if (t.starts_with("Latency (")) {
      section_ = Section::Latency;
    } else if (t.starts_with("Jitter (")) {
      section_ = Section::Jitter;
    } else if (t.starts_with("- ")) {
      item(trim(t.substr(2)), n);
    } else if (t.find(" received ") != std::string_view::npos && t.ends_with(" messages")) {
      notes_.push_back(std::string(t));  // pendulum_demo: "PendulumMotor received 985 messages"
    }
  }

  ImportBatch finish() {
    finish_block();
    if (!last_)
      throw ImportError(ImportErrorCategory::MissingField, {file_, 0, 0, {}},
                        "no rttest latency statistics ('Min latency:' / 'Max latency:' / 'Mean latency:', or an "
                        "'rttest statistics:' block with '- Min:' / '- Max:' / '- Mean:')");
    const Statistics& s = *last_;
    if (!s.min || !s.max || !s.mean)
      throw ImportError(ImportErrorCategory::MissingField, {file_, s.first_line, 0, {}},
                        std::string("the statistics lack their ") +
                            (!s.min   ? "minimum"
                             : !s.max ? "maximum"
                                      : "mean") +
                            " latency (the output may be cut)");
    if (*s.min > *s.max || *s.mean < *s.min || *s.mean > *s.max)
      throw ImportError(ImportErrorCategory::InvalidValue, {file_, s.first_line, 0, {}},
                        "min, mean and max latency are not in order (" + std::to_string(*s.min) + ", " +
                            std::to_string(*s.mean) + ", " + std::to_string(*s.max) + " ns)");
    headroom::HeadroomMeasurement m =
        headroom_import::imported_measurement(headroom::LatencyKind::ApplicationLoop, "rttest", file_);
    headroom::Phase& phase = m.phases.front();
    headroom::ThreadLatency t =
        headroom_import::summary_only_thread(0, std::nullopt, static_cast<std::int64_t>(std::llround(*s.min)),
                                             static_cast<std::int64_t>(std::llround(*s.max)), s.mean, s.sd);
    phase.threads.push_back(std::move(t));
    phase.notes.push_back(std::string(headroom_import::kSummaryOnlyNote) + "; the number of iterations is not given");
    if (s.analyze_py) phase.notes.push_back("rttest's analyze.py: statistics of the absolute latencies");
    if (s.minor_faults || s.major_faults)
      phase.notes.push_back("page faults during the run: " + std::to_string(s.minor_faults.value_or(0)) + " minor, " +
                            std::to_string(s.major_faults.value_or(0)) + " major");
    if (s.missed)
      phase.notes.push_back("rttest counted " + std::to_string(*s.missed) + " missed and " +
                            std::to_string(s.early.value_or(0)) + " early deadlines");
    if (blocks_ > 1)
      phase.notes.push_back("the last of " + std::to_string(blocks_) + " 'rttest statistics' blocks (line " +
                            std::to_string(s.first_line) + ")");
    for (std::string& note : notes_) phase.notes.push_back(std::move(note));
    m.provenance.settings.emplace_back("form", s.analyze_py ? "analyze.py statistics" : "rttest statistics block");
    ImportBatch batch = headroom_import::batch_of(std::move(m), file_);
    if (overrun_line_)
      batch.warnings.push_back(headroom_import::where(file_, overrun_line_) +
                               "'# of samples overrun' is not a count: rttest's analyze.py prints len() of the tuple "
                               "numpy.where returns, which is 1 whatever the data; ignored");
    if (cut_line_)
      batch.warnings.push_back(headroom_import::where(file_, cut_line_) +
                               "the last line has no line end: the file may have been cut while it was written");
    return batch;
  }

 private:
  enum class Section { None, Header, Latency, Jitter };

  void start_block(std::size_t line, bool analyze_py) {
    if (!current_.first_line) {
      current_.first_line = line;
      current_.analyze_py = analyze_py;
      ++blocks_;
    }
  }

  void finish_block() {
    if (current_.min || current_.max || current_.mean) last_ = current_;
  }

  void item(std::string_view t, std::size_t n) {
    if (auto v = count_after(t, "Minor pagefaults:", file_, n)) {
      current_.minor_faults = v;
    } else if (auto v2 = count_after(t, "Major pagefaults:", file_, n)) {
      current_.major_faults = v2;
    } else if (auto v3 = count_after(t, "Missed deadlines:", file_, n)) {
      current_.missed = v3;
    } else if (auto v4 = count_after(t, "Early deadlines:", file_, n)) {
      current_.early = v4;
    } else if (section_ == Section::Latency) {
      // The Jitter section's Min/Max are not latencies and are skipped.
      if (auto a = value_after(t, "Min:", file_, n)) current_.min = a;
      if (auto b = value_after(t, "Max:", file_, n)) current_.max = b;
      if (auto c = value_after(t, "Mean:", file_, n)) current_.mean = c;
      if (auto d = value_after(t, "Standard deviation:", file_, n)) current_.sd = d;
    }
  }

  const std::string& file_;
  Statistics current_;
  std::optional<Statistics> last_;
  Section section_ = Section::None;
  std::size_t blocks_ = 0;
  std::size_t overrun_line_ = 0;
  std::size_t cut_line_ = 0;
  std::vector<std::string> notes_;
};

}  // namespace

static ImportBatch parse_rttest_statistics(const std::string& text, const std::string& file,
                                           const ParseOptions& /*options*/, const ImportLimits& /*limits*/,
                                           const CancelToken& cancel) {
  StatisticsParser parser(file);
  return headroom_import::parse_lines(parser, text, cancel);
}

static int sniff_rttest_statistics(std::string_view head, std::string_view) {
  const auto has = [&](std::string_view w) { return head.find(w) != std::string_view::npos; };
  if (has("rttest statistics") && has("Latency (time after deadline was missed)")) return 95;
  if (has("Min latency:") && has("Max latency:") && has("Mean latency:")) return 85;
  return 0;
}

const FileFormat kRttestStatisticsFileFormat{
    "rttest-statistics",     "ROS 2 rttest statistics (analyze.py summary or rttest's final block)",
    sniff_rttest_statistics, parse_text_file_with<parse_rttest_statistics>,
    parse_rttest_statistics, ".txt .log"};

}  // namespace bs
