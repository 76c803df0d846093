// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A measurement on its way home (#52's one way home): what one front end measured or fetched, as the import batch
// and the content hash it is stored under. Each record kind has one builder that makes it (sustain_import,
// headroom_import, ...), so the GUI and the CLI store the same measurement the same way and a workspace recognises it
// as the same import whichever of them stored it.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "store/import_batch.h"
#include "util/cancel.h"

namespace bs {

class Workspace;

struct HomeBatch {
  ImportBatch batch;
  std::string content_hash;  // what makes it the same measurement: the same hash is not stored twice
};

// What every builder of one in-process measurement's home starts from (it then adds the record to its kind's vector):
// the import named `name` (util/home_name.h: who measured it, on which computer, when) in `format`, the power log
// recorded beside the measurement, if any, and the content hash of `key`, the record's serialised form.
HomeBatch measured_home(std::string name, std::string format, const std::optional<PowerTrace>& power,
                        std::string_view key);

// Stores `home` as one import (one transaction) and returns its id. Throws WorkspaceError: Constraint naming the
// earlier import when the hash is stored already; nothing is stored on any error or cancellation.
std::int64_t bring_home(Workspace& ws, const HomeBatch& home, const CancelToken* cancel = nullptr);
// Several in ONE transaction (a robot job's imports): all of them or none. Returns the import ids in order.
std::vector<std::int64_t> bring_home(Workspace& ws, const std::vector<HomeBatch>& homes,
                                     const CancelToken* cancel = nullptr);
// The same into the workspace at `workspace_path` (the CLI's --workspace), created when missing. A workspace this call
// created is not left behind when nothing could be stored (a duplicate, a full disk): the file, its WAL and its
// shared-memory file are removed again.
std::int64_t bring_home(const std::string& workspace_path, const HomeBatch& home);
std::vector<std::int64_t> bring_home(const std::string& workspace_path, const std::vector<HomeBatch>& homes);

}  // namespace bs
