// SPDX-License-Identifier: GPL-3.0-or-later
#include "power/power_csv.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>

#ifdef __linux__
#include <sys/mman.h>
#endif

#include "analysis/power/power_time.h"
#include "power/meter_log_text.h"
#include "power/power_line_reader.h"
#include "util/text.h"

namespace bs {
namespace {

enum class Role { Ignore, Time, Current, Voltage, Power };

struct Column {
  std::string name;  // as written in the header (quotes removed)
  Role role = Role::Ignore;
  double scale = 1;  // file unit -> SI (ms -> s: 1e-3, mA -> A: 1e-3, ...)
  bool utc = false;  // a time column that says its date-times are UTC ("Wall-clock time (UTC)")
};

bool space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }
bool letter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }

// Scale of a unit for a role; empty when the unit is not one of that quantity's.
std::optional<double> unit_scale(Role role, std::string_view unit) {
  struct U {
    Role role;
    std::string_view unit;
    double scale;
  };
  static constexpr U units[] = {
      {Role::Time, "", 1},
      {Role::Time, "s", 1},
      {Role::Time, "sec", 1},
      {Role::Time, "secs", 1},
      {Role::Time, "seconds", 1},
      {Role::Time, "ms", 1e-3},
      {Role::Time, "us", 1e-6},
      {Role::Time, "\xC2\xB5s", 1e-6},
      {Role::Time, "ns", 1e-9},
      {Role::Current, "", 1},
      {Role::Current, "a", 1},
      {Role::Current, "amps", 1},
      {Role::Current, "ma", 1e-3},
      {Role::Current, "ua", 1e-6},
      {Role::Current,
       "\xC2\xB5"
       "a",
       1e-6},
      {Role::Voltage, "", 1},
      {Role::Voltage, "v", 1},
      {Role::Voltage, "volts", 1},
      {Role::Voltage, "mv", 1e-3},
      {Role::Power, "", 1},
      {Role::Power, "w", 1},
      {Role::Power, "watt", 1},
      {Role::Power, "watts", 1},
      {Role::Power, "mw", 1e-3},
      {Role::Power, "uw", 1e-6},
      {Role::Power, "\xC2\xB5w", 1e-6},
      {Role::Power, "kw", 1e3},
  };
  for (const U& u : units)
    if (u.role == role && u.unit == unit) return u.scale;
  return std::nullopt;
}

bool known_unit(std::string_view unit) {
  for (Role r : {Role::Time, Role::Current, Role::Voltage, Role::Power})
    if (!unit.empty() && unit_scale(r, unit)) return true;
  return false;
}

// Role and unit of a header cell. The unit comes from "(mA)" / "[mA]" or a "_mA" suffix; names are aliases.
struct Classified {
  Column column;
  std::string bad_unit;  // non-empty: the unit that does not fit the column's quantity
};

Classified classify(std::string_view raw) {
  Classified out{Column{std::string(trim(raw))}, {}};
  std::string n = lower(out.column.name);
  std::string unit;
  const auto open = n.find_first_of("([");
  if (open != std::string::npos) {
    const auto close = n.find_first_of(")]", open);
    unit = std::string(trim(n.substr(open + 1, close == std::string::npos ? std::string::npos : close - open - 1)));
    n = n.substr(0, open);
  }
  while (!n.empty() && (space(n.back()) || n.back() == '_')) n.pop_back();
  if (unit.empty()) {
    // "current_mA", "bus_V", "total_watts": only a known unit after the last '_' is a unit ("main_current" keeps
    // its name).
    const auto us = n.rfind('_');
    if (us != std::string::npos && known_unit(n.substr(us + 1))) {
      unit = n.substr(us + 1);
      n = n.substr(0, us);
    }
  }
  const auto has = [&](std::string_view word) { return n.find(word) != std::string::npos; };
  Role role = Role::Ignore;
  if (has("shunt") || has("charge") || has("energy") || has("limit") || has("cumulative") || has("pl1") || has("pl2") ||
      has("pl4") || has("tdp")) {
    // INA219's shunt drop is not the supply voltage; Joulescope's charge/energy and Power Gadget's cumulative
    // energy are integrals; power limits (Power Gadget's "Package PL1_0(Watt)", nvidia-smi's power.limit) are
    // settings, not measurements.
    role = Role::Ignore;
  } else if (n == "t" || has("time") || has("second") || n == "sec" || n == "secs" || n == "millis" || n == "micros" ||
             has("elapsed") || has("zeit") || n == "date" || n == "datetime" || has("epoch") || n == "unix") {
    role = Role::Time;
    if (unit.empty() && n == "millis") unit = "ms";
    if (unit.empty() && n == "micros") unit = "us";
    if (unit == "utc" || unit == "gmt" || unit == "z") {
      // "Wall-clock time (UTC)" (Otii): a time zone, not a unit; the cells are date-times.
      out.column.utc = true;
      unit.clear();
    } else if (unit == "local" || unit == "local time") {
      unit.clear();
    }
  } else if (n == "i" || has("current") || n == "a" || n == "ma" || n == "ua" || has("strom")) {
    role = Role::Current;
    if (unit.empty() && (n == "ma" || n == "ua")) unit = n;
  } else if (n == "v" || has("voltage") || has("bus") || n == "mv" || has("spannung") || n == "u") {
    role = Role::Voltage;
    if (unit.empty() && n == "mv") unit = n;
  } else if (n == "p" || has("power") || n == "w" || n == "mw" || has("leistung")) {
    role = Role::Power;
    if (unit.empty() && n == "mw") unit = n;
  } else if (!unit.empty()) {
    // A name that says nothing ("total", "ch1", "node3") with an electrical unit: the unit says what it is.
    for (Role r : {Role::Power, Role::Current, Role::Voltage})
      if (unit_scale(r, unit)) role = r;
  }
  out.column.role = role;
  if (role != Role::Ignore) {
    if (const auto s = unit_scale(role, unit))
      out.column.scale = *s;
    else
      out.bad_unit = unit;
  }
  return out;
}

