// SPDX-License-Identifier: GPL-3.0-or-later
#include "power_csv.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstring>
#include <cstdint>
#include <optional>

#ifdef __linux__
#include <sys/mman.h>
#endif

#include "analysis/power_time.h"
#include "power_line_reader.h"

namespace bs {
namespace {

enum class Role { Ignore, Time, Current, Voltage, Power };

struct Column {
  std::string name;  // as written in the header
  Role role = Role::Ignore;
  double scale = 1;  // file unit -> SI (ms -> s: 1e-3, mA -> A: 1e-3, ...)
};

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return out;
}

bool space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

std::string_view trim(std::string_view s) {
  while (!s.empty() && (space(s.front()) || s.front() == '"')) s.remove_prefix(1);
  while (!s.empty() && (space(s.back()) || s.back() == '"')) s.remove_suffix(1);
  return s;
}

// Scale of a unit for a role; empty when the unit is not one of that quantity's.
std::optional<double> unit_scale(Role role, std::string_view unit) {
  struct U {
    Role role;
    std::string_view unit;
    double scale;
  };
  static constexpr U units[] = {
      {Role::Time, "", 1},          {Role::Time, "s", 1},          {Role::Time, "sec", 1},
      {Role::Time, "ms", 1e-3},     {Role::Time, "us", 1e-6},      {Role::Time, "\xC2\xB5s", 1e-6},
      {Role::Time, "ns", 1e-9},     {Role::Current, "", 1},        {Role::Current, "a", 1},
      {Role::Current, "ma", 1e-3},  {Role::Current, "ua", 1e-6},   {Role::Current, "\xC2\xB5" "a", 1e-6},
      {Role::Voltage, "", 1},       {Role::Voltage, "v", 1},       {Role::Voltage, "mv", 1e-3},
      {Role::Power, "", 1},         {Role::Power, "w", 1},         {Role::Power, "mw", 1e-3},
      {Role::Power, "uw", 1e-6},    {Role::Power, "\xC2\xB5w", 1e-6}, {Role::Power, "kw", 1e3},
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
// Throws (via the returned error text) when a bracketed unit is not one of the column's quantity.
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
    // "current_mA", "bus_V": only a known unit after the last '_' is a unit ("main_current" keeps its name).
    const auto us = n.rfind('_');
    if (us != std::string::npos && known_unit(n.substr(us + 1))) {
      unit = n.substr(us + 1);
      n = n.substr(0, us);
    }
  }
  const auto has = [&](std::string_view word) { return n.find(word) != std::string::npos; };
  Role role = Role::Ignore;
  if (has("shunt") || has("charge") || has("energy")) {
    role = Role::Ignore;  // INA219's shunt drop is not the supply voltage; Joulescope's charge/energy are integrals
  } else if (n == "t" || has("time") || has("second") || n == "millis" || n == "micros" || has("elapsed") ||
             has("zeit") || n == "date" || n == "datetime") {
    role = Role::Time;
    if (unit.empty() && n == "millis") unit = "ms";
    if (unit.empty() && n == "micros") unit = "us";
  } else if (n == "i" || has("current") || n == "a" || n == "ma" || n == "ua" || has("strom")) {
    role = Role::Current;
    if (unit.empty() && (n == "ma" || n == "ua")) unit = n;
  } else if (n == "v" || has("voltage") || has("bus") || n == "mv" || has("spannung") || n == "u") {
    role = Role::Voltage;
    if (unit.empty() && n == "mv") unit = n;
  } else if (n == "p" || has("power") || n == "w" || n == "mw" || has("leistung")) {
    role = Role::Power;
    if (unit.empty() && n == "mw") unit = n;
  }
  out.column.role = role;
  if (role != Role::Ignore) {
    if (const auto s = unit_scale(role, unit)) out.column.scale = *s;
    else out.bad_unit = unit;
  }
  return out;
}

char sniff_separator(std::string_view header) {
  const std::array<char, 3> candidates = {',', ';', '\t'};
  char best = ',';
  std::ptrdiff_t best_count = 0;
  for (char c : candidates) {
    const auto count = std::count(header.begin(), header.end(), c);
    if (count > best_count) {
      best = c;
      best_count = count;
    }
  }
  return best;
}

std::string separator_name(char sep) { return sep == '\t' ? "tab" : std::string("'") + sep + "'"; }

std::vector<std::string_view> split(std::string_view line, char sep) {
  std::vector<std::string_view> cells;
  std::size_t start = 0;
  for (;;) {
    const auto end = line.find(sep, start);
    cells.push_back(line.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start));
    if (end == std::string_view::npos) break;
    start = end + 1;
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

// A big column is written once from front to back: on Linux, ask for transparent huge pages on its untouched
// reservation, so filling 100 MB costs 50 page faults instead of 25,000 (a third of the parse time on a VM).
void advise_huge_pages(std::vector<double>& v) {
#ifdef __linux__
  constexpr std::uintptr_t huge = std::uintptr_t{2} << 20;
  const auto first = reinterpret_cast<std::uintptr_t>(v.data());
  const std::uintptr_t begin = (first + huge - 1) & ~(huge - 1);
  const std::uintptr_t end = (first + v.capacity() * sizeof(double)) & ~(huge - 1);
  if (end > begin) ::madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);  // a hint: errors are harmless
#else
  (void)v;
#endif
}

// The parser proper: header and comment lines first, then one row per line. Plain data in, ImportBatch out.
class PowerCsvParser {
 public:
  PowerCsvParser(const std::string& file, const PowerImportOptions& options, const ImportLimits& limits)
      : file_(file), options_(options), limits_(limits) {}

