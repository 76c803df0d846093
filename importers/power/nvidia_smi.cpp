// SPDX-License-Identifier: GPL-3.0-or-later
#include "power/nvidia_smi.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <unordered_map>
#include <vector>

#include "analysis/power/power_time.h"
#include "power/log_sustain.h"
#include "power/meter_log_text.h"
#include "power/power_line_reader.h"

namespace bs {
namespace {

using meter::trim;

// More distinct GPU keys than any machine has: a file that claims more is not a GPU log (and would otherwise make
// one trace per garbage row).
constexpr std::size_t kMaxGpus = 1024;

// Clock, ClockMax, Temperature and Reason columns make the GPU's sustained-performance record (#53).
enum class Role { Time, Bus, Uuid, Index, Name, Power, Driver, Limit, Clock, ClockMax, Temperature, Reason, Other };

struct Column {
  std::string name;  // the field name without its unit: "power.draw"
  std::string unit;  // from "[W]"; empty when the header has none (nounits keeps it, noheader has no header)
  Role role = Role::Other;
  std::string series;  // Clock, ClockMax: the clock's name ("SM"); Temperature: the sensor's ("GPU")
};

// nvidia-smi's clock fields, current ("clocks.sm", "clocks.current.sm") or maximum ("clocks.max.sm"), as the series
// name; the applications and default-applications clocks are settings, not readings, and are not matched.
std::string clock_series(std::string_view field) {
  if (field.starts_with("clocks.current."))
    field.remove_prefix(15);
  else if (field.starts_with("clocks.max."))
    field.remove_prefix(11);
  else if (field.starts_with("clocks."))
    field.remove_prefix(7);
  else
    return {};
  if (field == "sm") return "SM";
  if (field == "gr" || field == "graphics") return "graphics";
  if (field == "mem" || field == "memory") return "memory";
  if (field == "video") return "video";
  return {};
}

Column classify(std::string_view cell) {
  Column c;
  std::string_view name = trim(cell);
  if (const auto open = name.find(" ["); open != std::string_view::npos && name.back() == ']') {
    c.unit = std::string(name.substr(open + 2, name.size() - open - 3));
    name = trim(name.substr(0, open));
  }
  c.name = std::string(name);
  if (name == "timestamp")
    c.role = Role::Time;
  else if (name == "pci.bus_id" || name == "gpu_bus_id")
    c.role = Role::Bus;
  else if (name == "uuid" || name == "gpu_uuid")
    c.role = Role::Uuid;
  else if (name == "index")
    c.role = Role::Index;
  else if (name == "name" || name == "gpu_name")
    c.role = Role::Name;
  else if (name == "power.draw" || name == "power.draw.instant" || name == "power.draw.average")
    c.role = Role::Power;
  else if (name == "driver_version")
    c.role = Role::Driver;
  else if (name == "power.limit" || name == "enforced.power.limit")
    c.role = Role::Limit;
  else if (!(c.series = clock_series(name)).empty())
    c.role = name.starts_with("clocks.max.") ? Role::ClockMax : Role::Clock;
  else if (name == "temperature.gpu" || name == "temperature.memory") {
    c.role = Role::Temperature;
    c.series = name == "temperature.gpu" ? "GPU" : "memory";
  } else if ((name.starts_with("clocks_throttle_reasons.") || name.starts_with("clocks_event_reasons.")) &&
             !name.ends_with(".supported"))
    c.role = Role::Reason;
  return c;
}

// nvidia-smi writes "2023/10/05 14:31:02.123"; wrapper scripts often write ISO 8601 instead.
std::optional<double> parse_timestamp(std::string_view s) {
  if (s.size() >= 10 && s.size() < 64 && s[4] == '/' && s[7] == '/') {
    char copy[64];
    s.copy(copy, s.size());
    copy[4] = copy[7] = '-';
    return parse_iso8601(std::string_view(copy, s.size()));
  }
  return parse_iso8601(s);
}

bool slash_timestamp(std::string_view s) { return s.size() >= 19 && s[4] == '/' && s[7] == '/' && parse_timestamp(s); }

// "[N/A]", "[Not Supported]", "[Unknown Error]", "[GPU is lost]": nvidia-smi could not read the value.
bool missing_cell(std::string_view c) { return (c.size() >= 2 && c.front() == '[' && c.back() == ']') || c == "N/A"; }

enum class Cell { Ok, Missing, Bad };

// A power cell: "285.43 W", or "285.43" with nounits.
Cell watts(std::string_view c, double& v) {
  if (missing_cell(c)) return Cell::Missing;
  if (c.ends_with('W')) c = trim(c.substr(0, c.size() - 1));
  return meter::number(c, v) ? Cell::Ok : Cell::Bad;
}

// How often one throttle-reason column said the reason was active, and when first.
struct ReasonSeen {
  std::size_t samples = 0;
  double first_s = 0;
};

struct Gpu {
  std::string key, name;
  double first_epoch = 0;
  PowerTrace trace;
  // One entry per sensor column (NvidiaSmiParser::sensor_cols_), same order: values (MHz or C) or reason counts.
  std::vector<meter::SampleSeries::Series> series;
  std::vector<std::optional<double>> max_mhz;  // per sensor column: the highest clocks.max.* reading (ClockMax)
  std::vector<ReasonSeen> reasons;
};

class NvidiaSmiParser : meter::LineParserBase {
 public:
  using LineParserBase::LineParserBase;
  void line(std::string_view raw, std::size_t line_no, bool last);
  ImportBatch finish();

