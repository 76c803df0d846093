// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a process holds on a workspace, read as `awk '$5==PID' /proc/locks` and `ls -l /proc/PID/fd` read it (issue
// #50): its POSIX locks on the database file and on its -shm file (SQLite's WAL index), and whether a descriptor
// of it points at a deleted -wal file (another process checkpointed and deleted the WAL it still writes into).
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace bs::test {

// The number of POSIX locks process `pid` holds on the file `path` (0 when the file does not exist).
inline int posix_locks_on(long pid, const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return 0;
  std::ifstream locks("/proc/locks");
  std::string line;
  int count = 0;
  // "1: POSIX  ADVISORY  READ 1234 08:01:5678 128 128": the pid is field 5, "major:minor:inode" field 6. A line
  // of a lock that waits starts with "1: ->", one field more.
  while (std::getline(locks, line)) {
    std::istringstream in(line);
    std::string id, kind, advisory, mode, pid_text, where;
    in >> id >> kind;
    if (kind == "->") in >> kind;
    in >> advisory >> mode >> pid_text >> where;
    if (kind != "POSIX" || pid_text != std::to_string(pid)) continue;
    const auto colon = where.rfind(':');
    if (colon != std::string::npos && where.substr(colon + 1) == std::to_string(st.st_ino)) ++count;
  }
  return count;
}

// Whether process `pid` has a descriptor on "<workspace>-wal (deleted)" or "<workspace>-shm (deleted)".
inline bool holds_deleted_wal(long pid, const std::string& workspace) {
  namespace fs = std::filesystem;
  const std::string name = fs::path(workspace).filename().string();
  std::error_code ec;
  for (const auto& fd : fs::directory_iterator("/proc/" + std::to_string(pid) + "/fd", ec)) {
    std::error_code link_ec;
    const std::string target = fs::read_symlink(fd.path(), link_ec).string();
    if (link_ec) continue;
    if (target.find(name + "-wal (deleted)") != std::string::npos ||
        target.find(name + "-shm (deleted)") != std::string::npos)
      return true;
  }
  return false;
}

}  // namespace bs::test
