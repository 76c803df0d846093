// SPDX-License-Identifier: GPL-3.0-or-later
#include "workspace/import_service.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <memory>
#include <type_traits>

#include "common/log_platform.h"
#include "mlperf/loose_files.h"
#include "mlperf/mlperf_submission.h"
#include "store/open_workspaces.h"
#include "store/record_kinds.h"
#include "store/workspace.h"
#include "workspace/registry.h"

namespace bs {
namespace fs = std::filesystem;

std::vector<ImportCandidate> expand_import_paths(const std::vector<std::string>& paths) {
  std::vector<ImportCandidate> files;
  for (const std::string& p : paths) {
    std::error_code ec;
    if (!fs::is_directory(p, ec)) {
      files.push_back({p, false});
      continue;
    }
    std::vector<std::string> found;
    for (auto it = fs::recursive_directory_iterator(p, fs::directory_options::skip_permission_denied, ec);
         !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
      const std::string name = it->path().filename().string();
      if (!name.empty() && name[0] == '.') {
        if (it->is_directory()) it.disable_recursion_pending();
        continue;
      }
      // A folder may hold the workspace being imported into (a lab's folder): it is no data, and reading it would
      // drop this process's locks on it (store/open_workspaces.h).
      if (it->is_regular_file() && !is_open_workspace(it->path().string())) found.push_back(it->path().string());
    }
    if (ec) throw ImportError(ImportErrorCategory::Io, {p, 0, 0, {}}, "cannot list folder: " + ec.message());
    std::sort(found.begin(), found.end());  // std::string's < compares bytes: no locale, no file-system order
    for (auto& f : found) files.push_back({std::move(f), true});
  }
  return files;
}

bool skippable_in_folder(const ImportError& e) {
  return e.category() == ImportErrorCategory::UnknownFormat || e.category() == ImportErrorCategory::Binary;
}

int ImportResult::count(FileOutcome::Kind kind) const {
  return static_cast<int>(
      std::count_if(files.begin(), files.end(), [&](const FileOutcome& f) { return f.kind == kind; }));
}

std::vector<std::string> per_computer_report(const ImportResult& result) {
  struct Tally {
    std::vector<std::string> took, passed;
  };
  std::vector<std::pair<std::string, Tally>> by;
  const auto tally = [&](const std::string& computer) -> Tally& {
    const std::string key = computer.empty() ? "computer not stated" : computer;
    for (auto& [k, t] : by)
      if (k == key) return t;
    by.emplace_back(key, Tally{});
    return by.back().second;
  };
  for (const FileOutcome& f : result.files) {
    const bool took = f.kind == FileOutcome::Kind::Imported || f.kind == FileOutcome::Kind::Duplicate;
    const std::string what = f.path + (took ? "" : " (" + f.reason + ")");
    // A companion belongs to the computer of the summary it was read with.
    std::vector<std::string> computers = f.computers;
    if (!f.read_with.empty())
      for (const FileOutcome& s : result.files)
        if (s.path == f.read_with) computers = s.computers;
    if (computers.empty()) (took ? tally("").took : tally("").passed).push_back(what);
    for (const std::string& c : computers) (took ? tally(c).took : tally(c).passed).push_back(what);
  }
  std::vector<std::string> out;
  for (const auto& [computer, t] : by) {
    std::string line = computer + ": took " + std::to_string(t.took.size());
    line += ", passed over " + std::to_string(t.passed.size());
    out.push_back(line);
    for (const std::string& p : t.passed) out.push_back("  passed over " + p);
  }
  return out;
}

std::string describe_batch(const ImportBatch& b) {
  // Each kind in its descriptor's words and order (store/record_kinds.h); a frame and a headroom measurement say what
  // each one is. "0 runs" only when the file held nothing that says more.
  const auto frame_words = [](const Frame& f) {
    return "frame " + std::to_string(f.width) + "x" + std::to_string(f.height) + " " +
           (f.pattern.empty() ? (f.channels == 3 ? "colour" : "grey") : f.pattern) + " " + std::to_string(f.bit_depth) +
           "-bit" + (f.synthetic ? " synthetic" : "") +
           (f.storage == FrameStorage::Copy ? " (copied)" : " (by reference)");
  };
  const auto headroom_words = [](const headroom::HeadroomMeasurement& m) {
    std::size_t threads = 0;
    for (const headroom::Phase& p : m.phases) threads = std::max(threads, p.threads.size());
    return "control-loop latency: " + std::string(headroom::to_string(m.kind)) + ", " + std::to_string(threads) +
           (threads == 1 ? " thread" : " threads");
  };
  std::vector<std::string> parts;
  for_each_record_kind([&](const auto& kind) {
    const auto& items = b.*kind.in_batch;
    if constexpr (std::is_same_v<std::remove_cvref_t<decltype(items)>, std::vector<Frame>>)
      for (const Frame& f : items) parts.push_back(frame_words(f));
    else if constexpr (std::is_same_v<std::remove_cvref_t<decltype(items)>, std::vector<headroom::HeadroomMeasurement>>)
      for (const auto& m : items) parts.push_back(headroom_words(m));
    else if (!items.empty())
      parts.push_back(std::to_string(items.size()) + " " + (items.size() == 1 ? kind.words.one : kind.words.many));
  });
  std::string s = parts.empty() ? "0 runs" : parts.front();
  for (std::size_t i = 1; i < parts.size(); ++i) s += ", " + parts[i];
  return s + " (" + b.format + ")";
}

namespace {

// The workspace, opened on first need, and the content hashes it already holds.
class Target {
 public:
  explicit Target(std::string path) : path_(std::move(path)) {}
  // Whether there is a workspace to ask yet: opening one creates the file, and an all-or-nothing import that fails
  // must leave no workspace behind when there was none.
  bool exists() const { return ws_ || std::filesystem::exists(path_); }
  Workspace& ws() {
    if (!ws_) {
      ws_ = std::make_unique<Workspace>(path_);
      for (ImportRecord& r : ws_->imports()) known_.emplace(r.content_hash, std::move(r));
    }
    return *ws_;
  }
  // The earlier import of these bytes, if any.
  const ImportRecord* earlier(const std::string& hash) {
    ws();
    const auto it = known_.find(hash);
    if (it == known_.end()) return nullptr;
    if (it->second.imported_at.empty())  // stored by this import: its record is read only when needed
      for (ImportRecord& r : ws_->imports())
        if (r.id == it->second.id) it->second = std::move(r);
    return &it->second;
  }
  void remember(const std::string& hash, std::int64_t id) {
    ImportRecord r;
    r.id = id;
    known_.emplace(hash, std::move(r));
  }