// How much a time column is to be preferred when a header has several: a relative "Elapsed" clock first, Intel
// Power Gadget's "System Time" (a time of day without a date, "19:08:40:531") last, otherwise the first one.
int time_rank(std::string_view name) {
  const std::string n = lower(name);
  if (n.find("elapsed") != std::string::npos) return 2;
  if (n == "system time") return 0;
  return 1;
}

// A column named as the sum of the others: "total", "TOT" (jtop's "Power TOT"), "sum", "package"/"pkg", or
// Intel Power Gadget's "Processor Power_0" (the package power its footer calls "Package Power_0").
bool total_name(std::string_view name) {
  const std::string n = lower(name);
  if (n.find("total") != std::string::npos || n.find("package") != std::string::npos ||
      n.find("processor power") != std::string::npos)
    return true;
  // Whole words only for the short ones ("tot", "sum", "pkg"), so "summary" or "gotoff" do not count.
  std::size_t i = 0;
  while (i < n.size()) {
    while (i < n.size() && !letter(n[i])) ++i;
    std::size_t j = i;
    while (j < n.size() && letter(n[j])) ++j;
    const std::string_view word = std::string_view(n).substr(i, j - i);
    if (word == "tot" || word == "sum" || word == "pkg") return true;
    i = j;
  }
  return false;
}

// Separator of a header: the candidate found most often outside double quotes.
char sniff_separator(std::string_view header) {
  std::size_t counts[3] = {0, 0, 0};
  bool quoted = false;
  for (char c : header) {
    if (c == '"')
      quoted = !quoted;
    else if (!quoted && c == ',')
      ++counts[0];
    else if (!quoted && c == ';')
      ++counts[1];
    else if (!quoted && c == '\t')
      ++counts[2];
  }
  const char candidates[3] = {',', ';', '\t'};
  char best = ',';
  std::size_t best_count = 0;
  for (int i = 0; i < 3; ++i)
    if (counts[i] > best_count) {
      best = candidates[i];
      best_count = counts[i];
    }
  return best;
}

std::string separator_name(char sep) { return sep == '\t' ? "tab" : std::string("'") + sep + "'"; }

struct HeaderCell {
  std::string text;    // unquoted: "a ""b""" -> a "b"
  std::size_t column;  // 1-based byte column of the cell in the line
};

// Cells of a header or sniffed line, RFC 4180 quoting honoured (a separator inside quotes belongs to the cell).
// An unclosed quote runs to the end of the line (sniffing must not throw; the rows report it properly).
std::vector<HeaderCell> split_cells(std::string_view line, char sep) {
  std::vector<HeaderCell> cells;
  std::size_t i = 0;
  for (;;) {
    HeaderCell cell{{}, i + 1};
    std::size_t k = i;
    while (k < line.size() && line[k] == ' ') ++k;
    if (k < line.size() && line[k] == '"') {
      k = std::min(meter::read_quoted(line, k, cell.text), line.size());
      while (k < line.size() && line[k] != sep) ++k;  // text after the closing quote: dropped
    } else {
      const auto end = line.find(sep, i);
      k = end == std::string_view::npos ? line.size() : end;
      cell.text = std::string(line.substr(i, k - i));
    }
    cells.push_back(std::move(cell));
    if (k >= line.size()) break;
    i = k + 1;
  }
  return cells;
}

// A number cell: from_chars on the bytes in place; with a decimal comma through a small stack copy.
bool parse_number(std::string_view cell, bool decimal_comma, double& value) {
  if (!cell.empty() && cell.front() == '+') cell.remove_prefix(1);
  if (cell.empty()) return false;
  const char* first = cell.data();
  const char* last = first + cell.size();
  char copy[64];
  if (decimal_comma && std::memchr(first, ',', cell.size())) {
    if (cell.size() >= sizeof copy) return false;
    std::memcpy(copy, first, cell.size());
    std::replace(copy, copy + cell.size(), ',', '.');
    first = copy;
    last = copy + cell.size();
  }
  const auto [ptr, ec] = std::from_chars(first, last, value);
  return ec == std::errc() && ptr == last && std::isfinite(value);
}

// Cells that say "no sample here": empty, or N/A as nvidia-smi and spreadsheets write it. (A literal "nan" or
// "inf" stays an error: it is a number gone wrong, not a gap the logger meant.)
bool missing_marker(std::string_view cell) {
  if (cell.empty()) return true;
  const std::string l = lower(cell);
  return l == "n/a" || l == "[n/a]" || l == "na";
}

// Seconds since the epoch that a time column's first value may be: 2000-01-01 .. 2100-01-01. A relative log
// never starts 30 years in, so such a value is an absolute (Unix) time.
bool epoch_seconds(double s) { return s >= 946684800.0 && s < 4102444800.0; }

// A big column is written once from front to back: on Linux, ask for transparent huge pages on its untouched
// reservation, so filling 100 MB costs 50 page faults instead of 25,000 (a third of the parse time on a VM).
void advise_huge_pages(std::vector<double>& v) {
#ifdef __linux__
  constexpr std::uintptr_t huge = std::uintptr_t{2} << 20;
  const auto first = reinterpret_cast<std::uintptr_t>(v.data());
  const std::uintptr_t begin = (first + huge - 1) & ~(huge - 1);
  const std::uintptr_t end = (first + v.capacity() * sizeof(double)) & ~(huge - 1);
  if (end > begin)
    ::madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);  // a hint: errors are harmless
#else
  (void)v;
#endif
}

// How the time column's cells are read; decided by the first data row.
enum class TimeMode {
  Undecided,
  Number,    // seconds (or ms/us/ns by unit) as a double: relative, or Unix time when it starts after 2000
  Integer,   // an integer too big for a double's 53 bits (Unix nanoseconds): read as int64, offset from the first
  DateTime,  // text date-times (parse_date_time)
};

