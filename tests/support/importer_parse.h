// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A file read by one format, as the import dialog reads it once the format is chosen: no options, never cancelled.
// One definition for the importer tests that parse their fixtures by name (the token the parse wants is a detail).
#include <string>

#include "common/format_importer.h"

namespace bs::test {

inline ImportBatch parse_with(const FileFormat& format, const std::string& path) {
  const CancelToken cancel;
  return format.parse(path, {}, {}, cancel);
}

}  // namespace bs::test
