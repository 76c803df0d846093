// SPDX-License-Identifier: GPL-3.0-or-later
#include "store/workspace.h"

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string_view>

#include "store/schema.h"
#include "store/sqlite_db.h"
#include "store/workspace_impl.h"
#include "util/host_clock.h"

namespace bs {

using sqlite::Db;
using sqlite::Statement;
using sqlite::Transaction;

namespace {

// Rejects what is not an SQLite file before SQLite reads it, so opening never alters a foreign file. The bytes are
// read through SQLite's own descriptor of the file (SQLITE_FCNTL_FILE_POINTER), never a second one: closing any
// descriptor of a file drops every POSIX lock this process holds on it, those of its other open connections
// included (sqlite.org/howtocorrupt.html 2.2; issue #50: a GUI import unlocked the GUI's workspace this way, and a
// CLI command then deleted the WAL the GUI still wrote into).
void check_sqlite_header(const Db& db, const std::string& path) {
  sqlite3_file* file = nullptr;
  if (sqlite3_file_control(db.get(), "main", SQLITE_FCNTL_FILE_POINTER, &file) != SQLITE_OK || !file || !file->pMethods)
    throw WorkspaceError(WorkspaceError::Kind::Io, path + ": cannot open workspace");
  sqlite3_int64 size = 0;
  if (file->pMethods->xFileSize(file, &size) != SQLITE_OK)
    throw WorkspaceError(WorkspaceError::Kind::Io, path + ": cannot read the workspace's size");
  if (size == 0) return;  // an empty file becomes a new workspace
  unsigned char hdr[100] = {};
  // A short read is SQLITE_IOERR_SHORT_READ with the rest zero-filled: the size says how much is real.
  const int rc = file->pMethods->xRead(file, hdr, sizeof hdr, 0);
  if (rc != SQLITE_OK && rc != SQLITE_IOERR_SHORT_READ)
    throw WorkspaceError(WorkspaceError::Kind::Io, path + ": cannot read the workspace's header");
  if (size < 16 || std::memcmp(hdr, "SQLite format 3\0", 16) != 0)
    throw WorkspaceError(WorkspaceError::Kind::NotAWorkspace,
                         path + ": is not a BenchScope workspace (not an SQLite database)");
  if (size < 100)
    throw WorkspaceError(WorkspaceError::Kind::Corrupt, path + ": workspace file is truncated (header incomplete)");
  // A truncated file (a copy cut short, a full disk) can still open, and SQLite only notices when a query happens
  // to read a missing page. The header records the page size (offset 16, big-endian, 1 meaning 65536) and, when
  // the "valid-for" counter (offset 92) equals the change counter (offset 24), the page count (offset 28): a file
  // shorter than that is damaged, unless a WAL file is beside it. A longer file is fine (SQLite does not always
  // shrink it).
  const auto be32 = [&](int at) {
    return (std::uint32_t{hdr[at]} << 24) | (std::uint32_t{hdr[at + 1]} << 16) | (std::uint32_t{hdr[at + 2]} << 8) |
           std::uint32_t{hdr[at + 3]};
  };
  std::uint64_t page_size = (std::uint32_t{hdr[16]} << 8) | hdr[17];
  if (page_size == 1) page_size = 65536;
  const std::uint64_t pages = be32(28);
  if (be32(92) != be32(24) || pages == 0 || page_size < 512) return;  // no reliable size claim to check
  std::error_code ec;
  // A process killed during a WAL checkpoint can leave page 1 (with the new page count) written before the file
  // grew; the WAL beside it still holds every page and SQLite completes the checkpoint on open. Found by the
  // SIGKILL test (tests/app/workspace/test_import_kill.cpp). (file_size is a stat(): no descriptor.)
  if (std::filesystem::file_size(path + "-wal", ec) > 0 && !ec) return;
  if (static_cast<std::uint64_t>(size) < pages * page_size)
    throw WorkspaceError(WorkspaceError::Kind::Corrupt, path + ": workspace file is truncated (" +
                                                            std::to_string(size) + " bytes, its header says " +
                                                            std::to_string(pages * page_size) + ")");
}

}  // namespace

Workspace::Workspace(const std::string& path, OpenMode mode) : impl_(std::make_unique<Impl>()) {
  Impl& w = *impl_;
  w.path = path;
  const bool read_only = mode == OpenMode::ReadOnly;
  std::error_code ec;
  const bool existed = std::filesystem::exists(path, ec) && std::filesystem::file_size(path, ec) > 0;
  if (read_only && !existed)
    throw WorkspaceError(WorkspaceError::Kind::Io, path + ": no such workspace (or an empty file)");
  w.db = std::make_unique<Db>(path, read_only ? SQLITE_OPEN_READONLY : SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE);
  w.mark = OpenWorkspaceMark(path);  // the file exists now (SQLite opened or created it)
  if (existed) check_sqlite_header(*w.db, path);
  std::int64_t app_id = 0;
  std::int64_t version = 0;
  try {
    app_id = w.db->pragma_int("PRAGMA application_id");
    version = w.db->pragma_int("PRAGMA user_version");
  } catch (const WorkspaceError& e) {
    throw WorkspaceError(WorkspaceError::Kind::Corrupt,
                         path + ": workspace is damaged and cannot be read (" + std::string(e.what()) + ")");
  }
  if (existed && app_id != store::kApplicationId)
    throw WorkspaceError(WorkspaceError::Kind::NotAWorkspace,
                         path + ": is an SQLite database but not a BenchScope workspace");
  if (version > kSchemaVersion)
    throw WorkspaceError(WorkspaceError::Kind::NewerVersion, path + ": was written by a newer BenchScope (schema " +
                                                                 std::to_string(version) + ", this build reads up to " +
                                                                 std::to_string(kSchemaVersion) + ")");
  if (version < 0)
    throw WorkspaceError(WorkspaceError::Kind::Corrupt,
                         path + ": workspace is damaged (schema version " + std::to_string(version) + ")");
  if (read_only) {
    w.read_only = w.opened_read_only = true;
    if (version < kSchemaVersion) {
      // An older schema is migrated in a copy in memory: the file itself is never written.
      auto memory = std::make_unique<Db>(":memory:", SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, path);
      memory->copy_from(*w.db);
      w.db = std::move(memory);
      Transaction tx(*w.db);
      store::migrate(*w.db, static_cast<int>(version));
      tx.commit();
    }
  } else {
    const Db& db = *w.db;
    db.exec("PRAGMA foreign_keys = ON");
    db.exec("PRAGMA synchronous = NORMAL");
    if (version < kSchemaVersion) {
      Transaction tx(db);
      if (!existed) {
        db.exec(("PRAGMA application_id = " + std::to_string(store::kApplicationId)).c_str());
      }
      store::migrate(db, static_cast<int>(version));
      Statement meta(db, "INSERT OR REPLACE INTO meta(key, value) VALUES (?, ?)");
      if (version == 0) {  // a new file, or an empty one that only carries the application id
        meta.bind(1, std::string_view("created_at")).bind(2, std::string_view(bs::utc_timestamp())).run();
        meta.bind(1, std::string_view("created_by")).bind(2, std::string_view("benchscope " BENCHSCOPE_VERSION)).run();
      }
      meta.bind(1, std::string_view("schema_version")).bind(2, std::string_view(std::to_string(kSchemaVersion))).run();
      tx.commit();
    }
  }
  w.version = kSchemaVersion;
  // Read everything once: what breaks the import rules is listed, left out, and keeps the workspace read-only. A
  // table that is missing or unreadable is no single item: the workspace cannot be opened.
  try {
    w.scan(*this);
  } catch (const WorkspaceError& e) {
    throw WorkspaceError(WorkspaceError::Kind::Corrupt,
                         path + ": workspace is damaged and cannot be read (" + std::string(e.what()) + ")");
  }
  if (!w.damage.empty()) w.read_only = true;
}

// WAL (readers never wait for a writer) is switched on before the first write, not on opening: switching writes
// to the file's header, and reading a workspace writes nothing to it (damage in the samples is only found when
// they load, after opening). WAL stays on in the file once set.
void Workspace::Impl::prepare_write() const {
  if (wal) return;
  db->exec("PRAGMA journal_mode = WAL");
  wal = true;
}

Workspace::~Workspace() = default;
Workspace::Workspace(Workspace&&) noexcept = default;
Workspace& Workspace::operator=(Workspace&&) noexcept = default;

const std::string& Workspace::path() const { return impl_->path; }
int Workspace::schema_version() const { return impl_->version; }
const std::vector<WorkspaceDamage>& Workspace::damage() const { return impl_->damage; }
bool Workspace::read_only() const { return impl_->read_only; }
const ImportLimits& Workspace::limits() const { return impl_->limits; }

void Workspace::Impl::require_writable() const {
  if (opened_read_only) throw WorkspaceError(WorkspaceError::Kind::Constraint, path + ": opened read-only");
  if (damage.empty()) return prepare_write();
  // Corrupt, not Constraint: callers that treat Constraint as "this one file" (the import service) stop instead.
  throw WorkspaceError(WorkspaceError::Kind::Corrupt,
                       path + ": holds " + std::to_string(damage.size()) + " damaged item" +
                           (damage.size() == 1 ? "" : "s") + " (first: " + damage.front().item +
                           "), so nothing is written to it; remove them first (benchscope-cli check " + path +
                           " --remove-damaged, or the banner in BenchScope)");
}

namespace {
void rescan(Workspace::Impl& w, const Workspace& ws) {
  w.damage.clear();
  w.damaged_rows.clear();
  w.scan(ws);
  w.read_only = w.opened_read_only || !w.damage.empty();
}
}  // namespace

std::size_t Workspace::remove_damaged() {
  Impl& w = *impl_;
  if (w.opened_read_only) throw WorkspaceError(WorkspaceError::Kind::Constraint, w.path + ": opened read-only");
  w.prepare_write();
  std::size_t removed = 0;
  {
    Transaction tx(w.conn());
    for (const auto& [table, id] : w.damaged_rows) {
      // What ran on a device goes with it (runs and result sets refer to their device without a cascade).
      if (table == "devices")
        for (const char* sql : {"DELETE FROM runs WHERE device_id = ?", "DELETE FROM result_sets WHERE device_id = ?"})
          Statement(w.conn(), sql).bind(1, id).run();
      // `table` is one of the descriptions' own names (store/tables.cpp), never text from the file.
      Statement(w.conn(), ("DELETE FROM " + table + " WHERE id = ?").c_str()).bind(1, id).run();
      removed += static_cast<std::size_t>(sqlite3_changes(w.conn().get()));
    }
    // The import records count what they now hold, so that `check` finds the workspace sound.
    w.conn().exec(
        "UPDATE imports SET run_count = (SELECT COUNT(*) FROM runs WHERE import_id = imports.id), "
        "result_set_count = (SELECT COUNT(*) FROM result_sets WHERE import_id = imports.id)");
    tx.commit();
  }
  rescan(w, *this);
  return removed;
}

void Workspace::remove_import(std::int64_t import_id) {
  if (impl_->opened_read_only)
    throw WorkspaceError(WorkspaceError::Kind::Constraint, impl_->path + ": opened read-only");
  impl_->prepare_write();
  Transaction tx(impl_->conn());
  Statement(impl_->conn(), "DELETE FROM imports WHERE id = ?").bind(1, import_id).run();
  tx.commit();
  // Removing an import is the user's word even while the workspace is damaged: it may remove the damage.
  if (!impl_->damage.empty()) rescan(*impl_, *this);
}

namespace {
void require_name(const std::string& what, const std::string& name) {
  if (name.find_first_not_of(" \t") == std::string::npos)
    throw WorkspaceError(WorkspaceError::Kind::Constraint, what + ": the new name is empty");
}

// Renames one row of a kind the workspace tree lets the user name (a power log, a frame) through `update_sql`, which
// binds the label, then the id. Constraint for an empty name or an id no row has.
void rename_row(const Workspace::Impl& w, const std::string& what, const char* update_sql, std::int64_t id,
                const std::string& label) {
  w.require_writable();
  require_name(what, label);
  Statement(w.conn(), update_sql).bind(1, std::string_view(label)).bind(2, id).run();
  if (sqlite3_changes(w.conn().get()) == 0)
    throw WorkspaceError(WorkspaceError::Kind::Constraint, w.path + ": no " + what + " #" + std::to_string(id));
}
}  // namespace

void Workspace::rename_power_trace(std::int64_t trace_id, const std::string& label) {
  rename_row(*impl_, "power log", "UPDATE power_traces SET label = ? WHERE id = ?", trace_id, label);
}

void Workspace::rename_frame(std::int64_t frame_id, const std::string& label) {
  rename_row(*impl_, "frame", "UPDATE frames SET label = ? WHERE id = ?", frame_id, label);
}

void Workspace::rename_platform(const std::string& from, const std::string& to) {
  impl_->require_writable();
  require_name("platform '" + from + "'", to);
  if (from == to) return;
  if (impl_->opened_read_only)
    throw WorkspaceError(WorkspaceError::Kind::Constraint, impl_->path + ": opened read-only");
  Transaction tx(impl_->conn());
  Statement clash(impl_->conn(),
                  "SELECT a.device FROM devices a JOIN devices b ON a.device = b.device WHERE a.platform = ? AND "
                  "b.platform = ? LIMIT 1");
  clash.bind(1, std::string_view(from)).bind(2, std::string_view(to));
  if (clash.step())
    throw WorkspaceError(WorkspaceError::Kind::Constraint, "platform '" + to + "' already has a device '" +
                                                               clash.text(0) + "' like '" + from +
                                                               "': renaming would merge their runs");
  int changed = 0;
  for (const char* sql :
       {"UPDATE devices SET platform = ? WHERE platform = ?", "UPDATE power_traces SET platform = ? WHERE platform = ?",
        "UPDATE pipeline_runs SET platform = ? WHERE platform = ?",
        "UPDATE headroom_measurements SET platform = ? WHERE platform = ?",
        "UPDATE sustain_runs SET platform = ? WHERE platform = ?"}) {
    Statement(impl_->conn(), sql).bind(1, std::string_view(to)).bind(2, std::string_view(from)).run();
    changed += sqlite3_changes(impl_->conn().get());
  }
  if (changed == 0)
    throw WorkspaceError(WorkspaceError::Kind::Constraint, impl_->path + ": no platform '" + from + "'");
  tx.commit();
}

namespace {
constexpr std::string_view kSettingPrefix = "setting/";
}

void Workspace::set_setting(const std::string& key, const std::string& value) {
  impl_->require_writable();
  if (key.empty()) throw std::invalid_argument("workspace setting: empty key");
  Statement(impl_->conn(), "INSERT OR REPLACE INTO meta(key, value) VALUES (?, ?)")
      .bind(1, std::string_view(std::string(kSettingPrefix) + key))
      .bind(2, std::string_view(value))
      .run();
}

void Workspace::remove_setting(const std::string& key) {
  impl_->require_writable();
  Statement(impl_->conn(), "DELETE FROM meta WHERE key = ?")
      .bind(1, std::string_view(std::string(kSettingPrefix) + key))
      .run();
}

std::vector<std::pair<std::string, std::string>> Workspace::settings(const std::string& prefix) const {
  std::vector<std::pair<std::string, std::string>> out;
  // Keys sort bytewise (BINARY collation), so the ones with the prefix are contiguous from the prefix on; no LIKE,
  // as keys may hold % or _.
  const std::string full = std::string(kSettingPrefix) + prefix;
  Statement st(impl_->conn(), "SELECT key, value FROM meta WHERE key >= ? ORDER BY key");
  st.bind(1, std::string_view(full));
  while (st.step()) {
    std::string key = st.text(0);
    if (key.compare(0, full.size(), full) != 0) break;
    out.emplace_back(key.substr(kSettingPrefix.size()), st.text(1));
  }
  return out;
}

void Workspace::set_device_color(const std::string& platform, const std::string& device, int color_index) {
  impl_->require_writable();
  if (color_index < 0)
    throw WorkspaceError(WorkspaceError::Kind::Constraint,
                         "colour index must be 0 or more, not " + std::to_string(color_index));
  Statement st(impl_->conn(), "UPDATE devices SET color_index = ? WHERE platform = ? AND device = ?");
  st.bind(1, color_index).bind(2, std::string_view(platform)).bind(3, std::string_view(device)).run();
  if (sqlite3_changes(impl_->conn().get()) == 0)
    throw WorkspaceError(WorkspaceError::Kind::Constraint,
                         impl_->path + ": no device '" + device + "' on platform '" + platform + "'");
}

void Workspace::add_trace_phase(std::int64_t trace_id, const TracePhase& phase) {
  impl_->require_writable();
  if (phase.name.empty() || !(phase.end_s >= phase.start_s))
    throw WorkspaceError(WorkspaceError::Kind::Constraint,
                         impl_->path + ": phase '" + phase.name + "' needs a name and an end not before its start");
  Statement probe(impl_->conn(), "SELECT 1 FROM power_traces WHERE id = ?");
  probe.bind(1, trace_id);
  if (!probe.step())
    throw WorkspaceError(WorkspaceError::Kind::Constraint,
                         impl_->path + ": no power trace with id " + std::to_string(trace_id));
  Statement st(impl_->conn(), "INSERT INTO power_phases(trace_id, name, start_s, end_s) VALUES (?,?,?,?)");
  st.bind(1, trace_id).bind(2, std::string_view(phase.name)).bind(3, phase.start_s).bind(4, phase.end_s).run();
}

void Workspace::save_as(const std::string& new_path) const {
  std::error_code ec;
  if (std::filesystem::exists(new_path, ec))
    throw WorkspaceError(WorkspaceError::Kind::Io, new_path + ": already exists; choose another name");
  try {
    Statement st(impl_->conn(), "VACUUM INTO ?");
    st.bind(1, std::string_view(new_path));
    st.run();
  } catch (const WorkspaceError& e) {
    // Name the target: the failure is about where the copy goes (directory missing, no permission, disk full).
    throw WorkspaceError(e.kind(), new_path + ": cannot save a copy of the workspace here (" + e.what() + ")");
  }
}

const sqlite::Db& Workspace::database() const { return impl_->conn(); }

std::string Workspace::integrity_check() const {
  Statement st(impl_->conn(), "PRAGMA integrity_check");
  std::string result;
  while (st.step()) result += (result.empty() ? "" : "\n") + st.text(0);
  return result;
}

}  // namespace bs