// The parser proper: header and comment lines first, then one row per line. Plain data in, ImportBatch out.
class PowerCsvParser {
 public:
  PowerCsvParser(const std::string& file, const ParseOptions& options, const ImportLimits& limits)
      : file_(file), options_(options), limits_(limits) {}

  void line(std::string_view raw, std::size_t line_no) {
    if (columns_.empty()) return header_or_comment(raw, line_no);
    row(raw, line_no);
  }
  bool has_header() const { return !columns_.empty(); }
  // The last line, cut off mid-line (no line ending: a logger killed while writing, the commonest real
  // corruption), did not parse: it is left out, with a warning naming it, when complete rows came before it.
  // Returns false (the caller rethrows) when there are none. Cells the cut row had already stored are taken back.
  bool drop_cut_last_line(std::size_t line_no, const std::string& why) {
    if (columns_.empty() || trace_.time_s.empty()) return false;
    for (auto& c : trace_.channels) c.values.resize(trace_.time_s.size());
    batch_.warnings.push_back(
        file_ + ":" + std::to_string(line_no) + ": the last line is cut off (no line ending) and does not parse (" +
        why + "); left out, the " + std::to_string(trace_.time_s.size()) + " complete rows before it are imported");
    return true;
  }
  // The last line has no line ending, so a logger may have been stopped while writing it: "162.4,3." parses (as 3 A)
  // although the logger was writing 3.0611. With complete rows before it, it is left out unread (a possibly wrong
  // number never reaches the statistics) and the warning names it; as the only row it is read, and the warning says
  // to check it. Returns whether the line is to be left out.
  bool possibly_cut_last_line(std::string_view raw, std::size_t line_no) {
    const std::string_view text = trim(raw);
    if (columns_.empty() || text.empty() || text.front() == '#') return false;  // a comment carries no number
    const std::string shown(raw.substr(0, std::min<std::size_t>(raw.size(), 60)));
    const std::string where = file_ + ":" + std::to_string(line_no) + ": ";
    if (!trace_.time_s.empty()) {
      batch_.warnings.push_back(where +
                                "the last line has no line ending, so it may be cut off (a logger stopped "
                                "while writing it: \"" +
                                shown + "\"); left out, the " + std::to_string(trace_.time_s.size()) +
                                " complete rows before it are imported");
      return true;
    }
    batch_.warnings.push_back(where +
                              "the only data row has no line ending, so it may be cut off (a logger stopped "
                              "while writing it: \"" +
                              shown + "\"); read as it is: check its last value");
    return false;
  }
  // Reserves the columns for about `rows` rows (an estimate from the file system's size, capped by the limit).
  void reserve(std::size_t rows) {
    rows = std::min(rows, limits_.max_power_rows);
    trace_.time_s.reserve(rows);
    advise_huge_pages(trace_.time_s);
    for (auto& c : trace_.channels) {
      c.values.reserve(rows);
      advise_huge_pages(c.values);
    }
  }
  ImportBatch finish(std::size_t last_line);

 private:
  [[noreturn]] void fail(ImportErrorCategory cat, std::size_t line, std::size_t col, std::string field,
                         std::string reason) const {
    throw ImportError(cat, {file_, line, col, std::move(field)}, std::move(reason));
  }
  void header_or_comment(std::string_view raw, std::size_t line_no);
  void row(std::string_view raw, std::size_t line_no);
  bool footer_line(std::string_view raw, std::size_t line_no);
  std::string_view cell_text(const char* p, const char* stop, const char*& end, std::size_t line_no, std::size_t col,
                             std::size_t index);
  double time_cell(const char* p, const char* stop, const char*& end, std::string_view raw, std::size_t line_no,
                   std::size_t col);
  void decide_time_mode(std::string_view cell, std::string_view raw, std::size_t line_no, std::size_t col);
  void absolute_start(std::string_view cell, bool utc_column);
  void bad_cell(std::string_view line, std::string_view cell, std::size_t line_no, std::size_t col,
                std::size_t index) const;
  void detect_source(const std::vector<HeaderCell>& cells, bool comment_header);
  void choose_total();
  void drop_empty_channels();

  const std::string& file_;
  const ParseOptions& options_;
  const ImportLimits& limits_;
  std::vector<Column> columns_;
  std::vector<int> channel_of_;             // column index -> channel index, -1 for time and ignored columns
  std::vector<std::vector<double>*> sink_;  // column index -> the channel's values (set when the rows start)
  std::size_t time_col_ = 0;
  std::size_t abs_col_ = std::size_t(-1);  // a second time column that may give the absolute start time
  char sep_ = ',';
  bool decimal_comma_ = false;
  TimeMode time_mode_ = TimeMode::Undecided;
  long long t0_int_ = 0;  // TimeMode::Integer: the first row's value
  bool first_row_ = true;
  double t0_ = 0, last_t_ = 0;
  std::size_t header_line_ = 0;
  std::size_t repeats_ = 0, first_repeat_line_ = 0;        // rows whose time equals the previous row's
  std::vector<std::size_t> missing_, first_missing_line_;  // per channel: empty / N/A cells
  std::size_t footer_lines_ = 0, first_footer_line_ = 0;
  std::string scratch_;  // a quoted cell with doubled quotes, unescaped
  std::vector<std::string> comments_;
  MeasurementKind header_measurement_ = MeasurementKind::Unknown;
  std::string header_sensor_, header_tool_;
  PowerTrace trace_;
  ImportBatch batch_;
};

