// SPDX-License-Identifier: GPL-3.0-or-later
// Reading a workspace back: every row through its table description (store/tables.h), so every value meets the
// import rules. A row that breaks them makes its item (a run with its samples, a result set with its
// measurements, a power trace with its channels, phases and sample chunks, a frame, a pipeline or dnn run, a
// device with what ran on it) damaged: recorded once, named, and left out of every read.
#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "store/power_samples.h"
#include "store/record_kinds.h"
#include "store/tables.h"
#include "store/workspace_impl.h"

namespace bs {

using sqlite::Statement;
using store::Flaw;
using store::Row;

namespace {

std::string where(const Flaw& f) { return f.column.empty() ? f.reason : f.column + ": " + f.reason; }

std::string labelled(const std::string& s) { return s.empty() ? std::string() : " '" + s + "'"; }

std::string import_item(std::int64_t id, const ImportRecord& i) {
  return "import #" + std::to_string(id) + labelled(i.path);
}
std::string device_item(std::int64_t id, const DeviceRecord& d) {
  return "device #" + std::to_string(id) + " (" + d.platform + " / " + d.device + ")";
}
std::string run_item(std::int64_t id, const FlopsRun& r) {
  return "run #" + std::to_string(id) + " (" + r.platform + " / " + r.device + ", " + r.backend + " " + r.kernel + ")";
}
std::string set_item(std::int64_t id, const ResultSet& s) {
  return "result set #" + std::to_string(id) + " (" + s.platform + " / " + s.device + ", " + s.source_format + ")";
}
std::string trace_item(std::int64_t id, const PowerTrace& t) {
  return "power trace #" + std::to_string(id) + labelled(t.label) + (t.platform.empty() ? "" : " (" + t.platform + ")");
}
std::string pipeline_item(std::int64_t id, const PipelineRun& p) {
  return "pipeline run #" + std::to_string(id) + " (" + p.platform + ", " + p.backend + ")";
}
std::string dnn_item(std::int64_t id, const DnnRun& d) {
  return "dnn run #" + std::to_string(id) + " (" + d.platform + ", " + d.model + ")";
}
std::string headroom_item(std::int64_t id, const headroom::HeadroomMeasurement& m) {
  return "headroom measurement #" + std::to_string(id) + " (" + m.platform + ", " + m.tool + ")";
}
std::string sustain_item(std::int64_t id, const SustainRun& r) {
  return "sustained run #" + std::to_string(id) + " (" + r.platform + ", " + r.label + ")";
}

// The rows of a table whose rows are records by themselves (imports, devices) in `order`, each with its id; a row
// that breaks the import rules is recorded as damaged (named by `item`) and left out.
template <class Record>
std::vector<Record> read_records(const Workspace::Impl& w, const store::Table<Record>& table, const char* order,
                                 std::string (*item)(std::int64_t, const Record&)) {
  std::vector<Record> out;
  store::read_rows(w.conn(), table, w.limits, order, [&](Row<Record>&& r) {
    r.value.id = r.id;
    if (r.flaw)
      w.record({item(r.id, r.value), table.name, r.id, r.flaw->category, where(*r.flaw)});
    else
      out.push_back(std::move(r.value));
  });
  return out;
}

// The rows of a record kind an import brought (pipeline, inference and sustained runs, headroom measurements) in
// `order`, each as its Stored row; a row that breaks the import rules is recorded as damaged (named by `item`) and
// left out.
template <class Stored, class Item>
std::vector<Stored> read_import_rows(const Workspace::Impl& w, const store::Table<Item>& table, const char* order,
                                     std::string (*item)(std::int64_t, const Item&)) {
  std::vector<Stored> out;
  store::read_rows(w.conn(), table, w.limits, order, [&](Row<Item>&& r) {
    if (r.flaw) return w.record({item(r.id, r.value), table.name, r.id, r.flaw->category, where(*r.flaw)});
    // Each base in its own braces: clang's -Wmissing-braces (the sanitizer build, -Werror) refuses the flat form.
    out.push_back({{r.id, r.keys[0]}, std::move(r.value)});
  });
  return out;
}

}  // namespace

std::string describe(const WorkspaceDamage& d) {
  return d.item + ": " + d.reason + " [" + std::string(to_string(d.category)) + "]";
}

void Workspace::Impl::record(WorkspaceDamage d) const {
  // One entry per item, its first flaw: a run whose 64 timings are all negated is one damaged run, and a read
  // repeated (opening, then a view's read) does not list it again.
  if (damaged_rows.insert({d.table, d.id}).second) damage.push_back(std::move(d));
}

void Workspace::Impl::scan(const Workspace& ws) {
  (void)ws.imports();
  // Every kind as its listing reads it (runs read their devices too; a power log's summary: its samples are checked
  // when they load).
  for_each_record_kind([&](const auto& kind) { (void)(ws.*kind.list)(); });
}

std::vector<ImportRecord> Workspace::imports() const {
  return read_records(*impl_, store::imports_table(), "ORDER BY id", import_item);
}

std::vector<DeviceRecord> Workspace::devices() const {
  return read_records(*impl_, store::devices_table(), "ORDER BY color_index, id", device_item);
}

namespace {

// The sound devices by id, for the runs and result sets that name them.
std::map<std::int64_t, DeviceRecord> device_map(const Workspace& ws) {
  std::map<std::int64_t, DeviceRecord> m;
  for (DeviceRecord& d : ws.devices()) m.emplace(d.id, std::move(d));
  return m;
}

// Fills an item's device fields from its device_id; false (and the item recorded as damaged) when the device does
// not exist. A device that exists but is damaged leaves its items out without a second report.
template <class Item>
bool attach_device(const Workspace::Impl& w, const std::map<std::int64_t, DeviceRecord>& devices,
                   std::int64_t device_id, Item& item, const std::string& table, std::int64_t id,
                   const std::string& noun) {
  const auto it = devices.find(device_id);
  if (it == devices.end()) {
    if (!w.is_damaged("devices", device_id))
      w.record({noun + " #" + std::to_string(id), table, id, ImportErrorCategory::MissingField,
                table + ".device_id: device #" + std::to_string(device_id) + " does not exist"});
    return false;
  }
  item.platform = it->second.platform;
  item.device = it->second.device;
  item.device_kind = it->second.kind;
  return true;
}

// The rows of `table` that belong to the items read before it (a run's samples, a set's measurements, a trace's
// channels and phases, a pipeline run's stages): `each(k, row)` for a row whose item is at place k of the result
// (`index`: item id -> place). The rows of a damaged item, or of none (an orphan, which check names), are passed
// over.
template <class Child, class Each>
void read_child_rows(const Workspace::Impl& w, const store::Table<Child>& table, const char* order,
                     const std::map<std::int64_t, std::size_t>& index, Each each) {
  store::read_rows(w.conn(), table, w.limits, order, [&](Row<Child>&& r) {
    if (const auto it = index.find(r.keys[0]); it != index.end()) each(it->second, std::move(r));
  });
}

// The rows of a kind measured on a device (runs, result sets) in id order, each with its device's fields and colour;
// `index` gets each kept row's place, for the rows that belong to it (samples, measurements), read after. A row whose
// device is missing or that breaks the import rules is recorded as damaged (named by `item`) and left out.
template <class Stored, class Item>
std::vector<Stored> read_device_rows(const Workspace::Impl& w, const std::map<std::int64_t, DeviceRecord>& devices,
                                     const store::Table<Item>& table, std::string (*item)(std::int64_t, const Item&),
                                     std::map<std::int64_t, std::size_t>& index) {
  std::vector<Stored> out;
  store::read_rows(w.conn(), table, w.limits, "ORDER BY id", [&](Row<Item>&& r) {
    if (!attach_device(w, devices, r.keys[1], r.value, table.name, r.id, table.noun)) return;
    if (r.flaw) return w.record({item(r.id, r.value), table.name, r.id, r.flaw->category, where(*r.flaw)});
    if (w.is_damaged(table.name, r.id)) return;
    index[r.id] = out.size();
    out.push_back({{{r.id, r.keys[0]}, r.keys[1], devices.at(r.keys[1]).color_index}, std::move(r.value)});
  });
  return out;
}

}  // namespace

std::vector<StoredRun> Workspace::runs() const {
  const Impl& w = *impl_;
  std::map<std::int64_t, std::size_t> index;
  std::vector<StoredRun> out = read_device_rows<StoredRun>(w, device_map(*this), store::runs_table(), run_item, index);
  const auto damaged = [&](std::size_t k, const Flaw& f) {
    w.record({run_item(out[k].id, out[k].run), "runs", out[k].id, f.category, where(f)});
  };
  // Timings kept per run so far: counted as they come (summing the run's lists for every row was quadratic in its
  // worker counts, and most of a CLI command's time under ASan).
  std::vector<std::size_t> timings(out.size(), 0);
  read_child_rows(
      w, store::run_samples_table(), "ORDER BY run_id, workers, repetition", index,
      [&](std::size_t k, Row<store::RunSampleRow>&& r) {
        if (r.flaw) return damaged(k, *r.flaw);
        auto& list = out[k].run.samples;
        if (timings[k]++ >= w.limits.max_samples)
          return damaged(k, store::flaw(ImportErrorCategory::TooLarge,
                                        "run_samples: more than " + std::to_string(w.limits.max_samples) + " timings"));
        if (list.empty() || list.back().workers != r.value.workers) list.push_back({r.value.workers, {}});
        list.back().seconds.push_back(r.value.seconds);
      });
  std::erase_if(out, [&](const StoredRun& s) { return w.is_damaged("runs", s.id); });
  // Ordered as the views list them: by device colour, backend, dims, then id (bytewise, like SQLite's BINARY).
  std::stable_sort(out.begin(), out.end(), [](const StoredRun& a, const StoredRun& b) {
    return std::tie(a.color_index, a.run.backend, a.run.dims, a.id) <
           std::tie(b.color_index, b.run.backend, b.run.dims, b.id);
  });
  return out;
}

std::vector<StoredResultSet> Workspace::result_sets() const {
  const Impl& w = *impl_;
  std::map<std::int64_t, std::size_t> index;
  std::vector<StoredResultSet> out =
      read_device_rows<StoredResultSet>(w, device_map(*this), store::result_sets_table(), set_item, index);
  read_child_rows(
      w, store::measurements_table(), "ORDER BY result_set_id, id", index, [&](std::size_t k, Row<Measurement>&& r) {
        StoredResultSet& s = out[k];
        if (r.flaw)
          return w.record({set_item(s.id, s.set), "result_sets", s.id, r.flaw->category,
                           "measurement #" + std::to_string(r.id) + labelled(r.value.name) + ": " + where(*r.flaw)});
        s.set.measurements.push_back(std::move(r.value));
      });
  std::erase_if(out, [&](const StoredResultSet& s) { return w.is_damaged("result_sets", s.id); });
  std::stable_sort(out.begin(), out.end(), [](const StoredResultSet& a, const StoredResultSet& b) {
    return std::tie(a.color_index, a.id) < std::tie(b.color_index, b.id);
  });
  return out;
}

namespace {

// The stored chunks of each series of a trace (time and every channel) must follow each other from 0 and add up
// to the summary's sample count: checked on their lengths alone, before any sample is read or allocated.
std::optional<Flaw> chunk_flaw(const sqlite::Db& db, std::int64_t trace_id, std::size_t samples,
                               const std::vector<std::int64_t>& channel_ids) {
  std::map<std::int64_t, std::size_t> next;  // series -> samples so far
  next[0] = 0;
  for (const std::int64_t c : channel_ids) next[c] = 0;
  Statement st(db,
               "SELECT series, first, length(vals), typeof(vals) FROM power_chunks WHERE trace_id = ? "
               "ORDER BY series, first");
  st.bind(1, trace_id);
  const auto bad = [](std::int64_t series, const std::string& why) {
    return store::flaw(ImportErrorCategory::InvalidValue,
                       "power_chunks: series " + std::to_string(series) + (series == 0 ? " (time)" : "") + ": " + why);
  };
  while (st.step()) {
    const std::int64_t series = st.int64(0);
    const auto it = next.find(series);
    if (it == next.end()) return bad(series, "belongs to no channel of this trace");
    const std::int64_t first = st.int64(1);
    const std::int64_t bytes = st.int64(2);
    if (st.text(3) != "blob") return bad(series, "a chunk is not a BLOB");
    if (first < 0 || static_cast<std::size_t>(first) != it->second)
      return bad(series, "sample chunks do not follow each other (chunk at " + std::to_string(first) + ", expected " +
                             std::to_string(it->second) + ")");
    if (bytes % static_cast<std::int64_t>(sizeof(double)) != 0)
      return bad(series, "a chunk of " + std::to_string(bytes) + " bytes is not whole samples");
    it->second += static_cast<std::size_t>(bytes) / sizeof(double);
    if (it->second > samples)
      return bad(series, "holds more than the " + std::to_string(samples) + " samples its summary says");
  }
  for (const auto& [series, n] : next)
    if (n != samples)
      return bad(series, "holds " + std::to_string(n) + " samples, its summary says " + std::to_string(samples));
  return std::nullopt;
}

}  // namespace

std::vector<StoredPowerTrace> Workspace::power_trace_summaries() const {
  const Impl& w = *impl_;
  std::vector<StoredPowerTrace> out;
  std::map<std::int64_t, std::size_t> index;
  std::map<std::int64_t, std::vector<std::int64_t>> channel_ids;
  const auto damaged = [&](std::size_t k, const std::string& why, ImportErrorCategory c) {
    w.record({trace_item(out[k].id, out[k].trace), "power_traces", out[k].id, c, why});
  };
  store::read_rows(w.conn(), store::power_traces_table(), w.limits, "ORDER BY id", [&](Row<StoredPowerTrace>&& r) {
    r.value.id = r.id;
    r.value.import_id = r.keys[0];
    r.value.samples_loaded = false;
    if (r.flaw)
      return w.record({trace_item(r.id, r.value.trace), "power_traces", r.id, r.flaw->category, where(*r.flaw)});
    if (w.limits.max_power_rows < r.value.summary.samples)
      return w.record({trace_item(r.id, r.value.trace), "power_traces", r.id, ImportErrorCategory::TooLarge,
                       "power_traces.samples: " + std::to_string(r.value.summary.samples) + " (limit " +
                           std::to_string(w.limits.max_power_rows) + ")"});
    index[r.id] = out.size();
    out.push_back(std::move(r.value));
  });
  read_child_rows(
      w, store::power_channels_table(), "ORDER BY trace_id, id", index, [&](std::size_t k, Row<ChannelSummary>&& r) {
        StoredPowerTrace& s = out[k];
        if (r.flaw)
          return damaged(k, "channel #" + std::to_string(r.id) + labelled(r.value.name) + ": " + where(*r.flaw),
                         r.flaw->category);
        if (r.value.stats.summary.n > s.summary.samples)
          return damaged(k,
                         "channel" + labelled(r.value.name) + ": its summary counts " +
                             std::to_string(r.value.stats.summary.n) + " samples of " +
                             std::to_string(s.summary.samples),
                         ImportErrorCategory::InvalidValue);
        channel_ids[s.id].push_back(r.id);
        s.trace.channels.push_back({r.value.name, r.value.quantity, {}});
        s.summary.channels.push_back(std::move(r.value));
      });
  read_child_rows(w, store::power_phases_table(), "ORDER BY trace_id, start_s, id", index,
                  [&](std::size_t k, Row<TracePhase>&& r) {
                    if (r.flaw)
                      return damaged(k, "phase #" + std::to_string(r.id) + ": " + where(*r.flaw), r.flaw->category);
                    out[k].trace.phases.push_back(std::move(r.value));
                  });
  for (std::size_t k = 0; k < out.size(); ++k) {
    if (w.is_damaged("power_traces", out[k].id)) continue;
    if (const auto f = chunk_flaw(w.conn(), out[k].id, out[k].summary.samples, channel_ids[out[k].id]))
      damaged(k, f->reason, f->category);
  }
  std::erase_if(out, [&](const StoredPowerTrace& s) { return w.is_damaged("power_traces", s.id); });
  return out;
}

void Workspace::load_power_samples(StoredPowerTrace& t, const CancelToken* cancel) const {
  if (t.samples_loaded) return;
  const Impl& w = *impl_;
  std::vector<std::int64_t> channel_ids;
  Statement ch(w.conn(), "SELECT id FROM power_channels WHERE trace_id = ? ORDER BY id");
  ch.bind(1, t.id);
  while (ch.step()) channel_ids.push_back(ch.int64(0));
  if (channel_ids.size() != t.trace.channels.size())
    throw WorkspaceError(WorkspaceError::Kind::Corrupt,
                         w.path + ": power trace " + std::to_string(t.id) + " changed while it was being read");
  const std::size_t n = t.summary.samples;
  if (n > w.limits.max_power_rows)
    throw WorkspaceError(WorkspaceError::Kind::Corrupt, w.path + ": " + trace_item(t.id, t.trace) + ": " +
                                                            std::to_string(n) + " samples is beyond the import limit");
  store::SampleProgress progress{cancel, "loading samples", 0, n * (1 + channel_ids.size())};
  std::vector<double> time_s = store::read_series(w.conn(), t.id, 0, n, progress);
  // The importers' rules for samples: times finite and non-decreasing; a value NaN (missing) but never infinite.
  const auto bad = [&](const std::string& what, std::size_t k, double v) {
    throw WorkspaceError(WorkspaceError::Kind::Corrupt, w.path + ": " + trace_item(t.id, t.trace) + ": " + what +
                                                            " sample " + std::to_string(k) + " is " +
                                                            store::number_text(v) + " [invalid-value]");
  };
  for (std::size_t k = 0; k < n; ++k)
    if (!std::isfinite(time_s[k]) || (k > 0 && time_s[k] < time_s[k - 1])) bad("time", k, time_s[k]);
  std::vector<std::vector<double>> values(channel_ids.size());
  for (std::size_t c = 0; c < channel_ids.size(); ++c) {
    values[c] = store::read_series(w.conn(), t.id, channel_ids[c], n, progress);
    for (std::size_t k = 0; k < n; ++k)
      if (std::isinf(values[c][k])) bad("channel '" + t.trace.channels[c].name + "'", k, values[c][k]);
  }
  t.trace.time_s = std::move(time_s);
  for (std::size_t c = 0; c < channel_ids.size(); ++c) t.trace.channels[c].values = std::move(values[c]);
  t.samples_loaded = true;
}

std::vector<StoredPowerTrace> Workspace::power_traces() const {
  const Impl& w = *impl_;
  std::vector<StoredPowerTrace> out = power_trace_summaries();
  for (StoredPowerTrace& t : out) {
    try {
      load_power_samples(t);
    } catch (const WorkspaceError& e) {
      if (e.kind() != WorkspaceError::Kind::Corrupt) throw;
      std::string why = e.what();
      if (why.rfind(w.path + ": ", 0) == 0) why.erase(0, w.path.size() + 2);
      w.record({trace_item(t.id, t.trace), "power_traces", t.id, ImportErrorCategory::InvalidValue, why});
    }
  }
  std::erase_if(out, [&](const StoredPowerTrace& s) { return w.is_damaged("power_traces", s.id); });
  return out;
}

std::vector<StoredFrame> Workspace::frames() const {
  const Impl& w = *impl_;
  std::vector<StoredFrame> out;
  store::read_rows(w.conn(), store::frames_table(), w.limits, "ORDER BY id", [&](Row<StoredFrame>&& r) {
    StoredFrame& s = r.value;
    s.id = r.id;
    s.import_id = r.keys[0];
    if (r.flaw)
      return w.record({"frame #" + std::to_string(r.id) + labelled(s.frame.label), "frames", r.id, r.flaw->category,
                       where(*r.flaw)});
    out.push_back(std::move(s));
  });
  return out;
}

std::vector<std::uint8_t> Workspace::frame_pixels(std::int64_t frame_id) const {
  const Impl& w = *impl_;
  if (w.is_damaged("frames", frame_id))
    throw WorkspaceError(WorkspaceError::Kind::Corrupt,
                         w.path + ": frame #" + std::to_string(frame_id) + " is damaged and left out");
  // The geometry is read (and bounded) through the frame's description before its BLOB is copied.
  std::optional<StoredFrame> geometry;
  store::read_rows(
      w.conn(), store::frames_table(), w.limits, "WHERE id = ?",
      [&](Row<StoredFrame>&& r) {
        if (r.flaw)
          throw WorkspaceError(WorkspaceError::Kind::Corrupt,
                               w.path + ": frame #" + std::to_string(frame_id) + ": " + where(*r.flaw));
        geometry = std::move(r.value);
      },
      [&](Statement& st) { st.bind(1, frame_id); });
  if (!geometry)
    throw WorkspaceError(WorkspaceError::Kind::Constraint, w.path + ": no frame with id " + std::to_string(frame_id));
  Statement st(w.conn(), "SELECT byte_order, pixels FROM frames WHERE id = ?");
  st.bind(1, frame_id);
  if (!st.step()) throw WorkspaceError(WorkspaceError::Kind::Constraint, w.path + ": frame changed while read");
  const bool big = st.text(0) == "big";
  std::vector<std::uint8_t> pixels = st.bytes(1);
  if (pixels.empty()) return pixels;  // kept by reference
  const Frame& f = geometry->frame;
  if (pixels.size() != f.expected_bytes())
    throw WorkspaceError(WorkspaceError::Kind::Corrupt,
                         w.path + ": frame " + std::to_string(frame_id) + " has " + std::to_string(pixels.size()) +
                             " bytes of pixels, its geometry needs " + std::to_string(f.expected_bytes()));
  // A workspace written on a machine of the other byte order stays readable.
  if (f.bit_depth > 8 && big != (std::endian::native == std::endian::big))
    for (std::size_t i = 0; i + 1 < pixels.size(); i += 2) std::swap(pixels[i], pixels[i + 1]);
  return pixels;
}

std::vector<StoredPipelineRun> Workspace::pipeline_runs() const {
  const Impl& w = *impl_;
  std::vector<StoredPipelineRun> out =
      read_import_rows<StoredPipelineRun>(w, store::pipeline_runs_table(), "ORDER BY platform, id", pipeline_item);
  std::map<std::int64_t, std::size_t> index;
  for (std::size_t k = 0; k < out.size(); ++k) index[out[k].id] = k;
  // Stages in pipeline order (preprocess, detect, end-to-end, then any other), not alphabetically.
  read_child_rows(w, store::pipeline_stages_table(),
                  "ORDER BY run_id, CASE stage WHEN 'preprocess' THEN 0 WHEN 'detect' THEN 1 "
                  "WHEN 'end-to-end' THEN 2 ELSE 3 END, stage",
                  index, [&](std::size_t k, Row<StageStats>&& r) {
                    StoredPipelineRun& p = out[k];
                    if (r.flaw)
                      return w.record({pipeline_item(p.id, p.run), "pipeline_runs", p.id, r.flaw->category,
                                       "stage" + labelled(r.value.stage) + ": " + where(*r.flaw)});
                    p.run.stages.push_back(std::move(r.value));
                  });
  std::erase_if(out, [&](const StoredPipelineRun& s) { return w.is_damaged("pipeline_runs", s.id); });
  return out;
}

std::vector<StoredDnnRun> Workspace::dnn_runs() const {
  std::vector<StoredDnnRun> out = read_import_rows<StoredDnnRun>(
      *impl_, store::dnn_runs_table(), "ORDER BY platform, model, input_width, input_height, backend, id", dnn_item);
  for (StoredDnnRun& d : out) d.run.forward.stage = "inference";
  return out;
}

std::vector<StoredHeadroom> Workspace::headroom_measurements() const {
  return read_import_rows<StoredHeadroom>(*impl_, store::headroom_table(), "ORDER BY platform, id", headroom_item);
}

std::vector<StoredSustainRun> Workspace::sustain_runs() const {
  return read_import_rows<StoredSustainRun>(*impl_, store::sustain_table(), "ORDER BY platform, id", sustain_item);
}

}  // namespace bs
