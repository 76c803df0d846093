// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Thin RAII over the SQLite C API: errors become WorkspaceError with SQLite's message and the file path.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <sqlite3.h>

#include "store/workspace.h"

namespace bs::sqlite {

class Db {
 public:
  // `label` names the database in messages (the file a ":memory:" copy was made from); defaults to `path`.
  Db(const std::string& path, int flags, const std::string& label = {});
  ~Db();
  Db(const Db&) = delete;
  Db& operator=(const Db&) = delete;
  sqlite3* get() const { return db_; }
  const std::string& path() const { return path_; }
  void exec(const char* sql) const;
  std::int64_t pragma_int(const char* pragma) const;
  // Replaces this database's content with a copy of `source` (SQLite's online backup), e.g. into memory.
  void copy_from(const Db& source) const;  // "PRAGMA user_version" -> its value
  [[noreturn]] void fail(std::string_view what, WorkspaceError::Kind kind = WorkspaceError::Kind::Io) const;

 private:
  sqlite3* db_ = nullptr;
  std::string path_;
};

class Statement {
 public:
  Statement(const Db& db, const char* sql);
  ~Statement();
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;

  Statement& bind(int index, std::int64_t v);
  Statement& bind(int index, int v) { return bind(index, static_cast<std::int64_t>(v)); }
  Statement& bind(int index, double v);
  Statement& bind(int index, std::string_view v);
  Statement& bind(int index, const std::optional<double>& v);
  Statement& bind_null(int index);
  Statement& bind_doubles(int index, const std::vector<double>& values);     // as a BLOB of native doubles
  Statement& bind_bytes(int index, const std::vector<std::uint8_t>& bytes);  // as a BLOB
  // n doubles as a BLOB without SQLite's copy: `values` must stay valid until the statement is stepped and reset.
  Statement& bind_doubles_static(int index, const double* values, std::size_t n);

  bool step();  // true while a row is available
  void run();   // step to completion, then reset for reuse
  void reset();
  int type(int column) const;          // SQLITE_INTEGER, SQLITE_FLOAT, SQLITE_TEXT, SQLITE_BLOB or SQLITE_NULL
  std::size_t size(int column) const;  // bytes of a TEXT or BLOB value, without reading a BLOB's content
  std::int64_t int64(int column) const;
  double real(int column) const;
  std::optional<double> optional_real(int column) const;
  std::string text(int column) const;
  std::vector<double> doubles(int column) const;
  std::vector<std::uint8_t> bytes(int column) const;  // a BLOB column; empty for NULL
  // A BLOB column in place (valid until the next step or reset), its size in `size`; nullptr for NULL or empty.
  const void* blob(int column, std::size_t& size) const;

 private:
  const Db& db_;
  sqlite3_stmt* stmt_ = nullptr;
};

// BEGIN IMMEDIATE ... COMMIT; rolls back in the destructor unless commit() ran (exception or cancel).
class Transaction {
 public:
  explicit Transaction(const Db& db);
  ~Transaction();
  void commit();

 private:
  const Db& db_;
  bool done_ = false;
};

}  // namespace bs::sqlite