void PowerCsvParser::header_or_comment(std::string_view raw, std::size_t line_no) {
  std::string_view l = trim(raw);
  if (l.empty()) return;
  const bool comment = l.front() == '#';
  if (comment) l.remove_prefix(1);
  const char sep = sniff_separator(l);
  const std::vector<HeaderCell> cells = split_cells(l, sep);
  const std::size_t offset = static_cast<std::size_t>(l.data() - raw.data());
  std::vector<Column> cols;
  bool time = false, signal = false;
  std::size_t bad = cells.size();
  std::string bad_unit;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    Classified c = classify(cells[i].text);
    time = time || c.column.role == Role::Time;
    signal = signal || c.column.role == Role::Current || c.column.role == Role::Power;
    if (!c.bad_unit.empty() && bad == cells.size()) {
      bad = i;
      bad_unit = c.bad_unit;
    }
    cols.push_back(std::move(c.column));
  }
  // A '#' line is the header only when it names a time and a current/power column (Joulescope's "#time,current,
  // voltage,power"); prose such as "# logged at 10 Hz, time in s" stays a comment.
  if (comment && !(time && signal && cells.size() >= 2)) {
    comments_.emplace_back(trim(l));
    return;
  }
  if (bad < cells.size())
    fail(ImportErrorCategory::Unsupported, line_no, offset + cells[bad].column, cols[bad].name,
         "unit '" + bad_unit +
             "' does not fit this column (known: s ms us ns, UTC for date-times / A mA uA / V mV / W mW uW kW)");
  if (!time)
    fail(ImportErrorCategory::MissingField, line_no, 1, "header",
         "no time column (expected a header such as time_s,current_A; found '" + std::string(l.substr(0, 80)) + "')");
  if (!signal)
    fail(ImportErrorCategory::MissingField, line_no, 1, "header",
         "no current or power column (expected e.g. current_A, current_mA, power_W)");
  sep_ = sep;
  decimal_comma_ = sep != ',';
  header_line_ = line_no;
  // The time column: the best-ranked one (time_rank), the first of equals.
  int best = -1;
  for (std::size_t i = 0; i < cols.size(); ++i)
    if (cols[i].role == Role::Time && time_rank(cols[i].name) > best) {
      best = time_rank(cols[i].name);
      time_col_ = i;
    }
  std::string ignored;
  channel_of_.assign(cols.size(), -1);
  for (std::size_t i = 0; i < cols.size(); ++i) {
    const Role r = cols[i].role;
    if (r == Role::Current || r == Role::Voltage || r == Role::Power) {
      channel_of_[i] = static_cast<int>(trace_.channels.size());
      trace_.channels.push_back({cols[i].name,
                                 r == Role::Current   ? PowerQuantity::Current
                                 : r == Role::Voltage ? PowerQuantity::Voltage
                                                      : PowerQuantity::Power,
                                 {}});
    } else if (i != time_col_ && !cols[i].name.empty()) {
      // A second time column or one BenchScope has no use for: said once, so nobody wonders where it went. The
      // first other time column may still give the absolute start time (Otii's wall clock beside its seconds).
      bool start_only = false;
      if (r == Role::Time) {
        if (abs_col_ == std::size_t(-1)) abs_col_ = i, start_only = true;
        cols[i].role = Role::Ignore;
      }
      ignored += (ignored.empty() ? "'" : ", '") + cols[i].name + "' (" + std::to_string(i + 1) +
                 (start_only ? ", only for the start time" : "") + ")";
    }
  }
  if (!ignored.empty())
    batch_.warnings.push_back(file_ + ":" + std::to_string(line_no) + ": time from '" + cols[time_col_].name +
                              "'; columns not read (not time, current, voltage or power): " + ignored);
  columns_ = std::move(cols);
  missing_.assign(trace_.channels.size(), 0);
  first_missing_line_.assign(trace_.channels.size(), 0);
  sink_.assign(columns_.size(), nullptr);
  for (std::size_t i = 0; i < columns_.size(); ++i)
    if (channel_of_[i] >= 0) sink_[i] = &trace_.channels[static_cast<std::size_t>(channel_of_[i])].values;
  detect_source(cells, comment);
}

// Which instrument wrote the file, from its header alone: Joulescope ("#time,current,voltage,power" or with
// charge and energy), Otii ("Main current (A)", "Wall-clock time (UTC)"), Intel Power Gadget (RAPL on the chip).
void PowerCsvParser::detect_source(const std::vector<HeaderCell>& cells, bool comment_header) {
  std::vector<std::string> names;
  for (const HeaderCell& c : cells) names.push_back(lower(trim(c.text)));
  const auto any = [&](std::string_view prefix) {
    return std::any_of(names.begin(), names.end(), [&](const std::string& n) { return n.starts_with(prefix); });
  };
  const bool joulescope_columns =
      names.size() >= 3 && names[0] == "time" && names[1] == "current" && names[2] == "voltage";
  if (joulescope_columns && (comment_header || any("charge") || any("energy"))) {
    header_measurement_ = MeasurementKind::ExternalMeter;
    header_sensor_ = "Joulescope";
  } else if (any("main current") || any("main voltage") || any("main power") || any("wall-clock time")) {
    header_measurement_ = MeasurementKind::ExternalMeter;
    header_sensor_ = "Otii";
  } else if (any("processor power_0") || any("cumulative processor energy") || any("ia power_0")) {
    header_measurement_ = MeasurementKind::OnBoardSensor;
    header_sensor_ = "Intel Power Gadget (RAPL)";
    header_tool_ = "Intel Power Gadget";
  }
}

void PowerCsvParser::bad_cell(std::string_view line, std::string_view cell, std::size_t line_no, std::size_t col,
                              std::size_t index) const {
  const std::string& name = columns_[index].name;
  const char* others = sep_ == ',' ? ";\t" : sep_ == ';' ? "\t" : ";";
  if (cell.find_first_of(others) != std::string_view::npos ||
      (sep_ != ',' && line.find(sep_) == std::string_view::npos && line.find(',') != std::string_view::npos))
    fail(ImportErrorCategory::Syntax, line_no, col, name,
         "mixed separators: '" + std::string(cell.substr(0, 60)) + "' in a file whose header uses " +
             separator_name(sep_));
  if (cell.empty())
    fail(ImportErrorCategory::InvalidValue, line_no, col, name,
         index == time_col_ ? "empty cell: missing time" : "empty cell: missing value");
  fail(ImportErrorCategory::InvalidValue, line_no, col, name,
       "'" + std::string(cell.substr(0, 60)) + "' is not a number");
}

