// SPDX-License-Identifier: GPL-3.0-or-later
#include "store/tables.h"

#include <bit>
#include <cstring>

#include "headroom/headroom_json.h"
#include "model/provenance_json.h"
#include "sustain/sustain_json.h"

namespace bs::store {
namespace {

// Where a column's value lives in the row's model type, for both writing (const) and reading.
#define BS_FIELD(member) \
  [](auto& r) -> auto& { return r.member; }
#define BS_SELF \
  [](auto& r) -> auto& { return r; }

using C = ImportErrorCategory;

// --- JSON values --------------------------------------------------------------------------------------------

// Measurement values are JSON text. JSON has no NaN (nlohmann writes null), so a repetition that produced no
// number is the string "nan" and keeps its place. Infinities are written the same way but refused on reading:
// no importer produces one, and a view would print it.
nlohmann::json number_to_json(double v) {
  if (std::isfinite(v)) return v;
  return std::isnan(v) ? "nan" : (v > 0 ? "inf" : "-inf");
}

Check number_from_json(const nlohmann::json& j, double& out) {
  if (j.is_number()) {
    out = j.get<double>();
    return detail::bounded(out, Bound::Finite);
  }
  if (j.is_string() && j.get_ref<const std::string&>() == "nan") {
    out = std::numeric_limits<double>::quiet_NaN();
    return std::nullopt;
  }
  return flaw(C::InvalidValue, "'" + j.dump() + "' is not a finite number (or \"nan\" for a missing repetition)");
}

Column<Measurement> measurement_values() {
  return json<Measurement>(
      "vals", BS_FIELD(values),
      [](const std::vector<double>& values) {
        nlohmann::json a = nlohmann::json::array();
        for (const double v : values) a.push_back(number_to_json(v));
        return a;
      },
      [](const nlohmann::json& j, std::vector<double>& values, const ImportLimits& l) -> Check {
        if (!j.is_array()) return flaw(C::WrongType, "is not a JSON array");
        if (j.size() > l.max_samples)
          return flaw(C::TooLarge, std::to_string(j.size()) + " values (limit " + std::to_string(l.max_samples) + ")");
        values.reserve(j.size());
        for (std::size_t k = 0; k < j.size(); ++k) {
          double v = 0;
          if (auto f = number_from_json(j[k], v))
            return flaw(f->category, "value " + std::to_string(k) + ": " + f->reason);
          values.push_back(v);
        }
        return std::nullopt;
      });
}

Column<Measurement> measurement_aggregates() {
  return json<Measurement>(
      "aggregates", BS_FIELD(reported_aggregates),
      [](const std::vector<std::pair<std::string, double>>& aggregates) {
        nlohmann::json a = nlohmann::json::array();
        for (const auto& [name, value] : aggregates) a.push_back({name, number_to_json(value)});
        return a;
      },
      [](const nlohmann::json& j, std::vector<std::pair<std::string, double>>& out, const ImportLimits& l) -> Check {
        if (!j.is_array()) return flaw(C::WrongType, "is not a JSON array");
        if (j.size() > l.max_samples) return flaw(C::TooLarge, std::to_string(j.size()) + " aggregates");
        for (const auto& a : j) {
          if (!a.is_array() || a.size() != 2 || !a[0].is_string())
            return flaw(C::WrongType, "an aggregate is not a [name, value] pair: " + a.dump());
          double v = 0;
          if (auto f = number_from_json(a[1], v)) return flaw(f->category, a[0].get<std::string>() + ": " + f->reason);
          if (a[0] == "repetitions" && !(v >= 0)) return flaw(C::InvalidValue, "repetitions " + number_text(v));
          out.emplace_back(a[0].get<std::string>(), v);
        }
        return std::nullopt;
      });
}

template <class T, class Get>
Column<T> provenance(Get get) {
  return json<T>(
      "provenance", get, [](const Provenance& p) { return provenance_to_json(p, true); },
      [](const nlohmann::json& j, Provenance& p, const ImportLimits&) -> Check {
        if (!j.is_object()) return flaw(C::WrongType, "is JSON but not an object");
        p = provenance_from_json(j);
        return std::nullopt;
      });
}

// A channel's whole-log statistics, as written by the import (and schema 6's migration, store/power_samples.cpp).
Column<ChannelSummary> channel_summary() {
  return json<ChannelSummary>(
      "summary", BS_SELF,
      [](const ChannelSummary& c) {
        const Summary& s = c.stats.summary;
        return nlohmann::json{{"n", s.n},
                              {"mean", s.mean},
                              {"sd", s.sd},
                              {"min", s.min},
                              {"max", s.max},
                              {"p5", c.stats.pct.p5},
                              {"p50", c.stats.pct.p50},
                              {"p95", c.stats.pct.p95},
                              {"p99", c.stats.pct.p99},
                              {"integral", c.integral}};
      },
      [](const nlohmann::json& j, ChannelSummary& c, const ImportLimits& l) -> Check {
        if (!j.is_object()) return flaw(C::WrongType, "is JSON but not an object");
        const auto number = [&](const char* key, double& out) -> Check {
          const auto it = j.find(key);
          if (it == j.end()) return flaw(C::MissingField, std::string("no '") + key + "'");
          if (!it->is_number()) return flaw(C::WrongType, std::string("'") + key + "' is not a number");
          out = it->get<double>();
          if (auto f = detail::bounded(out, Bound::Finite)) return flaw(f->category, key + (": " + f->reason));
          return std::nullopt;
        };
        const auto n = j.find("n");
        if (n == j.end()) return flaw(C::MissingField, "no 'n'");
        if (!n->is_number_unsigned()) return flaw(C::InvalidValue, "'n' is not a count: " + n->dump());
        if (n->get<std::uint64_t>() > l.max_power_rows) return flaw(C::TooLarge, "'n' is " + n->dump());
        c.stats.summary.n = n->get<std::size_t>();
        Summary& s = c.stats.summary;
        for (const auto& [key, out] : {std::pair<const char*, double*>{"mean", &s.mean},
                                       {"sd", &s.sd},
                                       {"min", &s.min},
                                       {"max", &s.max},
                                       {"p5", &c.stats.pct.p5},
                                       {"p50", &c.stats.pct.p50},
                                       {"p95", &c.stats.pct.p95},
                                       {"p99", &c.stats.pct.p99},
                                       {"integral", &c.integral}})
          if (auto f = number(key, *out)) return f;
        if (s.sd < 0) return flaw(C::InvalidValue, "'sd' is negative: " + number_text(s.sd));
        if (s.n > 0 && s.min > s.max) return flaw(C::InvalidValue, "'min' is greater than 'max'");
        return std::nullopt;
      });
}

// The overview: a BLOB of (t, v) pairs of native doubles. Times are finite; a value may be NaN (a gap) but not
// infinite. Its size is bounded by what the import writes (two points per column, plus the ends).
Column<ChannelSummary> channel_overview() {
  return {
      "overview",
      [](sqlite::Statement& st, int i, const ChannelSummary& c) {
        std::vector<double> pairs;
        pairs.reserve(c.overview.t.size() * 2);
        for (std::size_t k = 0; k < c.overview.t.size(); ++k) {
          pairs.push_back(c.overview.t[k]);
          pairs.push_back(c.overview.v[k]);
        }
        st.bind_doubles(i, pairs);
      },
      [](const sqlite::Statement& st, int i, ChannelSummary& c, const ImportLimits& l) -> Check {
        if (auto f = detail::expect(st, i, SQLITE_BLOB, true, l)) return f;
        std::size_t bytes = 0;
        const void* p = st.blob(i, bytes);
        constexpr std::size_t kMaxPoints = 4 * kOverviewColumns + 16;
        if (bytes % (2 * sizeof(double)) != 0)
          return flaw(C::InvalidValue, std::to_string(bytes) + " bytes is not a whole number of (t, v) pairs");
        if (bytes / (2 * sizeof(double)) > kMaxPoints)
          return flaw(C::TooLarge, std::to_string(bytes / 16) + " points (limit " + std::to_string(kMaxPoints) + ")");
        const std::size_t n = bytes / (2 * sizeof(double));
        c.overview.t.resize(n);
        c.overview.v.resize(n);
        for (std::size_t k = 0; k < n; ++k) {
          double tv[2];
          std::memcpy(tv, static_cast<const char*>(p) + k * sizeof tv, sizeof tv);
          if (!std::isfinite(tv[0]) || std::isinf(tv[1]))
            return flaw(C::InvalidValue,
                        "point " + std::to_string(k) + " is (" + number_text(tv[0]) + ", " + number_text(tv[1]) + ")");
          c.overview.t[k] = tv[0];
          c.overview.v[k] = tv[1];
        }
        return std::nullopt;
      }};
}

// --- per-stage timing statistics (pipeline stages, a dnn run's forward pass) ------------------------------------

// The pipeline importer's rules (importers/runs/pipeline_json.cpp): min <= mean <= max, p50 <= p95, with a
// relative slack of 1e-9 for values rounded when written.
Check stage_rule(const StageStats& s) {
  const auto le = [](double a, double b) { return a <= b + 1e-9 * std::max(std::abs(a), std::abs(b)); };
  if (s.min_s && !le(*s.min_s, s.mean_s)) return flaw(C::InvalidValue, "min_s is greater than mean_s");
  if (s.max_s && !le(s.mean_s, *s.max_s)) return flaw(C::InvalidValue, "max_s is less than mean_s");
  if (s.p50_s && s.p95_s && !le(*s.p50_s, *s.p95_s)) return flaw(C::InvalidValue, "p95_s is less than p50_s");
  return std::nullopt;
}

template <class T, class Get>
void add_stage_columns(std::vector<Column<T>>& cols, Get stage, Bound mean_bound) {
  const auto field = [stage](auto member) {
    return [ stage, member ](auto& r) -> auto& { return stage(r).*member; };
  };
  cols.push_back(integer<T>("n", field(&StageStats::n), 1, kMaxFrames));
  cols.push_back(real<T>("mean_s", field(&StageStats::mean_s), mean_bound));
  cols.push_back(real<T>("sd_s", field(&StageStats::sd_s), Bound::NonNegative));
  cols.push_back(optional_real<T>("min_s", field(&StageStats::min_s), Bound::NonNegative));
  cols.push_back(optional_real<T>("max_s", field(&StageStats::max_s), Bound::NonNegative));
  cols.push_back(optional_real<T>("p50_s", field(&StageStats::p50_s), Bound::NonNegative));
  cols.push_back(optional_real<T>("p95_s", field(&StageStats::p95_s), Bound::NonNegative));
}

// The "data" column of a record kept whole as one JSON document beside a few columns (headroom measurements,
// sustained runs). The document is read through the same checks as any untrusted file (`from` throws `Error` on
// what it refuses); the columns read before it must agree with it (`disagreement` names what differs, else
// nullptr), except the platform, which the column alone holds (rename_platform updates it, not the document).
template <class T, class Error, class To, class From, class Disagreement>
Column<T> record_document(To to, From from, Disagreement disagreement) {
  return json<T>("data", BS_SELF, to,
                 [from, disagreement](const nlohmann::json& j, T& r, const ImportLimits&) -> Check {
                   try {
                     T read = from(j);
                     if (const char* differs = disagreement(read, r)) return flaw(C::InvalidValue, differs);
                     read.platform = r.platform;
                     r = std::move(read);
                     return std::nullopt;
                   } catch (const Error& e) {
                     return flaw(C::InvalidValue, e.what());
                   }
                 });
}

const std::vector<std::pair<DeviceKind, const char*>> kDeviceKinds = {
    {DeviceKind::Cpu, "cpu"}, {DeviceKind::Gpu, "gpu"}, {DeviceKind::Other, "other"}};

}  // namespace

PowerTrace trace_metadata(const PowerTrace& t) {
  PowerTrace m;
  m.platform = t.platform;
  m.label = t.label;
  m.start_time = t.start_time;
  m.supply_voltage_v = t.supply_voltage_v;
  m.phases = t.phases;
  m.provenance = t.provenance;
  m.total_channel = t.total_channel;
  for (const PowerChannel& c : t.channels) m.channels.push_back({c.name, c.quantity, {}});
  return m;
}

const Table<ImportRecord>& imports_table() {
  using T = ImportRecord;
  static const Table<T> t{
      "imports",
      "import",
      true,
      {},
      {text<T>("path", BS_FIELD(path)), text<T>("format", BS_FIELD(format)),
       text<T>("imported_at", BS_FIELD(imported_at)), text<T>("content_hash", BS_FIELD(content_hash)),
       integer<T>("run_count", BS_FIELD(run_count), 0, std::int64_t{1} << 40),
       integer<T>("result_set_count", BS_FIELD(result_set_count), 0, std::int64_t{1} << 40)},
      {}};
  return t;
}

const Table<DeviceRecord>& devices_table() {
  using T = DeviceRecord;
  static const Table<T> t{"devices",
                          "device",
                          true,
                          {},
                          {text<T>("platform", BS_FIELD(platform)), text<T>("device", BS_FIELD(device)),
                           enumeration<T>("kind", BS_FIELD(kind), kDeviceKinds),
                           integer<T>("color_index", BS_FIELD(color_index), 0, kMaxColorIndex)},
                          {}};
  return t;
}

const Table<FlopsRun>& runs_table() {
  using T = FlopsRun;
  static const Table<T> t{
      "runs",
      "run",
      true,
      {"import_id", "device_id"},
      {text<T>("backend", BS_FIELD(backend)), text<T>("kernel", BS_FIELD(kernel)),
       text<T>("variant", BS_FIELD(variant)), integer<T>("iterations", BS_FIELD(iterations), 1, kMaxIterations),
       integer<T>("dims", BS_FIELD(dims), 1, kMaxDims),
       optional_real<T>("reported_peak_flops", BS_FIELD(reported_peak_flops), Bound::Positive),
       optional_real<T>("theoretical_peak_flops", BS_FIELD(theoretical_peak_flops), Bound::Positive),
       provenance<T>(BS_FIELD(provenance))},
      {}};
  return t;
}

const Table<RunSampleRow>& run_samples_table() {
  using T = RunSampleRow;
  static const Table<T> t{"run_samples",
                          "run sample",
                          false,
                          {"run_id"},
                          {integer<T>("workers", BS_FIELD(workers), 1, kMaxWorkers),
                           integer<T>("repetition", BS_FIELD(repetition), 0, std::int64_t{1} << 40),
                           real<T>("seconds", BS_FIELD(seconds), Bound::Positive)},
                          {}};
  return t;
}

const Table<ResultSet>& result_sets_table() {
  using T = ResultSet;
  static const Table<T> t{"result_sets",
                          "result set",
                          true,
                          {"import_id", "device_id"},
                          {text<T>("backend", BS_FIELD(backend)), text<T>("source_format", BS_FIELD(source_format)),
                           provenance<T>(BS_FIELD(provenance))},
                          {}};
  return t;
}

const Table<Measurement>& measurements_table() {
  using T = Measurement;
  static const Table<T> t{"measurements",
                          "measurement",
                          true,
                          {"result_set_id"},
                          {text<T>("name", BS_FIELD(name)), text<T>("metric", BS_FIELD(metric)),
                           text<T>("unit", BS_FIELD(unit)), measurement_values(), measurement_aggregates()},
                          // A time or a rate is never negative (a user counter of another unit may be).
                          [](const T& m, const ImportLimits&) -> Check {
                            if (m.unit != "s" && m.unit != "FLOP/s" && m.unit != "B/s" && m.unit != "1/s")
                              return std::nullopt;
                            for (const double v : m.values)
                              if (v < 0)
                                return flaw(C::InvalidValue,
                                            "'" + m.name + "': " + number_text(v) + " " + m.unit + " is negative");
                            return std::nullopt;
                          }};
  return t;
}

const Table<StoredPowerTrace>& power_traces_table() {
  using T = StoredPowerTrace;
  static const Table<T> t{
      "power_traces",
      "power trace",
      true,
      {"import_id"},
      {text<T>("platform", BS_FIELD(trace.platform)), text<T>("label", BS_FIELD(trace.label)),
       text<T>("start_time", BS_FIELD(trace.start_time)),
       optional_real<T>("supply_voltage_v", BS_FIELD(trace.supply_voltage_v), Bound::Positive),
       // Schema 5's one-BLOB samples: kept empty so an older reader fails on the schema version, not a column.
       written_as<T>("time_s", [](sqlite::Statement& st, int i, const T&) { st.bind_doubles(i, {}); }),
       provenance<T>(BS_FIELD(trace.provenance)), text<T>("total_channel", BS_FIELD(trace.total_channel)),
       // Bounded by the import limit here and by the stored chunks' lengths before any sample is allocated.
       integer<T>("samples", BS_FIELD(summary.samples), 0, static_cast<std::int64_t>(ImportLimits{}.max_power_rows)),
       real<T>("duration_s", BS_FIELD(summary.duration_s), Bound::NonNegative)},
      {}};
  return t;
}

const Table<ChannelSummary>& power_channels_table() {
  using T = ChannelSummary;
  static const Table<T> t{
      "power_channels",
      "power channel",
      true,
      {"trace_id"},
      {text<T>("name", BS_FIELD(name)),
       enumeration<T>("quantity", BS_FIELD(quantity),
                      std::vector<std::pair<PowerQuantity, const char*>>{{PowerQuantity::Current, "current"},
                                                                         {PowerQuantity::Voltage, "voltage"},
                                                                         {PowerQuantity::Power, "power"}}),
       written_as<T>("vals", [](sqlite::Statement& st, int i, const T&) { st.bind_doubles(i, {}); }), channel_summary(),
       channel_overview()},
      {}};
  return t;
}

const Table<TracePhase>& power_phases_table() {
  using T = TracePhase;
  static const Table<T> t{"power_phases",
                          "power phase",
                          true,
                          {"trace_id"},
                          {text<T>("name", BS_FIELD(name)), real<T>("start_s", BS_FIELD(start_s), Bound::Finite),
                           real<T>("end_s", BS_FIELD(end_s), Bound::Finite)},
                          [](const T& p, const ImportLimits&) -> Check {
                            if (p.end_s < p.start_s)
                              return flaw(C::InvalidValue, "phase '" + p.name + "' ends (" + number_text(p.end_s) +
                                                               " s) before it starts (" + number_text(p.start_s) +
                                                               " s)");
                            return std::nullopt;
                          }};
  return t;
}

const Table<StoredFrame>& frames_table() {
  using T = StoredFrame;
  const int side = ImportLimits{}.max_frame_side;
  static const Table<T> t{
      "frames",
      "frame",
      true,
      {"import_id"},
      {text<T>("label", BS_FIELD(frame.label)),
       enumeration<T>("storage", BS_FIELD(frame.storage),
                      std::vector<std::pair<FrameStorage, const char*>>{{FrameStorage::Reference, "reference"},
                                                                        {FrameStorage::Copy, "copy"}}),
       text<T>("path", BS_FIELD(path)), text<T>("content_hash", BS_FIELD(content_hash)),
       text<T>("source_format", BS_FIELD(frame.source_format)),
       json_text<T>("read_options", BS_FIELD(frame.read_options), false, "{}"),
       integer<T>("width", BS_FIELD(frame.width), 1, side), integer<T>("height", BS_FIELD(frame.height), 1, side),
       integer<T>("channels", BS_FIELD(frame.channels), 1, 3),
       integer<T>("bit_depth", BS_FIELD(frame.bit_depth), 1, 16), text<T>("pattern", BS_FIELD(frame.pattern)),
       flag<T>("synthetic", BS_FIELD(frame.synthetic)), json_text<T>("lens", BS_FIELD(frame.lens_json), true),
       provenance<T>(BS_FIELD(frame.provenance)),
       written_as<T>("byte_order",
                     [](sqlite::Statement& st, int i, const T&) {
                       st.bind(i, std::string_view(std::endian::native == std::endian::big ? "big" : "little"));
                     }),
       written_as<T>("pixels",
                     [](sqlite::Statement& st, int i, const T& r) {
                       if (r.frame.storage == FrameStorage::Copy)
                         st.bind_bytes(i, r.frame.pixels);
                       else
                         st.bind_null(i);
                     }),
       // A copy's pixel BLOB must be exactly what the geometry needs (checked on its length, never read here).
       checked<T>("length(pixels)",
                  [](const sqlite::Statement& st, int i, T& r, const ImportLimits&) -> Check {
                    const Frame& f = r.frame;
                    const bool copy = f.storage == FrameStorage::Copy;
                    if (st.type(i) == SQLITE_NULL) {
                      if (copy) return flaw(C::MissingField, "a copied frame without pixels");
                      return std::nullopt;
                    }
                    const auto bytes = static_cast<std::size_t>(st.int64(i));
                    if (!copy) return flaw(C::InvalidValue, "a frame kept by reference holds pixels");
                    if (bytes != f.expected_bytes())
                      return flaw(C::InvalidValue, std::to_string(bytes) + " bytes of pixels, its " +
                                                       std::to_string(f.width) + "x" + std::to_string(f.height) +
                                                       " geometry needs " + std::to_string(f.expected_bytes()));
                    return std::nullopt;
                  })},
      [](const T& r, const ImportLimits& l) -> Check {
        const Frame& f = r.frame;
        const auto pixels = static_cast<std::size_t>(f.width) * static_cast<std::size_t>(f.height);
        if (pixels > l.max_frame_pixels)
          return flaw(C::TooLarge, std::to_string(f.width) + "x" + std::to_string(f.height) + " pixels (limit " +
                                       std::to_string(l.max_frame_pixels) + ")");
        if (f.channels == 2) return flaw(C::InvalidValue, "2 channels (1 or 3)");
        return std::nullopt;
      }};
  return t;
}

const Table<PipelineRun>& pipeline_runs_table() {
  using T = PipelineRun;
  const int side = ImportLimits{}.max_frame_side;
  static const Table<T> t{
      "pipeline_runs",
      "pipeline run",
      true,
      {"import_id"},
      {text<T>("platform", BS_FIELD(platform)), text<T>("device", BS_FIELD(device)),
       text<T>("backend", BS_FIELD(backend)), text<T>("demosaic", BS_FIELD(demosaic)),
       text<T>("detector", BS_FIELD(detector)), integer<T>("frame_width", BS_FIELD(frame_width), 0, side),
       integer<T>("frame_height", BS_FIELD(frame_height), 0, side),
       optional_real<T>("throughput_fps", BS_FIELD(throughput_fps), Bound::Positive),
       provenance<T>(BS_FIELD(provenance))},
      {}};
  return t;
}

const Table<StageStats>& pipeline_stages_table() {
  using T = StageStats;
  static const Table<T> t = [] {
    Table<T> s{"pipeline_stages", "pipeline stage", false, {"run_id"}, {text<T>("stage", BS_FIELD(stage))}, {}};
    add_stage_columns(s.columns, BS_SELF, Bound::NonNegative);
    s.rule = [](const T& st, const ImportLimits&) { return stage_rule(st); };
    return s;
  }();
  return t;
}

const Table<DnnRun>& dnn_runs_table() {
  using T = DnnRun;
  static const Table<T> t = [] {
    Table<T> s{"dnn_runs",
               "dnn run",
               true,
               {"import_id"},
               {text<T>("platform", BS_FIELD(platform)), text<T>("device", BS_FIELD(device)),
                text<T>("backend", BS_FIELD(backend)), text<T>("model", BS_FIELD(model)),
                text<T>("model_hash", BS_FIELD(model_hash)), text<T>("family", BS_FIELD(family)),
                flag<T>("architecture_only", BS_FIELD(architecture_only)),
                integer<T>("input_width", BS_FIELD(input_width), 1, ImportLimits{}.max_frame_side),
                integer<T>("input_height", BS_FIELD(input_height), 1, ImportLimits{}.max_frame_side),
                integer<T>("batch", BS_FIELD(batch), 1, 1 << 20), integer<T>("flops", BS_FIELD(flops), 0, kMaxFlops),
                integer<T>("opencv_flops", BS_FIELD(opencv_flops), 0, kMaxFlops)},
               {}};
    add_stage_columns(s.columns, BS_FIELD(forward), Bound::Positive);
    s.columns.push_back(optional_real<T>("device_peak_flops", BS_FIELD(device_peak_flops), Bound::Positive));
    s.columns.push_back(
        optional_real<T>("energy_per_inference_j", BS_FIELD(energy_per_inference_j), Bound::NonNegative));
    s.columns.push_back(optional_real<T>("mean_power_w", BS_FIELD(mean_power_w), Bound::NonNegative));
    s.columns.push_back(provenance<T>(BS_FIELD(provenance)));
    s.rule = [](const T& d, const ImportLimits&) { return stage_rule(d.forward); };
    return s;
  }();
  return t;
}

const Table<headroom::HeadroomMeasurement>& headroom_table() {
  using T = headroom::HeadroomMeasurement;
  using headroom::LatencyKind;
  // The platform column is the measurement's platform (rename_platform updates it alone); everything else is the
  // one JSON document, read through the same checks as any untrusted input (headroom/headroom_json.h).
  static const Table<T> t{
      "headroom_measurements",
      "headroom measurement",
      true,
      {"import_id"},
      {text<T>("platform", BS_FIELD(platform)),
       enumeration<T>("kind", BS_FIELD(kind),
                      std::vector<std::pair<LatencyKind, const char*>>{{LatencyKind::SystemWakeup, "wakeup"},
                                                                       {LatencyKind::ApplicationLoop, "loop"},
                                                                       {LatencyKind::MessageLatency, "message"}}),
       text<T>("tool", BS_FIELD(tool)),
       record_document<T, headroom::HeadroomJsonError>(
           [](const T& m) { return headroom::to_json(m); }, &headroom::measurement_from_json,
           [](const T& read, const T& m) {
             return read.kind != m.kind || read.tool != m.tool ? "kind/tool columns disagree with the document"
                                                               : nullptr;
           })},
      {}};
  return t;
}

const Table<SustainRun>& sustain_table() {
  using T = SustainRun;
  // Platform, label and load are columns (renaming a platform updates the column alone); the series are one JSON
  // document, read through the same checks as any untrusted input (sustain/sustain_json.h).
  static const Table<T> t{
      "sustain_runs",
      "sustained run",
      true,
      {"import_id"},
      {text<T>("platform", BS_FIELD(platform)), text<T>("label", BS_FIELD(label)), text<T>("load", BS_FIELD(load)),
       record_document<T, sustain::SustainJsonError>(&sustain::record_to_json, &sustain::record_from_json,
                                                     [](const T& read, const T& r) {
                                                       return read.label != r.label || read.load != r.load
                                                                  ? "label/load columns disagree with the document"
                                                                  : nullptr;
                                                     })},
      {}};
  return t;
}

}  // namespace bs::store
