// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The workspace files this process has open. POSIX advisory locks belong to a process and a file, not to a
// descriptor: closing ANY descriptor of a file drops every lock the process holds on it, SQLite's included
// (sqlite.org/howtocorrupt.html, section 2.2). A process that reads an open workspace through a second descriptor
// (an importer, a hash) therefore silently unlocks it, and another process's SQLite may then checkpoint and delete
// the WAL this process still writes into. Every reader of arbitrary files asks here first (by device and inode, so
// another name of the same file is caught too) and refuses such a file instead.
#include <string>

namespace bs {

// Registered for as long as it lives: one per open Workspace.
class OpenWorkspaceMark {
 public:
  OpenWorkspaceMark() = default;
  // Marks `path` (an existing file) as open; an unreadable path marks nothing.
  explicit OpenWorkspaceMark(const std::string& path);
  ~OpenWorkspaceMark();
  OpenWorkspaceMark(OpenWorkspaceMark&& other) noexcept;
  OpenWorkspaceMark& operator=(OpenWorkspaceMark&& other) noexcept;
  OpenWorkspaceMark(const OpenWorkspaceMark&) = delete;
  OpenWorkspaceMark& operator=(const OpenWorkspaceMark&) = delete;

 private:
  unsigned long long dev_ = 0, ino_ = 0;
  bool marked_ = false;
};

// True when `path` names (through any link or second name) a workspace open in this process, or one of its SQLite
// companions ("<workspace>-wal", "-shm", "-journal"). Uses stat(), which opens no descriptor.
bool is_open_workspace(const std::string& path);

// Throws std::runtime_error naming `path` when it is an open workspace; `doing` says what was refused ("import").
void refuse_open_workspace(const std::string& path, const std::string& doing);

}  // namespace bs