// The text of the cell that starts at `p`, without its quotes (RFC 4180: "a ""b"", c" is a "b", c) and
// trimmed of spaces; `end` is set to the separator after it, or `stop`. The returned view is valid until the next
// call. A quote left open at the end of the line is an error: line breaks inside quotes are not supported.
std::string_view PowerCsvParser::cell_text(const char* p, const char* stop, const char*& end, std::size_t line_no,
                                           std::size_t col, std::size_t index) {
  const char* q = p;
  while (q < stop && *q != sep_ && space(*q)) ++q;
  if (q < stop && *q == '"') {
    scratch_.clear();
    const std::size_t after = meter::read_quoted(std::string_view(q, static_cast<std::size_t>(stop - q)), 0, scratch_);
    if (after == std::string_view::npos)
      fail(ImportErrorCategory::Syntax, line_no, col, index < columns_.size() ? columns_[index].name : std::string{},
           "quoted cell not closed on this line (a line break inside quotes is not supported in a log)");
    const char* r = q + after;
    while (r < stop && *r != sep_ && space(*r)) ++r;
    if (r < stop && *r != sep_)
      fail(ImportErrorCategory::Syntax, line_no, static_cast<std::size_t>(col + (r - p)),
           index < columns_.size() ? columns_[index].name : std::string{},
           "text after the closing quote of a quoted cell (a quote inside a quoted cell is written twice: \"\")");
    end = r;
    return trim(scratch_);
  }
  const void* hit = std::memchr(p, sep_, static_cast<std::size_t>(stop - p));
  end = hit ? static_cast<const char*>(hit) : stop;
  return trim(std::string_view(p, static_cast<std::size_t>(end - p)));
}

// The first other time column's first cell as the absolute start time, when the main time column has none.
void PowerCsvParser::absolute_start(std::string_view cell, bool utc_column) {
  if (!trace_.start_time.empty()) return;
  bool zone = false;
  if (const auto abs = parse_date_time(cell, &zone)) {
    // ISO 8601 text is kept as written (its zone included); other forms are rewritten as ISO 8601.
    const bool iso = cell.size() >= 10 && cell[4] == '-' && cell[7] == '-';
    trace_.start_time = iso ? std::string(cell) + (utc_column && !zone ? "Z" : "")
                            : format_iso8601(*abs) + (utc_column || zone ? "Z" : "");
    return;
  }
  double v = 0;
  if (parse_number(cell, false, v)) {
    // Unix time in s, ms, us or ns: whichever scale lands between 2000 and 2100.
    for (double scale : {1.0, 1e-3, 1e-6, 1e-9})
      if (epoch_seconds(v * scale)) {
        trace_.start_time = format_iso8601(v * scale) + "Z";
        return;
      }
  }
}

void PowerCsvParser::decide_time_mode(std::string_view cell, std::string_view raw, std::size_t line_no,
                                      std::size_t col) {
  const Column& c = columns_[time_col_];
  double v = 0;
  if (parse_number(cell, decimal_comma_, v)) {
    long long whole = 0;
    const auto r = std::from_chars(cell.data(), cell.data() + cell.size(), whole);
    const bool integer = r.ec == std::errc() && r.ptr == cell.data() + cell.size();
    // Beyond 2^53 a double cannot hold every integer: Unix nanoseconds (1.7e18) would be read in steps of 256 ns.
    if (std::fabs(v) >= 9007199254740992.0) {
      if (!integer)
        fail(ImportErrorCategory::InvalidValue, line_no, col, c.name,
             "'" + std::string(cell.substr(0, 60)) +
                 "' is too large for a time (an integer up to 2^63 is read exactly)");
      time_mode_ = TimeMode::Integer;
      t0_int_ = whole;
    } else {
      time_mode_ = TimeMode::Number;
    }
    if (epoch_seconds(v * c.scale)) trace_.start_time = format_iso8601(v * c.scale) + "Z";
    return;
  }
  bool zone = false;
  if (parse_date_time(cell, &zone)) {
    time_mode_ = TimeMode::DateTime;
    trace_.start_time.clear();  // the main time column's own start wins over another column's
    return absolute_start(cell, c.utc);
  }
  if (cell.empty()) bad_cell(raw, cell, line_no, col, time_col_);
  const char* others = sep_ == ',' ? ";\t" : ";";
  if (cell.find_first_of(others) != std::string_view::npos) bad_cell(raw, cell, line_no, col, time_col_);
  fail(ImportErrorCategory::InvalidValue, line_no, col, c.name,
       "'" + std::string(cell.substr(0, 60)) +
           "' is neither a number nor a date-time (times are seconds, or ms/us/ns by the column's unit, Unix time, "
           "ISO 8601 such as 2026-11-22T10:00:01.250Z, 2026/11/22 10:00:01.250 or 11-22-2026 10:00:01.250)");
}