 private:
  std::string path_;
  std::unique_ptr<Workspace> ws_;
  std::map<std::string, ImportRecord> known_;
};

void mark_duplicate(FileOutcome& o, const std::string& earlier_path, const std::string& earlier_at) {
  o.kind = FileOutcome::Kind::Duplicate;
  o.earlier_path = earlier_path;
  o.earlier_imported_at = earlier_at;
  o.reason = earlier_at.empty() ? "same content as " + earlier_path + " earlier in this import"
                                : "already imported on " + earlier_at + " as " + earlier_path;
}

// Parses one file into `o`; returns the batch when the file holds data, nullopt when it was skipped or failed.
std::optional<ImportBatch> parse_one(const ImportCandidate& file, const ImportOptions& options,
                                     const CancelToken& cancel, FileOutcome& o) {
  try {
    ImportBatch batch =
        import_file_with_raw_geometry(file.path, options.raw_geometry, cancel, options.raw_geometry_source);
    for (Frame& f : batch.frames) f.storage = options.frames;
    o.warnings = batch.warnings;
    o.summary = describe_batch(batch);
    o.content_hash = file_content_hash(file.path);
    o.kind = FileOutcome::Kind::Imported;
    return batch;
  } catch (const ImportError& e) {
    const bool not_data = file.from_folder && skippable_in_folder(e);
    o.kind = not_data ? FileOutcome::Kind::NotData : FileOutcome::Kind::Failed;
    o.reason = not_data ? e.reason() : std::string(e.what());
  } catch (const Cancelled&) {
    throw;
  } catch (const std::exception& e) {  // the file vanished or became unreadable between parsing and hashing
    o.kind = FileOutcome::Kind::Failed;
    o.reason = e.what();
  }
  return std::nullopt;
}

// The platforms a workspace knows: its devices', power logs' and pipeline runs'.
std::vector<std::string> workspace_platforms(const Workspace& ws) {
  std::vector<std::string> out;
  const auto add = [&out](const std::string& p) {
    if (!blank_platform(p) && std::find(out.begin(), out.end(), p) == out.end()) out.push_back(p);
  };
  for (const DeviceRecord& d : ws.devices()) add(d.platform);
  for (const StoredPowerTrace& t : ws.power_trace_summaries()) add(t.trace.platform);
  for (const StoredPipelineRun& p : ws.pipeline_runs()) add(p.run.platform);
  for (const StoredHeadroom& h : ws.headroom_measurements()) add(h.measurement.platform);
  return out;
}

// The platform of one log or result whose file names none: --platform, else the chooser's answer (the GUI's
// question, shown `shown`'s label), else the guess; says which in the summary. Never blank. A log is attached only
// by what its file says or what the user chooses: the workspace's only platform is a guess the GUI offers, never
// taken silently (an MLPerf spl.txt is AC wall power of some other system).
std::string settle_platform(const LogPlatformGuess& guess, const PowerTrace& shown, const std::string& path,
                            const std::vector<std::string>& known, const ImportOptions& options, FileOutcome& o) {
  std::string chosen = options.log_platform;
  std::string how = "given with --platform";
  if (blank_platform(chosen) && options.choose_log_platform) {
    chosen = options.choose_log_platform(shown, path, guess.platform, known);
    how = "chosen at import";
  }
  if (blank_platform(chosen)) {
    chosen = guess.platform;
    how = guess.how;
    if (guess.how == "the workspace's only platform") {
      chosen = "unassigned: " + (shown.label.empty() ? std::string("power log") : shown.label);
      how = "not attached: the file names no platform; the workspace's only platform '" + guess.platform +
            "' is a guess (give --platform to attach it)";
    }
  }
  o.summary += ", platform '" + chosen + "' (" + how + ")";
  return chosen;
}

// Gives every power log and latency result of `batch` whose file names no platform one (never blank).
void attach_log_platforms(ImportBatch& batch, const std::string& path, const std::vector<std::string>& known,
                          const ImportOptions& options, FileOutcome& o) {
  for (PowerTrace& t : batch.power_traces)
    if (blank_platform(t.platform))
      t.platform = settle_platform(infer_log_platform(t, known), t, path, known, options, o);
  // A log's clocks and temperatures (#53) belong to the computer of its power, settled just above: never asked twice.
  for (SustainRun& r : batch.sustain_runs)
    if (blank_platform(r.platform))
      for (const PowerTrace& t : batch.power_traces)
        if (t.label == r.label && t.provenance.source_file == r.provenance.source_file) r.platform = t.platform;
  // A latency file (cyclictest, rttest, performance_test) rarely names its machine: asked like a power log, the
  // question naming the result as it names a log.
  for (headroom::HeadroomMeasurement& m : batch.headroom) {
    if (!blank_platform(m.platform)) continue;
    PowerTrace shown;
    shown.label = m.tool + " result " + std::filesystem::path(path).filename().string();
    shown.provenance = m.provenance;
    m.platform = settle_platform(infer_platform(m.provenance, shown.label, known), shown, path, known, options, o);
  }
  // An MLPerf result without a system description names no computer: --platform names it.
  for (ResultSet& r : batch.result_sets)
    if (r.platform.starts_with("computer not stated") && !blank_platform(options.log_platform)) {
      r.platform = options.log_platform;
      o.summary += ", computer '" + r.platform + "' (given with --platform)";
    }
}

// The computers a parsed batch belongs to.
std::vector<std::string> computers_of(const ImportBatch& b) {
  std::vector<std::string> out;
  const auto add = [&](const std::string& p) {
    if (std::find(out.begin(), out.end(), p) == out.end()) out.push_back(p);
  };
  for (const ResultSet& r : b.result_sets) add(r.platform);
  for (const PowerTrace& t : b.power_traces) add(t.platform);
  for (const FlopsRun& r : b.runs) add(r.platform);
  return out;
}

// The system a results tree files a path under (".../results/<system>/..."), "" outside one.
std::string tree_system(const std::string& path) {
  const std::size_t at = path.find("/results/");
  if (at == std::string::npos) return {};
  const std::size_t from = at + 9, to = path.find('/', from);
  return to == std::string::npos ? std::string() : path.substr(from, to - from);
}

// Companion files of the LoadGen summaries among `files` (detail logs, spl.txt, system and measurements JSONs):
// read with their summary, so an import does not take them again on their own (a spl.txt would become a platform of
// its own) -> the summary's path. A lab names summaries as it likes ("..._summary.txt"): the banner says what it is.
std::map<std::string, std::string> summary_companions(const std::vector<ImportCandidate>& files) {
  std::map<std::string, std::string> out;
  for (const ImportCandidate& f : files) {
    if (!mlperf_loose::run_prefix(fs::path(f.path).filename().string())) continue;
    std::string head;
    try {
      head = read_head(f.path, 4096);
    } catch (const ImportError&) {
      continue;
    }
    if (head.find("MLPerf Results Summary") == std::string::npos) continue;
    for (const std::string& c : mlperf_companion_paths(f.path)) out.emplace(c, f.path);
  }
  return out;
}

// "system description" / "measurements description" for an MLPerf JSON that describes a result but holds none.
std::string mlperf_description(const std::string& path) {
  if (!path.ends_with(".json")) return {};
  try {
    return mlperf_loose::description_kind(read_head(path, 64 * 1024));
  } catch (const ImportError&) {
    return {};  // unreadable: the import of the file says why
  }
}

}  // namespace

ImportResult import_paths(const std::string& workspace_path, const std::vector<std::string>& paths,
                          const ImportOptions& options, const CancelToken& cancel) {
  ImportResult result;
  const std::vector<ImportCandidate> files = expand_import_paths(paths);
  const int total = static_cast<int>(files.size());
  result.files.resize(files.size());
  for (std::size_t i = 0; i < files.size(); ++i) result.files[i].path = files[i].path;
  const bool each_file = options.atomicity == ImportAtomicity::EachFile;
  Target target(workspace_path);
  const std::map<std::string, std::string> companions = summary_companions(files);
  std::map<std::string, std::string> seen;                   // hash -> path, for twins within this import
  std::vector<std::pair<std::size_t, ImportBatch>> pending;  // AllOrNothing: parsed, not yet stored
  bool failed = false;

  for (std::size_t i = 0; i < files.size(); ++i) {
    if (options.progress) options.progress(static_cast<int>(i), total, files[i].path);
    FileOutcome& o = result.files[i];
    if (cancel.cancelled()) {
      result.cancelled = true;
      break;
    }
    // Named on the command line or found in a folder alike: a companion of a summary in this import is read with it.
    if (const auto c = companions.find(files[i].path); c != companions.end()) {
      o.kind = FileOutcome::Kind::NotData;
      o.reason = "read with its LoadGen summary " + c->second + ", not on its own";
      o.read_with = c->second;
      continue;
    }
    if (const std::string kind = mlperf_description(files[i].path); !kind.empty()) {
      o.kind = FileOutcome::Kind::NotData;
      o.reason = "an MLPerf " + kind +
                 ": it holds no result and is read with the LoadGen summary it belongs to, and no summary in this "
                 "import pairs with it (name each run's files with one prefix, or import the folder)";
      o.computers = {tree_system(files[i].path)};
      continue;
    }
    try {
      std::optional<ImportBatch> batch = parse_one(files[i], options, cancel, o);
      if (!batch) {
        failed = failed || o.kind == FileOutcome::Kind::Failed;
        o.computers = {tree_system(files[i].path)};
        continue;
      }
      if (const auto twin = seen.find(o.content_hash); twin != seen.end() && !each_file) {
        mark_duplicate(o, twin->second, {});
        continue;
      }
      if ((!batch->power_traces.empty() || !batch->headroom.empty()) &&
          (!target.exists() || !target.earlier(o.content_hash))) {
        std::vector<std::string> known;
        if (target.exists()) known = workspace_platforms(target.ws());
        for (const auto& [k, b] : pending)  // logs earlier in this import, not stored yet
          for (const PowerTrace& t : b.power_traces)
            if (std::find(known.begin(), known.end(), t.platform) == known.end()) known.push_back(t.platform);
        for (const auto& [k, b] : pending)
          for (const headroom::HeadroomMeasurement& m : b.headroom)
            if (std::find(known.begin(), known.end(), m.platform) == known.end()) known.push_back(m.platform);
        attach_log_platforms(*batch, o.path, known, options, o);
      } else if (!batch->result_sets.empty()) {
        attach_log_platforms(*batch, o.path, {}, options, o);
      }
      o.computers = computers_of(*batch);
      if (!each_file) {
        seen.emplace(o.content_hash, o.path);
        pending.emplace_back(i, std::move(*batch));
        continue;
      }
      if (const ImportRecord* r = target.earlier(o.content_hash)) {
        mark_duplicate(o, r->path, r->imported_at);
        continue;
      }
      o.import_id = target.ws().add_import(*batch, o.content_hash, &cancel);
      target.remember(o.content_hash, o.import_id);
      result.committed = true;
    } catch (const Cancelled&) {
      o.kind = FileOutcome::Kind::NotReached;
      result.cancelled = true;
      break;
    } catch (const WorkspaceError& e) {
      if (e.kind() != WorkspaceError::Kind::Constraint) throw;
      o.kind = FileOutcome::Kind::Failed;  // e.g. a copied frame whose pixels do not fit its geometry
      o.reason = o.path + ": " + e.what();
      failed = true;
    }
  }
  if (each_file) {
    if (options.progress) options.progress(total, total, {});
    return result;
  }

  // AllOrNothing: store only when every file parsed and nobody cancelled, then in one transaction.
  const auto abandon = [&] {
    for (auto& [i, batch] : pending) result.files[i].kind = FileOutcome::Kind::NotReached;
  };
  if (failed || result.cancelled || pending.empty()) {
    abandon();
    if (options.progress) options.progress(total, total, {});
    return result;
  }
  std::vector<Workspace::HashedBatch> to_store;
  std::vector<std::size_t> stored_index;
  for (auto& [i, batch] : pending) {
    FileOutcome& o = result.files[i];
    if (const ImportRecord* r = target.earlier(o.content_hash)) {
      mark_duplicate(o, r->path, r->imported_at);
      continue;
    }
    to_store.push_back({&batch, o.content_hash});
    stored_index.push_back(i);
  }
  try {
    if (!to_store.empty()) {
      const std::vector<std::int64_t> ids = target.ws().add_imports(to_store, &cancel);
      for (std::size_t k = 0; k < ids.size(); ++k) result.files[stored_index[k]].import_id = ids[k];
      result.committed = true;
    }
  } catch (const Cancelled&) {
    for (std::size_t i : stored_index) result.files[i].kind = FileOutcome::Kind::NotReached;
    result.cancelled = true;
  }
  if (options.progress) options.progress(total, total, {});
  return result;
}

}  // namespace bs
