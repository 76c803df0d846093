// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The one way a whole-document text format (JSON, clpeak text) gets from a file to its parse_X() function: the file
// is read whole within ImportLimits::max_json_bytes (checked on its size before anything is allocated), a UTF-8
// byte-order mark is dropped (strip_utf8_bom), and the text goes to the parser with the path naming it in errors.
// Streamed formats (the power logs) read their files line by line through PowerLineReader instead.
#include <string>

#include "common/importer.h"

namespace bs {

// The shape every text parser has: text without a byte-order mark, the file named in errors, then what the caller
// knows. A parser ignores what it does not use.
using TextParser = ImportBatch (*)(const std::string& text, const std::string& file, const ParseOptions& options,
                                   const ImportLimits& limits, const CancelToken& cancel);

// Reads `path` and hands its text to `parse`. Throws ImportError Io (missing file, a folder, read error),
// TooLarge (beyond limits.max_json_bytes, naming the file) or whatever `parse` throws; Cancelled when cancelled.
ImportBatch parse_text_file(const std::string& path, const ParseOptions& options, const ImportLimits& limits,
                            const CancelToken& cancel, TextParser parse);

// parse_text_file() with the parser fixed: a whole-document format's FileFormat::parse.
template <TextParser parse>
ImportBatch parse_text_file_with(const std::string& path, const ParseOptions& options, const ImportLimits& limits,
                                 const CancelToken& cancel) {
  return parse_text_file(path, options, limits, cancel, parse);
}

}  // namespace bs