// The time column's cell at `p`, in seconds: relative to the file's origin (TimeMode::Number), to the first row
// (Integer) or to the Unix epoch (DateTime). Sets `end` like cell_text().
double PowerCsvParser::time_cell(const char* p, const char* stop, const char*& end, std::string_view raw,
                                 std::size_t line_no, std::size_t col) {
  const Column& c = columns_[time_col_];
  // Fast paths: a plain number that ends at the separator, parsed in place.
  if (time_mode_ == TimeMode::Number) {
    double v = 0;
    const auto r = std::from_chars(p, stop, v);
    if (r.ec == std::errc() && (r.ptr == stop || *r.ptr == sep_) && std::isfinite(v)) {
      end = r.ptr;
      return v * c.scale;
    }
  } else if (time_mode_ == TimeMode::Integer) {
    long long v = 0;
    const auto r = std::from_chars(p, stop, v);
    if (r.ec == std::errc() && (r.ptr == stop || *r.ptr == sep_)) {
      end = r.ptr;
      return static_cast<double>(v - t0_int_) * c.scale;
    }
  }
  // Slow path: spaces, quotes, '+', decimal commas, date-times, the first row, and every error message.
  const std::string_view cell = cell_text(p, stop, end, line_no, col, time_col_);
  if (time_mode_ == TimeMode::Undecided) decide_time_mode(cell, raw, line_no, col);
  switch (time_mode_) {
    case TimeMode::Number: {
      double v = 0;
      if (!parse_number(cell, decimal_comma_, v)) bad_cell(raw, cell, line_no, col, time_col_);
      return v * c.scale;
    }
    case TimeMode::Integer: {
      long long v = 0;
      const auto r = std::from_chars(cell.data(), cell.data() + cell.size(), v);
      if (r.ec != std::errc() || r.ptr != cell.data() + cell.size()) {
        if (cell.empty()) bad_cell(raw, cell, line_no, col, time_col_);
        fail(ImportErrorCategory::InvalidValue, line_no, col, c.name,
             "'" + std::string(cell.substr(0, 60)) + "' is not an integer like the first row's time");
      }
      return static_cast<double>(v - t0_int_) * c.scale;
    }
    case TimeMode::DateTime: {
      const auto abs = parse_date_time(cell);
      if (!abs) {
        if (cell.empty()) bad_cell(raw, cell, line_no, col, time_col_);
        fail(ImportErrorCategory::InvalidValue, line_no, col, c.name,
             "'" + std::string(cell.substr(0, 60)) + "' is not a date-time like the first row's");
      }
      return *abs;
    }
    case TimeMode::Undecided:
      break;
  }
  return 0;
}

// Intel Power Gadget ends its log with a blank line and a summary, one "Name = value" per line (quoted in newer
// versions): read into the provenance's settings, not taken for rows. A line is such a footer line when it starts
// with a letter, has no separator outside quotes and has an '='.
bool PowerCsvParser::footer_line(std::string_view raw, std::size_t line_no) {
  std::string_view l = trim(raw);
  if (l.size() >= 2 && l.front() == '"' && l.back() == '"') l = l.substr(1, l.size() - 2);
  if (l.empty() || !letter(l.front()) || l.find(sep_) != std::string_view::npos) return false;
  const auto eq = l.find('=');
  if (eq == std::string_view::npos) return false;
  trace_.provenance.settings.emplace_back(std::string(trim(l.substr(0, eq))), std::string(trim(l.substr(eq + 1))));
  if (footer_lines_++ == 0) first_footer_line_ = line_no;
  return true;
}

void PowerCsvParser::row(std::string_view raw, std::size_t line_no) {
  // Fast check for blank and comment lines without trimming every row.
  std::size_t first = 0;
  while (first < raw.size() && space(raw[first])) ++first;
  if (first == raw.size() || raw[first] == '#') return;
  // Rows start with a digit, sign, point or quote; a letter may begin a summary footer.
  const char lead = raw[first] == '"' && first + 1 < raw.size() ? raw[first + 1] : raw[first];
  if (letter(lead) && footer_line(raw, line_no)) return;
  if (trace_.time_s.size() >= limits_.max_power_rows)
    fail(ImportErrorCategory::TooLarge, line_no, 1, {},
         "more than " + std::to_string(limits_.max_power_rows) + " rows (the limit for one log)");
  const std::size_t ncols = columns_.size();
  const char* const base = raw.data();
  const char* const stop = base + raw.size();
  const char* p = base;
  std::size_t index = 0;
  double t = 0;
  for (;;) {
    const std::size_t start = static_cast<std::size_t>(p - base);
    const char* end = nullptr;  // the separator after this cell, or `stop`
    if (index == time_col_) {
      t = time_cell(p, stop, end, raw, line_no, start + 1);
      if (time_mode_ == TimeMode::Number && t < 0)
        fail(ImportErrorCategory::InvalidValue, line_no, start + 1, columns_[index].name,
             "negative time " + std::string(trim(std::string_view(p, static_cast<std::size_t>(end - p)))));
    } else if (index < ncols && columns_[index].role != Role::Ignore) {
      double v = 0;
      // Fast path: a plain number that ends at the separator, parsed in place (from_chars also finds the end).
      const auto r = std::from_chars(p, stop, v);
      if (r.ec == std::errc() && (r.ptr == stop || *r.ptr == sep_) && std::isfinite(v)) {
        end = r.ptr;
        v *= columns_[index].scale;
      } else {
        // Slow path: spaces, quotes, '+', decimal commas, missing samples, and every error message.
        const std::string_view cell = cell_text(p, stop, end, line_no, start + 1, index);
        if (parse_number(cell, decimal_comma_, v)) {
          v *= columns_[index].scale;
        } else if (missing_marker(cell)) {
          const auto ch = static_cast<std::size_t>(channel_of_[index]);
          if (missing_[ch]++ == 0) first_missing_line_[ch] = line_no;
          v = std::numeric_limits<double>::quiet_NaN();
        } else {
          bad_cell(raw, cell, line_no, start + 1, index);
        }
      }
      sink_[index]->push_back(v);
    } else {
      // An ignored cell, or one beyond the header: only its end is needed (quotes may hide separators).
      const char* q = p;
      while (q < stop && *q == ' ') ++q;
      std::string_view cell;
      if (q < stop && *q == '"') {
        cell = cell_text(p, stop, end, line_no, start + 1, index);
      } else {
        const void* hit = std::memchr(p, sep_, static_cast<std::size_t>(stop - p));
        end = hit ? static_cast<const char*>(hit) : stop;
        cell = std::string_view(p, static_cast<std::size_t>(end - p));
      }
      if (index == abs_col_ && first_row_) absolute_start(trim(cell), columns_[index].utc);
      // Cells beyond the header: a trailing separator (empty cells) is harmless, anything else is not.
      if (index >= ncols && !trim(cell).empty())
        fail(ImportErrorCategory::Syntax, line_no, start + 1, {},
             "row has more cells than the header's " + std::to_string(ncols) + " (header on line " +
                 std::to_string(header_line_) + ")");
    }
    ++index;
    if (end == stop) break;
    p = end + 1;
  }
  if (index < ncols) {
    const std::string_view other = sep_ == ',' ? ";\t" : ",";
    const bool mixed = raw.find_first_of(other) != std::string_view::npos;
    fail(ImportErrorCategory::Syntax, line_no, raw.size() + 1, columns_[index].name,
         "row has " + std::to_string(index) + " cells, the header " + std::to_string(ncols) +
             (mixed ? " (mixed separators? the header uses " + separator_name(sep_) + ")" : ""));
  }
  if (first_row_) {
    t0_ = t;
    first_row_ = false;
  } else if (t < last_t_) {
    fail(ImportErrorCategory::InvalidValue, line_no, 0, columns_[time_col_].name,
         "time goes backwards (" + std::to_string(t - t0_) + " s after " + std::to_string(last_t_ - t0_) +
             " s on an earlier row)");
  } else if (t == last_t_ && repeats_++ == 0) {
    first_repeat_line_ = line_no;
  }
  last_t_ = t;
  trace_.time_s.push_back(t - t0_);
}