  void line(std::string_view raw, std::size_t line_no) {
    if (columns_.empty()) return header_or_comment(raw, line_no);
    row(raw, line_no);
  }
  bool has_header() const { return !columns_.empty(); }
  // Reserves the columns for about `rows` rows (an estimate from the file system's size, capped by the limit).
  void reserve(std::size_t rows) {
    rows = std::min(rows, limits_.max_samples);
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
  void bad_cell(std::string_view line, std::string_view cell, std::size_t line_no, std::size_t col, std::size_t index) const;

  const std::string& file_;
  const PowerImportOptions& options_;
  const ImportLimits& limits_;
  std::vector<Column> columns_;
  std::vector<int> channel_of_;  // column index -> channel index, -1 for time and ignored columns
  std::vector<std::vector<double>*> sink_;  // column index -> the channel's values (set when the rows start)
  std::size_t time_col_ = 0;
  char sep_ = ',';
  bool decimal_comma_ = false;
  bool iso_time_ = false;        // decided on the first data row
  bool first_row_ = true;
  double t0_ = 0, last_t_ = 0;
  std::size_t header_line_ = 0;
  std::vector<std::string> comments_;
  PowerTrace trace_;
  ImportBatch batch_;
};

void PowerCsvParser::header_or_comment(std::string_view raw, std::size_t line_no) {
  std::string_view l = trim(raw);
  if (l.empty()) return;
  const bool comment = l.front() == '#';
  if (comment) l.remove_prefix(1);
  const char sep = sniff_separator(l);
  const std::vector<std::string_view> cells = split(l, sep);
  std::vector<Column> cols;
  bool time = false, signal = false;
  std::size_t bad = cells.size();
  std::string bad_unit;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    Classified c = classify(cells[i]);
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
    fail(ImportErrorCategory::Unsupported, line_no, static_cast<std::size_t>(cells[bad].data() - raw.data()) + 1,
         cols[bad].name, "unit '" + bad_unit + "' does not fit this column (known: s ms us ns / A mA uA / V mV / W mW uW kW)");
  if (!time)
    fail(ImportErrorCategory::MissingField, line_no, 1, "header",
         "no time column (expected a header such as time_s,current_A; found '" + std::string(l.substr(0, 80)) + "')");
  if (!signal)
    fail(ImportErrorCategory::MissingField, line_no, 1, "header",
         "no current or power column (expected e.g. current_A, current_mA, power_W)");
  sep_ = sep;
  decimal_comma_ = sep != ',';
  header_line_ = line_no;
  time_col_ = static_cast<std::size_t>(
      std::find_if(cols.begin(), cols.end(), [](const Column& c) { return c.role == Role::Time; }) - cols.begin());
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
      // A second time column or one BenchScope has no use for: said once, so nobody wonders where it went.
      if (r == Role::Time) cols[i].role = Role::Ignore;
      ignored += (ignored.empty() ? "'" : ", '") + cols[i].name + "' (" + std::to_string(i + 1) + ")";
    }
  }
  if (!ignored.empty())
    batch_.warnings.push_back(file_ + ":" + std::to_string(line_no) + ": columns not read (not time, current, voltage or power): " + ignored);
  columns_ = std::move(cols);
  sink_.assign(columns_.size(), nullptr);
  for (std::size_t i = 0; i < columns_.size(); ++i)
    if (channel_of_[i] >= 0) sink_[i] = &trace_.channels[static_cast<std::size_t>(channel_of_[i])].values;
}

