// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Schema version 9 -> 10 (issue #43.2, #43.4): what the user sets in a tab that changes the decision is kept with the
// workspace, so the recommendation after reopening is the one set before (store/decision_store.h):
//  - decision: one row, the Platforms tab's constraints (power budget, frame rate, battery runtime, the control-loop
//    requirement of #45), its battery choice, parallel load and mission, and the library computers chosen as
//    candidates;
//  - chosen_logs: per platform the power log the comparisons use when the platform has several (Efficiency, Battery,
//    Platforms, the report, `benchscope-cli platforms`); removed with its log (ON DELETE CASCADE).
#include "store/sqlite_db.h"

namespace bs::store {

// Idempotent (CREATE ... IF NOT EXISTS), inside the caller's transaction.
void migrate_decision_and_chosen_logs(const sqlite::Db& db);

}  // namespace bs::store
