// SPDX-License-Identifier: GPL-3.0-or-later
#include "store/home_batch.h"

#include <filesystem>
#include <utility>

#include "store/workspace.h"

namespace bs {

HomeBatch measured_home(std::string name, std::string format, const std::optional<PowerTrace>& power,
                        std::string_view key) {
  HomeBatch out;
  out.batch.source_path = std::move(name);
  out.batch.format = std::move(format);
  if (power) out.batch.power_traces.push_back(*power);
  out.content_hash = content_hash(key);
  return out;
}

std::int64_t bring_home(Workspace& ws, const HomeBatch& home, const CancelToken* cancel) {
  return ws.add_import(home.batch, home.content_hash, cancel);
}

std::vector<std::int64_t> bring_home(Workspace& ws, const std::vector<HomeBatch>& homes, const CancelToken* cancel) {
  std::vector<Workspace::HashedBatch> hashed;
  hashed.reserve(homes.size());
  for (const HomeBatch& h : homes) hashed.push_back({&h.batch, h.content_hash});
  return ws.add_imports(hashed, cancel);
}

std::vector<std::int64_t> bring_home(const std::string& workspace_path, const std::vector<HomeBatch>& homes) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const bool existed = fs::exists(workspace_path, ec);
  try {
    Workspace ws(workspace_path);
    return bring_home(ws, homes);
  } catch (...) {
    if (!existed)
      for (const char* suffix : {"", "-wal", "-shm"}) fs::remove(workspace_path + suffix, ec);
    throw;
  }
}

std::int64_t bring_home(const std::string& workspace_path, const HomeBatch& home) {
  return bring_home(workspace_path, std::vector<HomeBatch>{home}).front();
}

}  // namespace bs