void PowerCsvParser::bad_cell(std::string_view line, std::string_view cell, std::size_t line_no, std::size_t col,
                              std::size_t index) const {
  const std::string& name = columns_[index].name;
  const char* others = sep_ == ',' ? ";\t" : sep_ == ';' ? "\t" : ";";
  if (cell.find_first_of(others) != std::string_view::npos ||
      (sep_ != ',' && line.find(sep_) == std::string_view::npos && line.find(',') != std::string_view::npos))
    fail(ImportErrorCategory::Syntax, line_no, col, name,
         "mixed separators: '" + std::string(cell.substr(0, 60)) + "' in a file whose header uses " + separator_name(sep_));
  if (cell.empty())
    fail(ImportErrorCategory::InvalidValue, line_no, col, name,
         index == time_col_ ? "empty cell: missing time" : "empty cell: missing value");
  fail(ImportErrorCategory::InvalidValue, line_no, col, name, "'" + std::string(cell.substr(0, 60)) + "' is not a number");
}

void PowerCsvParser::row(std::string_view raw, std::size_t line_no) {
  // Fast check for blank and comment lines without trimming every row.
  std::size_t first = 0;
  while (first < raw.size() && space(raw[first])) ++first;
  if (first == raw.size() || raw[first] == '#') return;
  if (trace_.time_s.size() >= limits_.max_samples)
    fail(ImportErrorCategory::TooLarge, line_no, 1, {},
         "more than " + std::to_string(limits_.max_samples) + " rows (the limit for one log)");
  const std::size_t ncols = columns_.size();
  const char* const base = raw.data();
  const char* const stop = base + raw.size();
  const char* p = base;
  std::size_t index = 0;
  double t = 0;
  for (;;) {
    const std::size_t start = static_cast<std::size_t>(p - base);
    const char* end = nullptr;  // the separator after this cell, or `stop`
    if (index < ncols && columns_[index].role != Role::Ignore) {
      double v = 0;
      // Fast path: a plain number that ends at the separator, parsed in place (from_chars also finds the end).
      if (!(index == time_col_ && iso_time_)) {
        const auto r = std::from_chars(p, stop, v);
        if (r.ec == std::errc() && (r.ptr == stop || *r.ptr == sep_) && std::isfinite(v)) end = r.ptr;
      }
      if (!end) {
        // Slow path: spaces, quotes, '+', decimal commas, ISO times, and every error message.
        const void* hit = std::memchr(p, sep_, static_cast<std::size_t>(stop - p));
        end = hit ? static_cast<const char*>(hit) : stop;
        const std::string_view cell = trim(std::string_view(p, static_cast<std::size_t>(end - p)));
        if (index == time_col_ && first_row_)
          iso_time_ = !parse_number(cell, decimal_comma_, v) && parse_iso8601(cell).has_value();
        if (index == time_col_ && iso_time_) {
          const auto abs = parse_iso8601(cell);
          if (!abs)
            fail(ImportErrorCategory::InvalidValue, line_no, start + 1, columns_[index].name,
                 "'" + std::string(cell.substr(0, 60)) + "' is not an ISO 8601 date-time like the first row's");
          if (first_row_) trace_.start_time = std::string(cell);
          v = *abs;
        } else if (!parse_number(cell, decimal_comma_, v)) {
          bad_cell(raw, cell, line_no, start + 1, index);
        }
      }
      if (index != time_col_) {
        sink_[index]->push_back(v * columns_[index].scale);
      } else if (iso_time_) {
        t = v;
      } else {
        t = v * columns_[index].scale;
        if (t < 0)
          fail(ImportErrorCategory::InvalidValue, line_no, start + 1, columns_[index].name,
               "negative time " + std::string(trim(std::string_view(p, static_cast<std::size_t>(end - p)))));
      }
    } else {
      const void* hit = std::memchr(p, sep_, static_cast<std::size_t>(stop - p));
      end = hit ? static_cast<const char*>(hit) : stop;
      // Cells beyond the header: a trailing separator (empty cells) is harmless, anything else is not.
      if (index >= ncols && !trim(std::string_view(p, static_cast<std::size_t>(end - p))).empty())
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
  }
  last_t_ = t;
  trace_.time_s.push_back(t - t0_);
}

ImportBatch PowerCsvParser::finish(std::size_t last_line) {
  if (columns_.empty())
    fail(ImportErrorCategory::Empty, last_line, 0, {},
         comments_.empty() ? "no header line" : "only comment lines, no header line (e.g. time_s,current_A)");
  if (trace_.time_s.empty())
    fail(ImportErrorCategory::Empty, last_line, 0, {},
         "header on line " + std::to_string(header_line_) + " but no data rows");
  trace_.label = file_.substr(file_.find_last_of('/') == std::string::npos ? 0 : file_.find_last_of('/') + 1);
  trace_.provenance.origin = DataOrigin::Measured;
  trace_.provenance.source_file = file_;
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
        fail(ImportErrorCategory::InvalidValue, 0, 0, "supply_voltage_V", "'" + std::string(value) + "': expected volts > 0");
      trace_.supply_voltage_v = v;
    }
  }
  trace_.provenance.note = note;
  if (trace_.platform.empty()) trace_.platform = options_.platform;
  if (options_.supply_voltage_v) trace_.supply_voltage_v = options_.supply_voltage_v;
  if (iso_time_) trace_.provenance.date = trace_.start_time;
  const auto has = [&](PowerQuantity q) {
    return std::any_of(trace_.channels.begin(), trace_.channels.end(), [&](const PowerChannel& c) { return c.quantity == q; });
  };
  if (!has(PowerQuantity::Power) && !has(PowerQuantity::Voltage) && !trace_.supply_voltage_v)
    batch_.warnings.push_back(file_ + ": current only and no supply voltage (no '# supply_voltage_V:' line): "
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

bool usual(std::string_view path) {
  const auto dot = path.rfind('.');
  if (dot == std::string_view::npos) return false;
  const std::string ext = lower(path.substr(dot + 1));
  return ext == "csv" || ext == "tsv" || ext == "txt";
}

}  // namespace

