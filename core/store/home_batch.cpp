// SPDX-License-Identifier: GPL-3.0-or-later
#include "store/home_batch.h"

#include "store/workspace.h"

namespace bs {

std::int64_t bring_home(Workspace& ws, const HomeBatch& home, const CancelToken* cancel) {
  return ws.add_import(home.batch, home.content_hash, cancel);
}

std::vector<std::int64_t> bring_home(Workspace& ws, const std::vector<HomeBatch>& homes, const CancelToken* cancel) {
  std::vector<Workspace::HashedBatch> hashed;
  hashed.reserve(homes.size());
  for (const HomeBatch& h : homes) hashed.push_back({&h.batch, h.content_hash});
  return ws.add_imports(hashed, cancel);
}

}  // namespace bs