 private:
  void header(std::size_t line_no);
  bool infer_columns(std::size_t line_no);
  Gpu& gpu_for(std::size_t line_no);

  std::vector<std::string_view> cells_;
  std::vector<Column> cols_;
  std::string header_line_;
  bool have_columns_ = false, noheader_ = false;
  std::size_t time_col_ = 0;
  std::optional<std::size_t> key_col_, name_col_, driver_col_, limit_col_;
  std::vector<std::size_t> power_cols_;
  std::vector<std::size_t> sensor_cols_;  // Clock, ClockMax, Temperature and Reason columns, in file order
  std::vector<Gpu> gpus_;
  void sensors(Gpu& g, std::size_t line_no);
  std::optional<SustainRun> sustain_run(Gpu& g) const;
  std::size_t bad_sensor_ = 0;
  std::unordered_map<std::string, std::size_t> gpu_index_;
  std::size_t samples_ = 0, missing_ = 0;
};

void NvidiaSmiParser::header(std::size_t line_no) {
  // A column in another unit than nvidia-smi writes is refused: its numbers would be read in the wrong unit.
  const auto require_unit = [&](const Column& c, const std::string& unit, const std::string& what) {
    if (!c.unit.empty() && c.unit != unit)
      fail(ImportErrorCategory::Unsupported, line_no, c.name,
           "unit '" + c.unit + "' for " + what + " (nvidia-smi writes " + unit + ")");
  };
  std::string ignored;
  for (std::size_t i = 0; i < cells_.size(); ++i) {
    Column c = classify(cells_[i]);
    switch (c.role) {
      case Role::Time:
        time_col_ = i;
        break;
      case Role::Bus:
        key_col_ = i;
        break;
      case Role::Uuid:
        if (!key_col_ || cols_[*key_col_].role != Role::Bus) key_col_ = i;
        break;
      case Role::Index:
        if (!key_col_ || cols_[*key_col_].role == Role::Name) key_col_ = i;
        break;
      case Role::Name:
        name_col_ = i;
        if (!key_col_) key_col_ = i;
        break;
      case Role::Power:
        require_unit(c, "W", "power");
        power_cols_.push_back(i);
        break;
      case Role::Driver:
        driver_col_ = i;
        break;
      case Role::Limit:
        if (!limit_col_) limit_col_ = i;
        break;
      case Role::Clock:
      case Role::ClockMax:
        require_unit(c, "MHz", "a clock");
        sensor_cols_.push_back(i);
        break;
      case Role::Temperature:
        require_unit(c, "C", "a temperature");
        sensor_cols_.push_back(i);
        break;
      case Role::Reason:
        sensor_cols_.push_back(i);
        break;
      case Role::Other:
        ignored += (ignored.empty() ? "" : ", ") + c.name;
        break;
    }
    cols_.push_back(std::move(c));
  }
  if (power_cols_.empty())
    fail(ImportErrorCategory::MissingField, line_no, "header",
         "no power.draw column (query it: nvidia-smi --query-gpu=timestamp,name,pci.bus_id,power.draw --format=csv -l "
         "1)");
  if (std::none_of(cols_.begin(), cols_.end(), [](const Column& c) { return c.role == Role::Time; }))
    fail(ImportErrorCategory::MissingField, line_no, "header",
         "no timestamp column: the times of the samples are not in the file (add timestamp to --query-gpu)");
  if (!ignored.empty())
    batch_.warnings.push_back(file_ + ": columns that are not power, a clock or a temperature ignored: " + ignored);
}

// noheader: safe only with one nvidia-smi timestamp cell and exactly one cell in W (the power); the GPU is told
// apart by a PCI bus id ("00000000:01:00.0") or a UUID ("GPU-...") cell, its name by a cell starting "NVIDIA".
bool NvidiaSmiParser::infer_columns(std::size_t line_no) {
  std::optional<std::size_t> time, power;
  std::size_t in_watts = 0;
  for (std::size_t i = 0; i < cells_.size(); ++i) {
    const std::string_view c = cells_[i];
    double w = 0;
    Column col;
    col.name = "column " + std::to_string(i + 1);
    if (!time && slash_timestamp(c)) {
      time = i;
      col.role = Role::Time;
    } else if (c.size() > 2 && c.ends_with(" W") && watts(c, w) == Cell::Ok) {
      ++in_watts;
      power = i;
      col.role = Role::Power;
      col.name = "power.draw";
    } else if (c.size() == 16 && c[8] == ':' && c[11] == ':' && c[14] == '.') {
      key_col_ = i;
      col.role = Role::Bus;
    } else if (c.starts_with("GPU-") && !key_col_) {
      key_col_ = i;
      col.role = Role::Uuid;
    } else if (c.starts_with("NVIDIA ")) {
      name_col_ = i;
      col.role = Role::Name;
    }
    cols_.push_back(std::move(col));
  }
  if (!time) return false;
  if (in_watts != 1)
    fail(ImportErrorCategory::MissingField, line_no, "header",
         "nvidia-smi log without a header and " + std::to_string(in_watts) +
             " columns in W: which one is power.draw cannot be told; keep the header (--format=csv, without "
             "noheader) or keep the units (without nounits) and query one power field");
  time_col_ = *time;
  power_cols_.push_back(*power);
  noheader_ = true;
  batch_.warnings.push_back(file_ + ": no header; columns inferred from the first row (timestamp in column " +
                            std::to_string(*time + 1) + ", power in W in column " + std::to_string(*power + 1) + ")");
  return true;
}

Gpu& NvidiaSmiParser::gpu_for(std::size_t line_no) {
  std::string key = key_col_ ? std::string(cells_[*key_col_]) : std::string();
  if (const auto it = gpu_index_.find(key); it != gpu_index_.end()) return gpus_[it->second];
  if (gpus_.size() >= kMaxGpus)
    fail(ImportErrorCategory::TooLarge, line_no, key_col_ ? cols_[*key_col_].name : "",
         "more than " + std::to_string(kMaxGpus) + " different GPUs");
  gpu_index_.emplace(key, gpus_.size());
  Gpu& g = gpus_.emplace_back();
  g.key = std::move(key);
  if (name_col_ && !missing_cell(cells_[*name_col_])) g.name = std::string(cells_[*name_col_]);
  for (std::size_t col : power_cols_) g.trace.channels.push_back({cols_[col].name, PowerQuantity::Power, {}});
  for (std::size_t col : sensor_cols_) g.series.push_back({cols_[col].series, {}});
  g.max_mhz.resize(sensor_cols_.size());
  g.reasons.resize(sensor_cols_.size());
  auto& settings = g.trace.provenance.settings;
  if (driver_col_) settings.emplace_back("driver_version", std::string(cells_[*driver_col_]));
  if (limit_col_) {
    std::string limit(cells_[*limit_col_]);
    if (!noheader_ && cols_[*limit_col_].unit == "W" && !limit.ends_with('W') && !missing_cell(limit)) limit += " W";
    settings.emplace_back(cols_[*limit_col_].name, limit);
  }
  return g;
}

void NvidiaSmiParser::line(std::string_view raw, std::size_t line_no, bool last) {
  meter::split(raw, ',', cells_);
  if (!have_columns_) {
    bool header_row = false;
    for (std::string_view c : cells_) header_row = header_row || classify(c).role == Role::Power;
    if (header_row) {
      header(line_no);
      header_line_ = std::string(trim(raw));
      have_columns_ = true;
      return;
    }
    if (!infer_columns(line_no))
      fail(ImportErrorCategory::MissingField, line_no, "header",
           "no nvidia-smi header with power.draw (the first line is '" + std::string(trim(raw).substr(0, 80)) +
               "'); keep the header: nvidia-smi --query-gpu=timestamp,name,pci.bus_id,power.draw --format=csv");
    have_columns_ = true;
  } else if (!header_line_.empty() && trim(raw) == header_line_) {
    return skip(line_no, "the header again (logs appended one after another)");
  }
  if (cells_.size() != cols_.size()) {
    if (last) return skip(line_no, "incomplete last line (nvidia-smi stopped while writing it)");
    fail(ImportErrorCategory::Syntax, line_no, "",
         std::to_string(cells_.size()) + " cells; the header has " + std::to_string(cols_.size()));
  }
  const auto epoch = parse_timestamp(cells_[time_col_]);
  if (!epoch) {
    if (last) return skip(line_no, "incomplete last line");
    fail(ImportErrorCategory::InvalidValue, line_no, "timestamp",
         "'" + std::string(cells_[time_col_]) + "' is not a date-time (expected 2023/10/05 14:31:02.123)");
  }
  std::vector<double> values(power_cols_.size());
  for (std::size_t k = 0; k < power_cols_.size(); ++k) {
    switch (watts(cells_[power_cols_[k]], values[k])) {
      case Cell::Ok:
        break;
      case Cell::Missing:
        values[k] = std::numeric_limits<double>::quiet_NaN();
        ++missing_;
        break;
      case Cell::Bad:
        if (last) return skip(line_no, "incomplete last line");
        fail(ImportErrorCategory::InvalidValue, line_no, cols_[power_cols_[k]].name,
             "'" + std::string(cells_[power_cols_[k]]) + "' is not a power in W");
    }
  }
  if (++samples_ > limits_.max_samples)
    fail(ImportErrorCategory::TooLarge, line_no, "",
         "more than " + std::to_string(limits_.max_samples) + " rows (the limit for one log)");
  Gpu& g = gpu_for(line_no);
  PowerTrace& t = g.trace;
  if (t.time_s.empty()) {
    g.first_epoch = *epoch;
    t.start_time = format_iso8601(*epoch);
  }
  const double rel = *epoch - g.first_epoch;
  if (!t.time_s.empty() && rel < t.time_s.back())
    fail(ImportErrorCategory::InvalidValue, line_no, "timestamp",
         "time goes backwards for GPU '" + g.key + "' (" + std::string(cells_[time_col_]) + ")");
  t.time_s.push_back(rel);
  for (std::size_t k = 0; k < values.size(); ++k) t.channels[k].values.push_back(values[k]);
  sensors(g, line_no);
}

// The row's clocks ("1530 MHz", or 1530 with nounits), temperatures ("65", "65 C") and throttle reasons ("Active",
// "Not Active"; the .active bit mask "0x0000000000000004"). Not power: a cell that does not parse is a warning and
// NaN, the row's power stays; "[N/A]" is a missing reading.
void NvidiaSmiParser::sensors(Gpu& g, std::size_t line_no) {
  for (std::size_t k = 0; k < sensor_cols_.size(); ++k) {
    const Column& c = cols_[sensor_cols_[k]];
    std::string_view cell = cells_[sensor_cols_[k]];
    double v = std::numeric_limits<double>::quiet_NaN();
    bool ok = missing_cell(cell);
    if (c.role == Role::Reason) {
      unsigned long long mask = 0;
      const bool hex =
          cell.starts_with("0x") && cell.size() <= 18 &&
          std::from_chars(cell.data() + 2, cell.data() + cell.size(), mask, 16).ptr == cell.data() + cell.size();
      // Bit 0x1 of the mask is "GPU idle": the clock is low because there is no work, not throttling.
      const bool active = cell == "Active" || (hex && (mask & ~1ULL) != 0);
      ok = ok || active || cell == "Not Active" || hex;
      if (active && g.reasons[k].samples++ == 0) g.reasons[k].first_s = g.trace.time_s.back();
    } else if (!ok) {
      const std::string_view unit = c.role == Role::Temperature ? " C" : " MHz";
      if (cell.ends_with(unit)) cell.remove_suffix(unit.size());
      const bool sane = c.role == Role::Temperature ? meter::number(cell, v) && v > -100 && v < 200
                                                    : meter::number(cell, v) && v >= 0 && v < 100'000;
      ok = sane;
      if (!sane) v = std::numeric_limits<double>::quiet_NaN();
      if (sane && c.role == Role::ClockMax) g.max_mhz[k] = std::max(g.max_mhz[k].value_or(0), v);
    }
    if (c.role != Role::Reason) g.series[k].values.push_back(v);
    if (!ok && ++bad_sensor_ <= kListedWarnings)
      batch_.warnings.push_back(file_ + ":" + std::to_string(line_no) + ": " + c.name + ": '" +
                                std::string(cells_[sensor_cols_[k]]) + "' is not a " +
                                (c.role == Role::Temperature ? "temperature in C"
                                 : c.role == Role::Reason    ? "throttle reason (Active, Not Active or a 0x mask)"
                                                             : "clock in MHz") +
                                "; kept as missing");
  }
}

// The GPU's sustained-performance record: its clocks with their maximum (clocks.max.* of the same clock), its
// temperatures, and in the note how often each throttle reason was active.
std::optional<SustainRun> NvidiaSmiParser::sustain_run(Gpu& g) const {
  meter::LogSensors s;
  std::vector<std::optional<double>> max_of;  // by clock name
  for (std::size_t k = 0; k < sensor_cols_.size(); ++k) {
    const Column& c = cols_[sensor_cols_[k]];
    if (c.role == Role::Clock) {
      s.clocks_mhz.push_back(std::move(g.series[k]));
      s.max_mhz.emplace_back();
      for (std::size_t m = 0; m < sensor_cols_.size(); ++m)
        if (cols_[sensor_cols_[m]].role == Role::ClockMax && cols_[sensor_cols_[m]].series == c.series)
          s.max_mhz.back() = g.max_mhz[m];
    } else if (c.role == Role::Temperature) {
      s.celsius.push_back(std::move(g.series[k]));
    } else if (c.role == Role::Reason) {
      char first[32];
      std::snprintf(first, sizeof first, "%g", g.reasons[k].first_s);
      s.notes.push_back(c.name + (g.reasons[k].samples == 0 ? std::string(" never active")
                                                            : " active in " + std::to_string(g.reasons[k].samples) +
                                                                  " of " + std::to_string(g.trace.time_s.size()) +
                                                                  " samples, first at " + first + " s"));
    }
  }
  if (std::none_of(s.clocks_mhz.begin(), s.clocks_mhz.end(), [](const auto& c) { return c.name == "SM"; }))
    s.not_exposed.push_back(noheader_ ? "no header: no clock or temperature column can be told"
                                      : "no SM clock (clocks.sm not queried): GPU clock throttling cannot be seen");
  s.notes.push_back("nvidia-smi clocks in MHz, temperatures in C; [N/A] kept as missing");
  return meter::log_sustain_run(g.trace, std::move(s));
}

ImportBatch NvidiaSmiParser::finish() {
  if (gpus_.empty())
    throw ImportError(ImportErrorCategory::MissingField, {file_, 0, 0, {}},
                      have_columns_ ? "a header but no rows" : "no nvidia-smi rows");
  more_skipped_warning();
  if (bad_sensor_ > kListedWarnings)
    batch_.warnings.push_back(file_ + ": " + std::to_string(bad_sensor_ - kListedWarnings) +
                              " more clock, temperature or throttle-reason cells that do not parse, kept as missing");
  if (missing_ > 0)
    batch_.warnings.push_back(file_ + ": " + std::to_string(missing_) +
                              " power readings nvidia-smi could not take ([N/A], [Not Supported]) are missing samples");
  const std::string label = meter::file_name(file_);
  for (Gpu& g : gpus_) {
    PowerTrace& t = g.trace;
    t.platform = options_.platform;
    // A GPU is named by its name when the log has it ("NVIDIA RTX A2000 12GB"), with its bus id only when two
    // GPUs share the name (issue #32.8).
    const bool shared_name = std::count_if(gpus_.begin(), gpus_.end(),
                                           [&](const Gpu& o) { return !g.name.empty() && o.name == g.name; }) > 1;
    const std::string gpu = g.name.empty() ? "GPU " + g.key : shared_name ? g.name + " (" + g.key + ")" : g.name;
    t.label = gpus_.size() > 1 ? label + " " + gpu : label;
    for (const char* pick : {"power.draw", "power.draw.instant", "power.draw.average"})
      if (t.total_channel.empty())
        for (const auto& c : t.channels)
          if (c.name == pick) t.total_channel = c.name;
    // The total first as well: readers that take the first power channel (as before total_channel) agree.
    std::stable_partition(t.channels.begin(), t.channels.end(),
                          [&](const PowerChannel& c) { return c.name == t.total_channel; });
    meter::stamp_log_provenance(t, file_, "nvidia-smi", MeasurementKind::OnBoardSensor, "NVML (nvidia-smi)");
    auto& p = t.provenance;
    p.gpu_model = g.name;
    if (!g.key.empty() && gpus_.size() > 1) p.note = "GPU " + g.key;
    if (auto run = sustain_run(g)) batch_.sustain_runs.push_back(std::move(*run));
    batch_.power_traces.push_back(std::move(t));
  }
  return std::move(batch_);
}

}  // namespace

static int sniff_nvidia_smi(std::string_view head, std::string_view) {
  PowerLineReader lines(head, {});
  std::vector<std::string_view> cells;
  while (const auto line = lines.next()) {
    if (trim(*line).empty()) continue;
    meter::split(*line, ',', cells);
    bool power = false, power_in_watts = false, timestamp_cell = false, watt_cell = false;
    int known = 0;
    for (std::string_view c : cells) {
      const Column col = classify(c);
      power = power || col.role == Role::Power;
      power_in_watts = power_in_watts || (col.role == Role::Power && col.unit == "W");
      known += col.role != Role::Other || !col.unit.empty();
      timestamp_cell = timestamp_cell || slash_timestamp(c);
      watt_cell = watt_cell || (c.size() > 2 && c.ends_with(" W"));
    }
    if (power_in_watts) return 95;       // "power.draw [W]": nvidia-smi's own header
    if (power && known >= 2) return 90;  // nounits header, or a wrapper's header of nvidia-smi field names
    if (power) return 60;
    // noheader: nvidia-smi's timestamp format; parse() decides whether the columns can be inferred.
    if (timestamp_cell) return watt_cell ? 85 : 40;
    return 0;
  }
  return 0;
}

const FileFormat kNvidiaSmiFileFormat{"nvidia-smi", "nvidia-smi --query-gpu CSV log (GPU power)", sniff_nvidia_smi,
                                      meter::parse_log_file<NvidiaSmiParser>, meter::parse_log_text<NvidiaSmiParser>};

}  // namespace bs
