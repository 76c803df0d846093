// SPDX-License-Identifier: GPL-3.0-or-later
#include "power_csv.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <optional>

namespace bs {
namespace {

enum class Role { Ignore, Time, Current, Voltage, Power };

struct Column {
  std::string name;
  Role role = Role::Ignore;
  double scale = 1;  // file unit -> SI (ms -> s: 1e-3, mA -> A: 1e-3, ...)
};

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (std::isspace(static_cast<unsigned char>(s.front())) || s.front() == '"')) s.remove_prefix(1);
  while (!s.empty() && (std::isspace(static_cast<unsigned char>(s.back())) || s.back() == '"')) s.remove_suffix(1);
  return s;
}

// Role and unit of a header cell. The unit is read from "(mA)", "[mA]" or a "_ma" suffix; names are aliases.
Column classify(std::string_view raw) {
  Column col{std::string(trim(raw))};
  std::string n = lower(col.name);
  std::string unit;
  const auto open = n.find_first_of("([");
  if (open != std::string::npos) {
    const auto close = n.find_first_of(")]", open);
    unit = n.substr(open + 1, close == std::string::npos ? std::string::npos : close - open - 1);
    n = n.substr(0, open);
  }
  while (!n.empty() && (n.back() == ' ' || n.back() == '_')) n.pop_back();
  if (unit.empty()) {
    const auto us = n.rfind('_');
    if (us != std::string::npos) {
      unit = n.substr(us + 1);
      n = n.substr(0, us);
    }
  }
  const auto has = [&](const char* word) { return n.find(word) != std::string::npos; };
  // English names plus the German ones that decimal-comma spreadsheet exports often carry.
  if (n == "t" || has("time") || has("second") || n == "millis" || has("elapsed") || has("zeit")) {
    col.role = Role::Time;
    if (n == "millis" || unit == "ms") col.scale = 1e-3;
    else if (unit == "us" || unit == "\xC2\xB5s") col.scale = 1e-6;
  } else if (n == "i" || has("current") || n == "a" || n == "ma" || has("strom")) {
    col.role = Role::Current;
    if (unit == "ma" || n == "ma") col.scale = 1e-3;
    else if (unit == "ua" || unit == "\xC2\xB5" "a") col.scale = 1e-6;
  } else if (n == "v" || has("voltage") || has("bus") || n == "mv" || has("spannung")) {
    col.role = Role::Voltage;
    if (unit == "mv" || n == "mv") col.scale = 1e-3;
    if (has("shunt")) col.role = Role::Ignore;  // INA219's shunt drop is not the supply voltage
  } else if (n == "p" || has("power") || n == "w" || n == "mw" || has("leistung")) {
    col.role = Role::Power;
    if (unit == "mw" || n == "mw") col.scale = 1e-3;
  }
  if (n.find("shunt") != std::string::npos) col.role = Role::Ignore;
  return col;
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

// One line at a time without copying the file; tracks the 1-based line number for errors.
class Lines {
 public:
  explicit Lines(std::string_view text) : text_(text) {}
  std::optional<std::string_view> next() {
    if (pos_ >= text_.size()) return std::nullopt;
    const auto end = std::min(text_.find('\n', pos_), text_.size());
    std::string_view line = text_.substr(pos_, end - pos_);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    pos_ = end + 1;
    ++number_;
    return line;
  }
  std::size_t number() const { return number_; }

 private:
  std::string_view text_;
  std::size_t pos_ = 0, number_ = 0;
};

}  // namespace

int PowerCsvImporter::sniff(std::string_view head, std::string_view) const {
  Lines lines(head);
  while (auto line = lines.next()) {
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
    std::size_t start = 0;
    while (start <= l.size()) {
      const auto end = std::min(l.find(sep, start), l.size());
      const Column c = classify(l.substr(start, end - start));
      time = time || c.role == Role::Time;
      signal = signal || c.role == Role::Current || c.role == Role::Power;
      start = end + 1;
    }
    if (time && signal) return 70;
    if (!comment) return 0;
  }
  return 0;
}

ImportBatch PowerCsvImporter::parse(const std::string& path, const ImportLimits& limits,
                                    const CancelToken& cancel) const {
  return parse_power_csv(read_whole_file(path, limits.max_json_bytes), path, cancel);
}

