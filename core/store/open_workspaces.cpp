// SPDX-License-Identifier: GPL-3.0-or-later
#include "store/open_workspaces.h"

#include <sys/stat.h>

#include <map>
#include <mutex>
#include <stdexcept>
#include <utility>

namespace bs {
namespace {

using FileId = std::pair<unsigned long long, unsigned long long>;  // device, inode

std::mutex& registry_mutex() {
  static std::mutex m;
  return m;
}

// How many open Workspace objects name each file (the GUI, its import and its power loader each have one).
std::map<FileId, int>& registry() {
  static std::map<FileId, int> r;
  return r;
}

bool file_id(const std::string& path, FileId& out) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return false;
  out = {static_cast<unsigned long long>(st.st_dev), static_cast<unsigned long long>(st.st_ino)};
  return true;
}

}  // namespace

OpenWorkspaceMark::OpenWorkspaceMark(const std::string& path) {
  FileId id;
  if (!file_id(path, id)) return;
  std::lock_guard lock(registry_mutex());
  ++registry()[id];
  dev_ = id.first;
  ino_ = id.second;
  marked_ = true;
}

OpenWorkspaceMark::~OpenWorkspaceMark() {
  if (!marked_) return;
  std::lock_guard lock(registry_mutex());
  const auto it = registry().find({dev_, ino_});
  if (it != registry().end() && --it->second <= 0) registry().erase(it);
}

OpenWorkspaceMark::OpenWorkspaceMark(OpenWorkspaceMark&& other) noexcept
    : dev_(other.dev_), ino_(other.ino_), marked_(std::exchange(other.marked_, false)) {}

OpenWorkspaceMark& OpenWorkspaceMark::operator=(OpenWorkspaceMark&& other) noexcept {
  if (this != &other) {
    OpenWorkspaceMark old(std::move(*this));  // unmarks what this held, on leaving
    dev_ = other.dev_;
    ino_ = other.ino_;
    marked_ = std::exchange(other.marked_, false);
  }
  return *this;
}

bool is_open_workspace(const std::string& path) {
  // SQLite's companions hold locks too (the -shm file its WAL lock bytes): "<workspace>-wal" is the workspace's.
  std::string stem = path;
  for (const char* suffix : {"-wal", "-shm", "-journal"}) {
    const std::string s(suffix);
    if (stem.size() > s.size() && stem.compare(stem.size() - s.size(), s.size(), s) == 0) {
      stem.resize(stem.size() - s.size());
      break;
    }
  }
  FileId id, stem_id;
  const bool have = file_id(path, id);
  const bool have_stem = stem != path && file_id(stem, stem_id);
  std::lock_guard lock(registry_mutex());
  return (have && registry().count(id) > 0) || (have_stem && registry().count(stem_id) > 0);
}

void refuse_open_workspace(const std::string& path, const std::string& doing) {
  if (is_open_workspace(path))
    throw std::runtime_error(path + ": is a workspace open in this BenchScope; it is not read as a file for " + doing +
                             " (a second descriptor would drop the locks that keep its edits safe)");
}

}  // namespace bs
