// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Small text helpers shared by the power-log importers (nvidia-smi, perf stat, SPEC PTDaemon, tegrastats, jtop):
// trimming, splitting on one separator, strict numbers, the file's display name and the streaming loop with one
// line of look-ahead, so each parser knows which line is the file's last (a logger stopped mid-line cuts only that
// one).
#include <charconv>
#include <cmath>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "common/importer.h"
#include "power/power_line_reader.h"
#include "util/cancel.h"
#include "util/text.h"

namespace bs::meter {

using bs::trim;  // util/text.h

// Fields between `sep`, each trimmed; an empty line gives one empty field.
inline void split(std::string_view line, char sep, std::vector<std::string_view>& out) {
  out.clear();
  std::size_t start = 0;
  for (;;) {
    const std::size_t end = line.find(sep, start);
    out.push_back(trim(line.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start)));
    if (end == std::string_view::npos) return;
    start = end + 1;
  }
}

// Whitespace-separated tokens.
inline void tokens(std::string_view line, std::vector<std::string_view>& out) {
  out.clear();
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    const std::size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
}

// The whole of `s` as a finite number ("+" allowed, nothing else around it).
inline bool number(std::string_view s, double& v) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  if (s.empty()) return false;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  return r.ec == std::errc() && r.ptr == s.data() + s.size() && std::isfinite(v);
}

// A quoted CSV cell (RFC 4180): `open` is the index of its opening quote in `line`. Appends the text up to the
// closing quote to `out`, a doubled quote ("") as one quote character, and returns the index just after the
// closing quote; npos when the quote is not closed on this line (then the rest of the line is appended). The CSV
// readers (power-csv, jtop) share it so that they unquote alike; each decides what an open quote means.
inline std::size_t read_quoted(std::string_view line, std::size_t open, std::string& out) {
  std::size_t i = open + 1;
  for (;;) {
    const std::size_t quote = line.find('"', i);
    if (quote == std::string_view::npos) {
      out.append(line.substr(i));
      return std::string_view::npos;
    }
    out.append(line.substr(i, quote - i));
    if (quote + 1 < line.size() && line[quote + 1] == '"') {
      out += '"';
      i = quote + 2;
      continue;
    }
    return quote + 1;
  }
}

// The first `most` lines of a sniffed head, copied (the reader reuses its buffer): the sniffers look at a few lines
// each, and this is their common loop.
inline std::vector<std::string> head_lines(std::string_view head, std::size_t most) {
  PowerLineReader lines(head, {});
  std::vector<std::string> out;
  while (out.size() < most) {
    const auto line = lines.next();
    if (!line) break;
    out.emplace_back(*line);
  }
  return out;
}

inline std::string file_name(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

// What every meter log says of its trace: measured, by `tool` (the program that wrote the log), read from `file`,
// dated by the trace's start, a `kind` of measurement by `sensor`. Each format adds its own note and settings.
inline void stamp_log_provenance(PowerTrace& trace, const std::string& file, std::string tool, MeasurementKind kind,
                                 std::string sensor) {
  Provenance& p = trace.provenance;
  p.origin = DataOrigin::Measured;
  p.tool = std::move(tool);
  p.source_file = file;
  p.date = trace.start_time;
  p.measurement = kind;
  p.sensor = std::move(sensor);
}

// Feeds every non-blank line to parser.line(text, number, last) and returns parser.finish(). The pending line is
// copied because the reader reuses its buffer. Checks for cancellation every 1024 lines.
// What every line-by-line meter log parser holds and how it reports: errors name the file, the line and the field;
// a skipped line becomes a warning naming file:line, the first kListedWarnings of them listed and the rest counted
// (more_skipped_warning() at the end). The parsers derive from it rather than each carrying a copy.
class LineParserBase {
 public:
  static constexpr std::size_t kListedWarnings = 10;

  // Public so that the parsers inherit it (`using LineParserBase::LineParserBase`) for parse_log to call.
  LineParserBase(const std::string& file, const ParseOptions& options, const ImportLimits& limits)
      : file_(file), options_(options), limits_(limits) {}

 protected:
  [[noreturn]] void fail(ImportErrorCategory cat, std::size_t line_no, std::string field,
                         const std::string& why) const {
    throw ImportError(cat, {file_, line_no, 0, std::move(field)}, why);
  }
  void skip(std::size_t line_no, const std::string& why) {
    if (++skipped_ <= kListedWarnings)
      batch_.warnings.push_back(file_ + ":" + std::to_string(line_no) + ": " + why + "; skipped");
  }
  // The count of the skipped lines not listed, as the last warning ("N more lines skipped"); nothing when none.
  void more_skipped_warning() {
    if (skipped_ > kListedWarnings)
      batch_.warnings.push_back(file_ + ": " + std::to_string(skipped_ - kListedWarnings) + " more lines skipped");
  }

  const std::string& file_;
  const ParseOptions& options_;
  const ImportLimits& limits_;
  std::size_t skipped_ = 0;
  ImportBatch batch_;
};

// A last line without its line ending may be cut off: a logger stopped while writing it leaves "VDD_IN 3624/36"
// where it was writing "3624/3624", and the cut number can still parse. Unless the parser already skipped that
// line (a warning naming file:line), the batch says so, naming the file and the line, so the user checks the value.
inline void warn_possibly_cut(ImportBatch& batch, const std::string& file, std::size_t line_no) {
  const std::string where = file + ":" + std::to_string(line_no) + ":";
  for (const std::string& w : batch.warnings)
    if (w.rfind(where, 0) == 0) return;
  batch.warnings.push_back(where +
                           " the last line has no line ending, so it may be cut off (a logger stopped while writing "
                           "it); its values are imported: check the last sample");
}

template <class Lines, class Parser>
auto run_lines(Lines& lines, Parser& parser, const CancelToken& cancel) {
  std::string pending;
  std::size_t pending_no = 0;
  bool have = false, pending_cut = false;
  while (const auto line = lines.next()) {
    if (trim(*line).empty()) continue;
    if (have) parser.line(pending, pending_no, false);
    pending.assign(*line);
    pending_no = lines.line_number();
    pending_cut = lines.last_line_unterminated();
    have = true;
    if ((pending_no & 0x3ff) == 0) cancel.throw_if_cancelled();
  }
  if (have) parser.line(pending, pending_no, true);
  auto batch = parser.finish();
  if (have && pending_cut) warn_possibly_cut(batch, lines.name(), pending_no);
  return batch;
}

// The whole of a line-based power format's Importer::parse (the file's lines, streamed) and of its parse_X (lines
// of text in memory): a Parser built from (file, options, limits) fed by run_lines.
template <class Parser>
ImportBatch parse_log(PowerLineReader&& lines, const std::string& file, const ParseOptions& options,
                      const ImportLimits& limits, const CancelToken& cancel) {
  Parser parser(file, options, limits);
  return run_lines(lines, parser, cancel);
}

// A meter format's two entry points: its file streamed line by line (FileFormat::parse), and text in memory
// (FileFormat::text_parser, which tests and the fuzzers call).
template <class Parser>
ImportBatch parse_log_file(const std::string& path, const ParseOptions& options, const ImportLimits& limits,
                           const CancelToken& cancel) {
  return parse_log<Parser>(PowerLineReader(path), path, options, limits, cancel);
}

template <class Parser>
ImportBatch parse_log_text(const std::string& text, const std::string& file, const ParseOptions& options,
                           const ImportLimits& limits, const CancelToken& cancel) {
  return parse_log<Parser>(PowerLineReader(text, file), file, options, limits, cancel);
}

}  // namespace bs::meter
