// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Which importer reads a file: every format BenchScope knows, in sniffing order, and the sniffing that picks one.
// It names every format folder (importers/frames, power, runs, ...), so it lives on the services floor: the base
// folder importers/common holds only what the formats themselves need (common/importer.h), and knows none of them.
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "common/importer.h"
#include "frames/frame_raw.h"

namespace bs {

// All importers BenchScope knows, in sniffing order.
const std::vector<std::unique_ptr<Importer>>& all_importers();
const Importer* find_importer(std::string_view id);

// Reads the head of `path`, rejects empty / binary / UTF-16 input with a clear ImportError, picks the importer
// with the highest sniff score (ties broken by usual_extension, then by order) and parses. UnknownFormat when
// nothing scores above 0. Formats get the default ParseOptions.
ImportBatch import_file(const std::string& path, const CancelToken& cancel, const ImportLimits& limits = {});

// import_file(), except that a .raw file without a sidecar is read with `raw_geometry` when one is given (the CLI's
// --raw-geometry, the GUI's geometry dialog); `geometry_source` names it in error messages.
ImportBatch import_file_with_raw_geometry(const std::string& path, const std::optional<RawFrameOptions>& raw_geometry,
                                          const CancelToken& cancel, const std::string& geometry_source);

}  // namespace bs
