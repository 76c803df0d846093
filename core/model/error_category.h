// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The categories of bad input, shared by the importers (ImportError) and the workspace reader (a value read back
// from a workspace meets the same rules as an import, and a violation is reported in the same words).
#include <string_view>

namespace bs {

// What kind of problem a file has; the bad-input corpus (tests/data/bad) records the expected category per file.
enum class ImportErrorCategory {
  Io,             // cannot open / read
  Empty,          // zero bytes or only whitespace
  Binary,         // NUL bytes or not text where text is required
  Encoding,       // not UTF-8 (e.g. UTF-16)
  UnknownFormat,  // no importer recognises the content
  Syntax,         // malformed JSON / CSV / text, including truncation
  MissingField,   // a required field is absent
  WrongType,      // a field has the wrong JSON type
  InvalidValue,   // NaN, Infinity, negative time, out-of-range number, unknown enum text
  TooLarge,       // file or a declared size exceeds a documented limit
  TooDeep,        // JSON nesting beyond the limit
  Unsupported,    // a newer format version, an unsupported variant
};
std::string_view to_string(ImportErrorCategory category);

}  // namespace bs
