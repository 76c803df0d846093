// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Schema version 7 -> 8 (issue #32): what the user decides about a workspace's data, kept with it.
//  - lenses: a lens per frame or per camera, with how it was obtained (store/lens_store.h);
//  - power_traces.voltage_trace_id / voltage_channel: a current-only log's voltage borrowed from another log's
//    voltage channel (store/log_settings_store.h; the supply voltage itself was a column from version 2);
//  - power_phases.origin: 'log' for phases that came with the file, 'user' for ranges the user saved.
#include "store/sqlite_db.h"

namespace bs::store {

// Idempotent (CREATE ... IF NOT EXISTS, columns added only when missing), inside the caller's transaction.
void migrate_lenses_and_log_settings(const sqlite::Db& db);

}  // namespace bs::store