// Channels with no value at all (a CPU column a logger left empty throughout) are dropped, with a warning; a file
// whose every current/power column is empty is an error.
void PowerCsvParser::drop_empty_channels() {
  std::vector<PowerChannel> kept;
  std::vector<std::size_t> kept_missing, kept_first;
  std::string dropped;
  std::size_t first_empty_line = 0;
  std::string first_empty_name;
  const std::size_t n = trace_.time_s.size();
  for (std::size_t c = 0; c < trace_.channels.size(); ++c) {
    if (missing_[c] == n) {
      dropped += (dropped.empty() ? "'" : ", '") + trace_.channels[c].name + "'";
      if (first_empty_name.empty() && trace_.channels[c].quantity != PowerQuantity::Voltage) {
        first_empty_name = trace_.channels[c].name;
        first_empty_line = first_missing_line_[c];
      }
      continue;
    }
    kept.push_back(std::move(trace_.channels[c]));
    kept_missing.push_back(missing_[c]);
    kept_first.push_back(first_missing_line_[c]);
  }
  trace_.channels = std::move(kept);
  missing_ = std::move(kept_missing);
  first_missing_line_ = std::move(kept_first);
  const bool signal = std::any_of(trace_.channels.begin(), trace_.channels.end(),
                                  [](const PowerChannel& c) { return c.quantity != PowerQuantity::Voltage; });
  if (!signal)
    fail(ImportErrorCategory::InvalidValue, first_empty_line, 0, first_empty_name,
         "every cell of the column is empty (empty cell from line " + std::to_string(first_empty_line) +
             " on): no current or power sample in the file");
  if (!dropped.empty()) batch_.warnings.push_back(file_ + ": columns with no value in any row, not kept: " + dropped);
  for (std::size_t c = 0; c < trace_.channels.size(); ++c)
    if (missing_[c] > 0)
      batch_.warnings.push_back(file_ + ":" + std::to_string(first_missing_line_[c]) + ": '" + trace_.channels[c].name +
                                "': " + std::to_string(missing_[c]) + " of " + std::to_string(n) +
                                " cells empty or N/A, kept as missing samples (statistics skip them)");
}

// The channel the statistics use when several power (else current) columns exist: one named as the total, else
// none (analysis then takes the first) and a warning says so.
void PowerCsvParser::choose_total() {
  const bool power = std::any_of(trace_.channels.begin(), trace_.channels.end(),
                                 [](const PowerChannel& c) { return c.quantity == PowerQuantity::Power; });
  const PowerQuantity q = power ? PowerQuantity::Power : PowerQuantity::Current;
  std::vector<const PowerChannel*> candidates;
  for (const PowerChannel& c : trace_.channels)
    if (c.quantity == q) candidates.push_back(&c);
  for (const PowerChannel* c : candidates)
    if (total_name(c->name)) {
      trace_.total_channel = c->name;
      if (candidates.size() > 1)
        batch_.warnings.push_back(file_ + ": " + std::to_string(candidates.size()) + (power ? " power" : " current") +
                                  " columns; statistics use '" + c->name +
                                  "' (named as the total), the others are channels");
      return;
    }
  if (candidates.size() > 1) {
    std::string names;
    for (const PowerChannel* c : candidates) names += (names.empty() ? "'" : ", '") + c->name + "'";
    batch_.warnings.push_back(file_ + ": " + std::to_string(candidates.size()) + (power ? " power" : " current") +
                              " columns (" + names + ") and none named total/sum/package: statistics use '" +
                              candidates.front()->name + "' (the first); the others are channels");
  }
}

