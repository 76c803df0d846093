// SPDX-License-Identifier: GPL-3.0-or-later
#include "headroom/performance_test_csv.h"

#include <charconv>
#include <cmath>
#include <map>

#include "common/text_file.h"
#include "headroom/imported_latency.h"
#include "headroom/performance_test_rows.h"
#include "headroom/text_lines.h"

namespace bs {
namespace {

using headroom_import::PerfTestRow;
using headroom_import::TextLine;
using headroom_import::trim;

// The cells of a row: comma-separated, each trimmed of the tabs performance_test pads with; a trailing empty cell
// (every value is followed by a comma in older versions) is dropped.
std::vector<std::string_view> cells_of(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t pos = 0;
  while (pos <= line.size()) {
    const std::size_t comma = std::min(line.find(',', pos), line.size());
    out.push_back(trim(line.substr(pos, comma - pos)));
    pos = comma + 1;
  }
  if (!out.empty() && out.back().empty()) out.pop_back();
  return out;
}

// Seconds per unit of a header's "(ms)" / "(us)" / "(ns)" / "(s)"; nullopt for anything else.
std::optional<double> unit_scale(std::string_view header) {
  const auto open = header.rfind('(');
  if (open == std::string_view::npos || !header.ends_with(")")) return std::nullopt;
  const std::string_view u = header.substr(open + 1, header.size() - open - 2);
  if (u == "s") return 1.0;
  if (u == "ms") return 1e-3;
  if (u == "us") return 1e-6;
  if (u == "ns") return 1e-9;
  return std::nullopt;
}

std::string_view name_of(std::string_view header) {
  const auto open = header.find(" (");
  return open == std::string_view::npos ? header : header.substr(0, open);
}

struct Columns {
  std::size_t t_experiment = 0, t_loop = 0, received = 0, sent = 0, min = 0, max = 0, mean = 0, variance = 0;
  double scale = 1e-3;  // seconds per unit of the latency columns
  std::size_t count = 0;
};

class CsvParser {
 public:
  explicit CsvParser(const std::string& file) : file_(file) {}

  void line(const TextLine& raw) {
    last_line_ = raw.number;
    const std::string_view t = trim(raw.text);
    if (t.empty()) return;
    if (t.starts_with("---")) {
      if (t == "---EXPERIMENT-START---") start_line_ = raw.number;
      return;  // a start or end marker
    }
    if (!columns_) {
      if (t.starts_with("T_experiment")) {
        header(t, raw.number);
        return;
      }
      if (start_line_ == 0) {
        setting(t);
        return;
      }
      throw ImportError(ImportErrorCategory::MissingField, {file_, raw.number, 1, {}},
                        "expected the header row 'T_experiment, T_loop, received, sent, ...' after "
                        "---EXPERIMENT-START--- (line " +
                            std::to_string(start_line_) + ")");
    }
    row(t, raw);
  }

  ImportBatch finish() {
    if (!columns_)
      throw ImportError(ImportErrorCategory::MissingField, {file_, last_line_, 0, {}},
                        "no statistics header row ('T_experiment, T_loop, received, ...'): not a performance_test log, "
                        "or the log was cut before its first row");
    if (rows_.empty())
      throw ImportError(ImportErrorCategory::MissingField, {file_, header_line_, 0, {}},
                        "the header row is not followed by any statistics row (the experiment wrote none)");
    const headroom_import::CombinedLatency combined = headroom_import::combine_rows(rows_, rate_);
    ImportBatch batch =
        headroom_import::batch_of(headroom_import::perf_test_measurement(combined, std::move(settings_), file_), file_);
    batch.warnings = std::move(warnings_);
    return batch;
  }

 private:
  void setting(std::string_view t) {
    const auto colon = t.find(':');
    if (colon == std::string_view::npos) return;
    const std::string key(trim(t.substr(0, colon)));
    const std::string value(trim(t.substr(colon + 1)));
    settings_.emplace_back(key, value);
    if (key == "Publishing rate") {
      double rate = 0;
      const auto [ptr, ec] = std::from_chars(value.data(), value.data() + value.size(), rate);
      if (ec == std::errc() && ptr == value.data() + value.size() && std::isfinite(rate) && rate > 0) rate_ = rate;
    }
  }

  void header(std::string_view t, std::size_t line) {
    const std::vector<std::string_view> cells = cells_of(t);
    std::map<std::string_view, std::size_t> index;
    for (std::size_t i = 0; i < cells.size(); ++i) index.emplace(name_of(cells[i]), i);
    const auto need = [&](std::string_view name) {
      const auto it = index.find(name);
      if (it == index.end())
        throw ImportError(ImportErrorCategory::MissingField, {file_, line, 0, std::string(name)},
                          "the header row has no '" + std::string(name) + "' column");
      return it->second;
    };
    Columns c;
    c.t_experiment = need("T_experiment");
    c.t_loop = need("T_loop");
    c.received = need("received");
    c.sent = need("sent");
    c.min = need("latency_min");
    c.max = need("latency_max");
    c.mean = need("latency_mean");
    c.variance = need("latency_variance");
    for (std::size_t col : {c.min, c.max, c.mean}) {
      const auto scale = unit_scale(cells[col]);
      if (!scale)
        throw ImportError(ImportErrorCategory::Unsupported, {file_, line, 0, std::string(cells[col])},
                          "no time unit BenchScope knows in '" + std::string(cells[col]) + "' (ms, us, ns or s)");
      if (col != c.min && *scale != c.scale)
        throw ImportError(ImportErrorCategory::Unsupported, {file_, line, 0, std::string(cells[col])},
                          "the latency columns name different units");
      c.scale = *scale;
    }
    c.count = cells.size();
    columns_ = c;
    header_line_ = line;
    settings_.emplace_back("latency unit",
                           std::string(cells[c.mean].substr(cells[c.mean].rfind('(') + 1,
                                                            cells[c.mean].size() - cells[c.mean].rfind('(') - 2)));
  }

