// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The workspace's private state, shared by its source files: workspace.cpp (opening, edits, settings),
// workspace_write.cpp (imports) and workspace_read.cpp (reading back, with the damage it finds).
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "model/import_limits.h"
#include "store/open_workspaces.h"
#include "store/sqlite_db.h"
#include "store/workspace.h"

namespace bs {

struct Workspace::Impl {
  std::string path;
  // Declared before `db`, so it is unmarked only after the connection has closed (store/open_workspaces.h).
  OpenWorkspaceMark mark;
  std::unique_ptr<sqlite::Db> db;
  int version = 0;
  bool read_only = false;  // opened for reading only (OpenMode::ReadOnly), or damaged until the user says
  bool opened_read_only = false;
  ImportLimits limits;
  // What reading found damaged, in the order found; `damaged_rows` holds each item's (table, id) so every read
  // leaves it out.
  mutable std::vector<WorkspaceDamage> damage;
  mutable std::set<std::pair<std::string, std::int64_t>> damaged_rows;

  const sqlite::Db& conn() const { return *db; }
  void record(WorkspaceDamage d) const;
  bool is_damaged(const std::string& table, std::int64_t id) const { return damaged_rows.count({table, id}) > 0; }
  // Throws WorkspaceError naming the damage when writes are refused; else prepares the file for writing.
  void require_writable() const;
  void prepare_write() const;  // WAL on, once (see workspace.cpp)
  mutable bool wal = false;
  // Reads every entity once (without samples or pixels) so that `damage` lists all that is damaged.
  void scan(const Workspace& ws);
};

}  // namespace bs
