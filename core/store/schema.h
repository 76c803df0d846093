// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include "store/sqlite_db.h"

namespace bs::store {

// 'BSCP': marks an SQLite file as a BenchScope workspace (PRAGMA application_id).
inline constexpr std::int64_t kApplicationId = 0x42534350;

// Brings a workspace from `from_version` to Workspace::kSchemaVersion, one migration per step, inside the
// caller's transaction. Version 0 is an empty file that carries only the application id.
void migrate(const sqlite::Db& db, int from_version);

// Whether `table` has `column` already. The migrations that add a column ask first, so that they are idempotent like
// the CREATE ... IF NOT EXISTS steps: a workspace whose user_version was set back (tests do) may have the column.
bool has_column(const sqlite::Db& db, const char* table, const char* column);

}  // namespace bs::store