ImportBatch parse_power_csv(std::string_view text, const std::string& file, const CancelToken& cancel) {
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
  Lines lines(text);
  std::vector<Column> columns;
  char sep = ',';
  std::vector<std::string> comments;
  // Header: the first non-comment line, or a '#' line that names the columns.
  while (auto line = lines.next()) {
    std::string_view l = trim(*line);
    if (l.empty()) continue;
    const bool comment = l.front() == '#';
    if (comment) l.remove_prefix(1);
    sep = sniff_separator(l);
    std::vector<Column> cols;
    std::size_t start = 0;
    while (start <= l.size()) {
      const auto end = std::min(l.find(sep, start), l.size());
      cols.push_back(classify(l.substr(start, end - start)));
      start = end + 1;
    }
    const bool names_columns = std::any_of(cols.begin(), cols.end(), [](const Column& c) { return c.role == Role::Time; });
    if (comment && !names_columns) {
      comments.emplace_back(trim(l));
      continue;
    }
    if (!names_columns)
      throw ImportError(ImportErrorCategory::MissingField, {file, lines.number(), 1, "header"},
                        "no time column (expected a header such as time_s,current_A)");
    columns = std::move(cols);
    break;
  }
  if (columns.empty()) throw ImportError(ImportErrorCategory::Empty, {file, 0, 0, {}}, "no header line");
  const auto count_role = [&](Role r) { return std::count_if(columns.begin(), columns.end(), [&](const Column& c) { return c.role == r; }); };
  if (count_role(Role::Current) + count_role(Role::Power) == 0)
    throw ImportError(ImportErrorCategory::MissingField, {file, lines.number(), 1, "header"},
                      "no current or power column (expected e.g. current_A, current_mA, power_W)");
  const bool decimal_comma = sep != ',';

  PowerTrace trace;
  trace.label = file.substr(file.find_last_of('/') == std::string::npos ? 0 : file.find_last_of('/') + 1);
  trace.provenance.origin = DataOrigin::Measured;
  for (const auto& c : comments) {
    const std::string lc = lower(c);
    if (lc.find("reconstructed") != std::string::npos) trace.provenance.origin = DataOrigin::Reconstructed;
    // "# platform: NUC" and "# supply_voltage_V: 16" name what the log cannot say in its columns.
    const auto colon = c.find(':');
    if (colon == std::string::npos) continue;
    const std::string key = lower(trim(std::string_view(c).substr(0, colon)));
    const std::string_view value = trim(std::string_view(c).substr(colon + 1));
    if (key == "platform") trace.platform = std::string(value);
    if (key == "supply_voltage_v") {
      double v = 0;
      const auto [ptr, ec] = std::from_chars(value.data(), value.data() + value.size(), v);
      if (ec != std::errc() || !(v > 0)) throw ImportError(ImportErrorCategory::InvalidValue, {file, 0, 0, "supply_voltage_V"}, "expected volts > 0");
      trace.supply_voltage_v = v;
    }
  }
  trace.provenance.note = [&] {
    std::string n;
    for (const auto& c : comments) n += (n.empty() ? "" : " ") + c;
    return n;
  }();
  trace.provenance.source_file = file;
  std::vector<int> channel_of(columns.size(), -1);
  for (std::size_t i = 0; i < columns.size(); ++i) {
    const Role r = columns[i].role;
    if (r == Role::Current || r == Role::Voltage || r == Role::Power) {
      channel_of[i] = static_cast<int>(trace.channels.size());
      trace.channels.push_back({columns[i].name,
                                r == Role::Current ? PowerQuantity::Current
                                : r == Role::Voltage ? PowerQuantity::Voltage
                                                     : PowerQuantity::Power,
                                {}});
    }
  }
  const auto time_col = static_cast<std::size_t>(
      std::find_if(columns.begin(), columns.end(), [](const Column& c) { return c.role == Role::Time; }) - columns.begin());
  std::string cell;
  double t0 = 0;
  while (auto line = lines.next()) {
    std::string_view l = trim(*line);
    if (l.empty() || l.front() == '#') continue;
    if ((lines.number() & 0xfff) == 0) cancel.throw_if_cancelled();
    std::size_t start = 0, col = 0;
    double t = 0;
    while (start <= l.size() && col < columns.size()) {
      const auto end = std::min(l.find(sep, start), l.size());
      const std::string_view raw = trim(l.substr(start, end - start));
      if (columns[col].role != Role::Ignore) {
        cell.assign(raw);
        if (decimal_comma) std::replace(cell.begin(), cell.end(), ',', '.');
        double v = 0;
        const auto [ptr, ec] = std::from_chars(cell.data(), cell.data() + cell.size(), v);
        if (ec != std::errc() || ptr != cell.data() + cell.size() || cell.empty() || !std::isfinite(v)) {
          const bool other_separator = raw.find_first_of(sep == ',' ? ";\t" : sep == ';' ? "\t" : ";") != std::string_view::npos;
          if (other_separator)
            throw ImportError(ImportErrorCategory::Syntax, {file, lines.number(), start + 1, columns[col].name},
                              "mixed separators: '" + std::string(raw) + "' in a file whose header uses '" +
                                  (sep == '\t' ? std::string("tab") : std::string(1, sep)) + "'");
          throw ImportError(ImportErrorCategory::InvalidValue, {file, lines.number(), start + 1, columns[col].name},
                            cell.empty() ? "empty cell" : "'" + cell + "' is not a number");
        }
        v *= columns[col].scale;
        if (col == time_col) t = v;
        else trace.channels[static_cast<std::size_t>(channel_of[col])].values.push_back(v);
      }
      start = end + 1;
      ++col;
    }
    if (col < columns.size())
      throw ImportError(ImportErrorCategory::Syntax, {file, lines.number(), l.size() + 1, {}},
                        "row has " + std::to_string(col) + " cells, the header " + std::to_string(columns.size()) +
                            (sep == ',' ? "" : " (mixed separators?)"));
    if (t < 0) throw ImportError(ImportErrorCategory::InvalidValue, {file, lines.number(), 1, columns[time_col].name}, "negative time");
    if (trace.time_s.empty()) t0 = t;
    else if (t - t0 < trace.time_s.back())
      throw ImportError(ImportErrorCategory::InvalidValue, {file, lines.number(), 1, columns[time_col].name},
                        "time goes backwards (" + std::to_string(t) + " after " + std::to_string(trace.time_s.back() + t0) + ")");
    trace.time_s.push_back(t - t0);
  }
  if (trace.time_s.empty()) throw ImportError(ImportErrorCategory::Empty, {file, lines.number(), 0, {}}, "header but no data rows");
  ImportBatch batch;
  batch.power_traces.push_back(std::move(trace));
  return batch;
}

}  // namespace bs