ImportBatch PowerCsvParser::finish(std::size_t last_line) {
  if (columns_.empty())
    fail(ImportErrorCategory::Empty, last_line, 0, {},
         comments_.empty() ? "no header line" : "only comment lines, no header line (e.g. time_s,current_A)");
  if (trace_.time_s.empty())
    fail(ImportErrorCategory::Empty, last_line, 0, {},
         "header on line " + std::to_string(header_line_) + " but no data rows");
  drop_empty_channels();
  choose_total();
  trace_.label = file_.substr(file_.find_last_of('/') == std::string::npos ? 0 : file_.find_last_of('/') + 1);
  trace_.provenance.origin = DataOrigin::Measured;
  trace_.provenance.source_file = file_;
  trace_.provenance.measurement = header_measurement_;
  trace_.provenance.sensor = header_sensor_;
  if (!header_tool_.empty()) trace_.provenance.tool = header_tool_;
  std::string note;
  for (const auto& c : comments_) {
    note += (note.empty() ? "" : " ") + c;
    const std::string lc = lower(c);
    if (lc.find("reconstructed") != std::string::npos) trace_.provenance.origin = DataOrigin::Reconstructed;
    const auto colon = c.find(':');
    if (colon == std::string::npos) continue;
    const std::string key = lower(trim(std::string_view(c).substr(0, colon)));
    const std::string_view value = trim(std::string_view(c).substr(colon + 1));
    if (key == "platform") trace_.platform = std::string(value);
    if (key == "supply_voltage_v") {
      double v = 0;
      if (!parse_number(value, false, v) || !(v > 0))
        fail(ImportErrorCategory::InvalidValue, 0, 0, "supply_voltage_V",
             "'" + std::string(value) + "': expected volts > 0");
      trace_.supply_voltage_v = v;
    }
    // "# meter: Keysight N6705C" (or instrument): an external meter, named; "# sensor: INA3221" names the sensor;
    // "# measurement: on-board sensor" says how, in the words of to_string(MeasurementKind).
    if ((key == "meter" || key == "instrument") && !value.empty()) {
      trace_.provenance.measurement = MeasurementKind::ExternalMeter;
      trace_.provenance.sensor = std::string(value);
    }
    if (key == "sensor" && !value.empty()) trace_.provenance.sensor = std::string(value);
    if (key == "measurement" && measurement_kind_from_string(lower(value)) != MeasurementKind::Unknown)
      trace_.provenance.measurement = measurement_kind_from_string(lower(value));
  }
  trace_.provenance.note = note;
  if (trace_.platform.empty()) trace_.platform = options_.platform;
  if (options_.supply_voltage_v) trace_.supply_voltage_v = options_.supply_voltage_v;
  if (!trace_.start_time.empty()) trace_.provenance.date = trace_.start_time;
  if (repeats_ > 0)
    batch_.warnings.push_back(file_ + ":" + std::to_string(first_repeat_line_) + ": " + std::to_string(repeats_) +
                              " rows repeat the previous row's time; kept (they add no width to the energy integral)");
  if (footer_lines_ > 0)
    batch_.warnings.push_back(file_ + ":" + std::to_string(first_footer_line_) + ": summary footer (" +
                              std::to_string(footer_lines_) + " 'name = value' lines) kept as settings, not samples");
  const auto has = [&](PowerQuantity q) {
    return std::any_of(trace_.channels.begin(), trace_.channels.end(),
                       [&](const PowerChannel& c) { return c.quantity == q; });
  };
  if (!has(PowerQuantity::Power) && !has(PowerQuantity::Voltage) && !trace_.supply_voltage_v)
    batch_.warnings.push_back(file_ +
                              ": current only and no supply voltage (no '# supply_voltage_V:' line): "
                              "power and energy stay unknown until one is given");
  // Give back a reservation that overshot by more than a quarter (the estimate from the first rows was off);
  // a small overshoot is cheaper to keep than to copy.
  const auto trim_excess = [](std::vector<double>& v) {
    if (v.capacity() > v.size() + v.size() / 4 + 1024) v.shrink_to_fit();
  };
  for (auto& c : trace_.channels) trim_excess(c.values);
  trim_excess(trace_.time_s);
  batch_.power_traces.push_back(std::move(trace_));
  return std::move(batch_);
}

}  // namespace

static int sniff_power_csv(std::string_view head, std::string_view) {
  for (const std::string& line : meter::head_lines(head, 64)) {
    std::string_view l = trim(line);
    if (l.empty()) continue;
    const bool comment = l.front() == '#';
    if (comment) l.remove_prefix(1);
    const char sep = sniff_separator(l);
    if (l.find(sep) == std::string_view::npos) {
      if (comment) continue;
      return 0;
    }
    bool time = false, signal = false;
    for (const HeaderCell& cell : split_cells(l, sep)) {
      const Classified c = classify(cell.text);
      time = time || c.column.role == Role::Time;
      signal = signal || c.column.role == Role::Current || c.column.role == Role::Power;
    }
    if (time && signal) return 70;
    if (!comment) return 0;
  }
  return 0;
}

namespace {

// One pass over the lines. Once some rows are in, the columns are sized from the mean row length and the total
// size (for files the file system's, which the file cannot lie about), so a 100 MB log does not double its
// vectors a dozen times; the reservation is capped by the row limit.
ImportBatch parse_lines(PowerLineReader&& lines, const std::string& file, const ParseOptions& options,
                        const ImportLimits& limits, const CancelToken& cancel) {
  PowerCsvParser parser(file, options, limits);
  bool reserved = false;
  while (const auto line = lines.next()) {
    if (lines.last_line_unterminated() && parser.possibly_cut_last_line(*line, lines.line_number())) break;
    try {
      parser.line(*line, lines.line_number());
    } catch (const ImportError& e) {
      if (!lines.last_line_unterminated() || !parser.drop_cut_last_line(lines.line_number(), e.reason())) throw;
    }
    if ((lines.line_number() & 0x3ff) == 0) {
      cancel.throw_if_cancelled();
      // Reading is most of a long import: report it by bytes (every 1024 lines, a few dozen KB).
      if (lines.file_size() > 0)
        cancel.report(static_cast<double>(lines.bytes_consumed()) / static_cast<double>(lines.file_size()), "reading");
      if (!reserved && parser.has_header() && lines.bytes_consumed() > 0) {
        reserved = true;
        const double per_line = static_cast<double>(lines.bytes_consumed()) / static_cast<double>(lines.line_number());
        parser.reserve(static_cast<std::size_t>(static_cast<double>(lines.file_size()) / per_line * 1.02) + 16);
      }
    }
  }
  return parser.finish(lines.line_number());
}

}  // namespace

static ImportBatch parse_power_csv_file(const std::string& path, const ParseOptions& options,
                                        const ImportLimits& limits, const CancelToken& cancel) {
  return parse_lines(PowerLineReader(path), path, options, limits, cancel);
}

static ImportBatch parse_power_csv(const std::string& text, const std::string& file, const ParseOptions& options,
                                   const ImportLimits& limits, const CancelToken& cancel) {
  return parse_lines(PowerLineReader(text, file), file, options, limits, cancel);
}

const FileFormat kPowerCsvFileFormat{"power-csv",     "current/power log (CSV: generic, Joulescope, Otii, INA219)",
                                     sniff_power_csv, parse_power_csv_file,
                                     parse_power_csv, ".csv .tsv .txt"};

}  // namespace bs