  double cell(const std::vector<std::string_view>& cells, std::size_t col, const TextLine& raw) const {
    const std::string_view v = cells[col];
    double d = 0;
    const auto [ptr, ec] = std::from_chars(v.data(), v.data() + v.size(), d);
    if (ec != std::errc() || ptr != v.data() + v.size() || !std::isfinite(d))
      throw ImportError(ImportErrorCategory::Syntax, {file_, raw.number, 0, std::string(column_name(col))},
                        "'" + std::string(v) + "' is not a number");
    return d;
  }

  std::string_view column_name(std::size_t col) const {
    const Columns& c = *columns_;
    if (col == c.t_experiment) return "T_experiment";
    if (col == c.t_loop) return "T_loop";
    if (col == c.received) return "received";
    if (col == c.sent) return "sent";
    if (col == c.min) return "latency_min";
    if (col == c.max) return "latency_max";
    if (col == c.mean) return "latency_mean";
    return "latency_variance";
  }

  void row(std::string_view t, const TextLine& raw) {
    const Columns& c = *columns_;
    const std::vector<std::string_view> cells = cells_of(t);
    if (cells.size() != c.count) {
      if (!raw.has_line_end && cells.size() < c.count) {
        warnings_.push_back(headroom_import::where(file_, raw.number) + "the last row is cut short (no line end, " +
                            std::to_string(cells.size()) + " of " + std::to_string(c.count) + " values): left out");
        return;
      }
      throw ImportError(ImportErrorCategory::Syntax, {file_, raw.number, 0, {}},
                        "a row of " + std::to_string(cells.size()) + " values under a header of " +
                            std::to_string(c.count) + " columns (line " + std::to_string(header_line_) + ")");
    }
    PerfTestRow r;
    r.at = {file_, raw.number, 0, {}};
    r.t_experiment_s = cell(cells, c.t_experiment, raw);
    r.t_loop_s = cell(cells, c.t_loop, raw);
    r.received = cell(cells, c.received, raw);
    r.sent = cell(cells, c.sent, raw);
    r.min_s = cell(cells, c.min, raw) * c.scale;
    r.max_s = cell(cells, c.max, raw) * c.scale;
    r.mean_s = cell(cells, c.mean, raw) * c.scale;
    // performance_test prints variance (s^2) x 1000 under "(ms)": undo that x1000 (the squared unit's scale is
    // c.scale^2 only when the column is truly in ms^2, which no version writes).
    r.variance_s2 = cell(cells, c.variance, raw) * c.scale;
    if (!raw.has_line_end)
      warnings_.push_back(headroom_import::where(file_, raw.number) +
                          "the last row has no line end: its last value may have been cut while it was written");
    rows_.push_back(r);
  }

  const std::string& file_;
  std::size_t last_line_ = 0, start_line_ = 0, header_line_ = 0;
  std::optional<Columns> columns_;
  std::optional<double> rate_;
  std::vector<std::pair<std::string, std::string>> settings_;
  std::vector<PerfTestRow> rows_;
  std::vector<std::string> warnings_;
};

}  // namespace

static ImportBatch parse_performance_test_csv(const std::string& text, const std::string& file,
                                              const ParseOptions& /*options*/, const ImportLimits& limits,
                                              const CancelToken& cancel) {
  CsvParser parser(file);
  headroom_import::LineCursor cursor(text, cancel);
  TextLine line;
  std::size_t lines = 0;
  while (cursor.next(&line)) {
    if (++lines > limits.max_samples)
      throw ImportError(ImportErrorCategory::TooLarge, {file, line.number, 0, {}},
                        "more than the import limit of " + std::to_string(limits.max_samples) + " lines");
    parser.line(line);
  }
  return parser.finish();
}

static int sniff_performance_test_csv(std::string_view head, std::string_view) {
  const auto has = [&](std::string_view w) { return head.find(w) != std::string_view::npos; };
  if (has("---EXPERIMENT-START---") && has("T_experiment")) return 95;
  if (has("T_experiment") && has("latency_mean")) return 85;
  if (has("Performance Test Version:") || has("---EXPERIMENT-START---")) return 50;
  return 0;
}

const FileFormat kPerformanceTestCsvFileFormat{
    "performance-test-csv",     "Apex.AI performance_test CSV log",
    sniff_performance_test_csv, parse_text_file_with<parse_performance_test_csv>,
    parse_performance_test_csv, ".csv .log .txt"};

}  // namespace bs
