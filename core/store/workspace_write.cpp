// SPDX-License-Identifier: GPL-3.0-or-later
// Storing imports: one transaction per call, every row written through its table's description (store/tables.h).
#include "store/record_kinds.h"
#include "store/tables.h"
#include "store/workspace_impl.h"
#include "util/host_clock.h"

namespace bs {

using sqlite::Db;
using sqlite::Statement;
using sqlite::Transaction;

namespace {

void refuse_duplicate(const Db& db, const std::string& content_hash) {
  Statement dup(db, "SELECT path, imported_at FROM imports WHERE content_hash = ?");
  dup.bind(1, std::string_view(content_hash));
  if (dup.step())
    throw WorkspaceError(WorkspaceError::Kind::Constraint,
                         "already imported from " + dup.text(0) + " on " + dup.text(1));
}

// Inserts one import inside the caller's transaction and returns its id: the import's row, then each record kind's
// rows through its descriptor (store/record_kinds.h), in the kinds' order.
std::int64_t insert_import(const Db& db, const ImportBatch& batch, const std::string& content_hash,
                           const CancelToken* cancel) {
  refuse_duplicate(db, content_hash);
  ImportRecord record;
  record.path = batch.source_path;
  record.format = batch.format;
  record.imported_at = bs::utc_timestamp();
  record.content_hash = content_hash;
  record.run_count = static_cast<std::int64_t>(batch.runs.size());
  record.result_set_count = static_cast<std::int64_t>(batch.result_sets.size());
  const std::int64_t import_id = store::Inserter(db, store::imports_table()).insert({}, record);
  store::ImportWrite write(db, import_id, batch, content_hash, cancel);
  for_each_record_kind([&](const auto& kind) { kind.write(write, batch.*kind.in_batch); });
  write.check();
  return import_id;
}

}  // namespace

std::int64_t Workspace::add_import(const ImportBatch& batch, const std::string& content_hash,
                                   const CancelToken* cancel) {
  impl_->require_writable();
  const Db& db = impl_->conn();
  refuse_duplicate(db, content_hash);  // before BEGIN, so a duplicate never takes the write lock
  Transaction tx(db);
  const std::int64_t id = insert_import(db, batch, content_hash, cancel);
  tx.commit();
  return id;
}

std::vector<std::int64_t> Workspace::add_imports(const std::vector<HashedBatch>& batches, const CancelToken* cancel) {
  impl_->require_writable();
  const Db& db = impl_->conn();
  Transaction tx(db);
  std::vector<std::int64_t> ids;
  ids.reserve(batches.size());
  for (const HashedBatch& b : batches) ids.push_back(insert_import(db, *b.batch, b.content_hash, cancel));
  tx.commit();
  return ids;
}

}  // namespace bs