int PowerCsvImporter::sniff(std::string_view head, std::string_view) const {
  PowerLineReader lines(head, {});
  for (int seen = 0; seen < 64; ++seen) {
    const auto line = lines.next();
    if (!line) return 0;
    std::string_view l = trim(*line);
    if (l.empty()) continue;
    const bool comment = l.front() == '#';
    if (comment) l.remove_prefix(1);
    const char sep = sniff_separator(l);
    if (l.find(sep) == std::string_view::npos) {
      if (comment) continue;
      return 0;
    }
    bool time = false, signal = false;
    for (std::string_view cell : split(l, sep)) {
      const Classified c = classify(cell);
      time = time || c.column.role == Role::Time;
      signal = signal || c.column.role == Role::Current || c.column.role == Role::Power;
    }
    if (time && signal) return 70;
    if (!comment) return 0;
  }
  return 0;
}

bool PowerCsvImporter::usual_extension(std::string_view path) const { return usual(path); }

ImportBatch PowerCsvImporter::parse(const std::string& path, const ImportLimits& limits, const CancelToken& cancel) const {
  return read_power_csv(path, {}, limits, cancel);
}

namespace {

// One pass over the lines. Once some rows are in, the columns are sized from the mean row length and the total
// size (for files the file system's, which the file cannot lie about), so a 100 MB log does not double its
// vectors a dozen times; the reservation is capped by the row limit.
ImportBatch parse_lines(PowerLineReader& lines, PowerCsvParser& parser, const CancelToken& cancel) {
  bool reserved = false;
  while (const auto line = lines.next()) {
    parser.line(*line, lines.line_number());
    if ((lines.line_number() & 0x3ff) == 0) {
      cancel.throw_if_cancelled();
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

ImportBatch read_power_csv(const std::string& path, const PowerImportOptions& options, const ImportLimits& limits,
                           const CancelToken& cancel) {
  PowerLineReader lines(path);
  PowerCsvParser parser(path, options, limits);
  return parse_lines(lines, parser, cancel);
}

ImportBatch parse_power_csv(std::string_view text, const std::string& file, const CancelToken& cancel,
                            const PowerImportOptions& options, const ImportLimits& limits) {
  PowerLineReader lines(text, file);
  PowerCsvParser parser(file, options, limits);
  return parse_lines(lines, parser, cancel);
}

}  // namespace bs
