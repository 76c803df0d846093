// SPDX-License-Identifier: GPL-3.0-or-later
#include "store/sqlite_db.h"

#include <cstring>

namespace bs::sqlite {

Db::Db(const std::string& path, int flags, const std::string& label) : path_(label.empty() ? path : label) {
  const int rc = sqlite3_open_v2(path.c_str(), &db_, flags, nullptr);
  if (rc != SQLITE_OK) {
    const std::string msg = db_ ? sqlite3_errmsg(db_) : sqlite3_errstr(rc);
    sqlite3_close(db_);
    db_ = nullptr;
    throw WorkspaceError(WorkspaceError::Kind::Io, path_ + ": cannot open workspace: " + msg);
  }
  sqlite3_extended_result_codes(db_, 1);
  sqlite3_busy_timeout(db_, 5000);
  // A reader never checkpoints on close: were it the last connection SQLite knows of, closing would fold the WAL
  // into the file and delete it, and a writer in another process that lost its locks would write on into a
  // deleted file. Reading must not change the file at all.
  if (flags & SQLITE_OPEN_READONLY) sqlite3_db_config(db_, SQLITE_DBCONFIG_NO_CKPT_ON_CLOSE, 1, nullptr);
}

Db::~Db() { sqlite3_close_v2(db_); }

void Db::fail(std::string_view what, WorkspaceError::Kind kind) const {
  const int code = sqlite3_errcode(db_);
  if (code == SQLITE_NOTADB || (code & 0xff) == SQLITE_CORRUPT) kind = WorkspaceError::Kind::Corrupt;
  throw WorkspaceError(kind, path_ + ": " + std::string(what) + ": " + sqlite3_errmsg(db_));
}

void Db::exec(const char* sql) const {
  char* err = nullptr;
  if (sqlite3_exec(db_, sql, nullptr, nullptr, &err) != SQLITE_OK) {
    const std::string msg = err ? err : "unknown error";
    sqlite3_free(err);
    fail(std::string("SQL failed (") + msg + ")");
  }
}

std::int64_t Db::pragma_int(const char* pragma) const {
  Statement st(*this, pragma);
  return st.step() ? st.int64(0) : 0;
}

void Db::copy_from(const Db& source) const {
  sqlite3_backup* b = sqlite3_backup_init(db_, "main", source.get(), "main");
  if (!b) fail("cannot copy the workspace");
  const int rc = sqlite3_backup_step(b, -1);
  sqlite3_backup_finish(b);
  if (rc != SQLITE_DONE) source.fail("cannot copy the workspace", WorkspaceError::Kind::Corrupt);
}

Statement::Statement(const Db& db, const char* sql) : db_(db) {
  if (sqlite3_prepare_v2(db.get(), sql, -1, &stmt_, nullptr) != SQLITE_OK) db.fail("cannot prepare statement");
}

Statement::~Statement() { sqlite3_finalize(stmt_); }

Statement& Statement::bind(int index, std::int64_t v) {
  if (sqlite3_bind_int64(stmt_, index, v) != SQLITE_OK) db_.fail("bind failed");
  return *this;
}

Statement& Statement::bind(int index, double v) {
  if (sqlite3_bind_double(stmt_, index, v) != SQLITE_OK) db_.fail("bind failed");
  return *this;
}

Statement& Statement::bind(int index, std::string_view v) {
  if (sqlite3_bind_text(stmt_, index, v.data(), static_cast<int>(v.size()), SQLITE_TRANSIENT) != SQLITE_OK)
    db_.fail("bind failed");
  return *this;
}

Statement& Statement::bind(int index, const std::optional<double>& v) { return v ? bind(index, *v) : bind_null(index); }

Statement& Statement::bind_doubles(int index, const std::vector<double>& values) {
  const auto bytes = static_cast<sqlite3_uint64>(values.size()) * sizeof(double);
  if (sqlite3_bind_blob64(stmt_, index, values.empty() ? "" : static_cast<const void*>(values.data()), bytes,
                          SQLITE_TRANSIENT) != SQLITE_OK)
    db_.fail("bind failed");
  return *this;
}

Statement& Statement::bind_doubles_static(int index, const double* values, std::size_t n) {
  if (sqlite3_bind_blob64(stmt_, index, n == 0 ? static_cast<const void*>("") : static_cast<const void*>(values),
                          static_cast<sqlite3_uint64>(n) * sizeof(double), SQLITE_STATIC) != SQLITE_OK)
    db_.fail("bind failed");
  return *this;
}

const void* Statement::blob(int column, std::size_t& size) const {
  const void* p = sqlite3_column_blob(stmt_, column);
  size = static_cast<std::size_t>(sqlite3_column_bytes(stmt_, column));
  return p;
}

Statement& Statement::bind_bytes(int index, const std::vector<std::uint8_t>& bytes) {
  if (sqlite3_bind_blob64(stmt_, index, bytes.empty() ? "" : static_cast<const void*>(bytes.data()),
                          static_cast<sqlite3_uint64>(bytes.size()), SQLITE_TRANSIENT) != SQLITE_OK)
    db_.fail("bind failed");
  return *this;
}

std::vector<std::uint8_t> Statement::bytes(int column) const {
  const auto* p = static_cast<const std::uint8_t*>(sqlite3_column_blob(stmt_, column));
  const auto n = static_cast<std::size_t>(sqlite3_column_bytes(stmt_, column));
  return p ? std::vector<std::uint8_t>(p, p + n) : std::vector<std::uint8_t>();
}

std::vector<double> Statement::doubles(int column) const {
  const auto* p = static_cast<const unsigned char*>(sqlite3_column_blob(stmt_, column));
  const auto bytes = static_cast<std::size_t>(sqlite3_column_bytes(stmt_, column));
  std::vector<double> out(bytes / sizeof(double));
  if (p && !out.empty()) std::memcpy(out.data(), p, out.size() * sizeof(double));
  return out;
}

Statement& Statement::bind_null(int index) {
  if (sqlite3_bind_null(stmt_, index) != SQLITE_OK) db_.fail("bind failed");
  return *this;
}

bool Statement::step() {
  const int rc = sqlite3_step(stmt_);
  if (rc == SQLITE_ROW) return true;
  if (rc == SQLITE_DONE) return false;
  const bool constraint = (rc & 0xff) == SQLITE_CONSTRAINT;
  db_.fail("statement failed", constraint ? WorkspaceError::Kind::Constraint : WorkspaceError::Kind::Io);
}

void Statement::run() {
  while (step()) {
  }
  reset();
}

void Statement::reset() {
  sqlite3_reset(stmt_);
  sqlite3_clear_bindings(stmt_);
}

int Statement::type(int column) const { return sqlite3_column_type(stmt_, column); }
std::size_t Statement::size(int column) const { return static_cast<std::size_t>(sqlite3_column_bytes(stmt_, column)); }
std::int64_t Statement::int64(int column) const { return sqlite3_column_int64(stmt_, column); }
double Statement::real(int column) const { return sqlite3_column_double(stmt_, column); }
std::optional<double> Statement::optional_real(int column) const {
  if (sqlite3_column_type(stmt_, column) == SQLITE_NULL) return std::nullopt;
  return real(column);
}
std::string Statement::text(int column) const {
  const auto* p = reinterpret_cast<const char*>(sqlite3_column_text(stmt_, column));
  return p ? std::string(p, static_cast<std::size_t>(sqlite3_column_bytes(stmt_, column))) : std::string();
}

Transaction::Transaction(const Db& db) : db_(db) { db_.exec("BEGIN IMMEDIATE"); }

Transaction::~Transaction() {
  if (!done_) sqlite3_exec(db_.get(), "ROLLBACK", nullptr, nullptr, nullptr);
}

void Transaction::commit() {
  db_.exec("COMMIT");
  done_ = true;
}

}  // namespace bs::sqlite
