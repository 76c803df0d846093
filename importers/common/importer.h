// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <cstddef>
#include <string>
#include <string_view>

#include "common/import_error.h"
#include "common/parse_options.h"
#include "model/import_limits.h"
#include "store/import_batch.h"
#include "util/cancel.h"

namespace bs {

// One file format. Importers are stateless and pure: bytes in, ImportBatch out, or an ImportError.
class Importer {
 public:
  virtual ~Importer() = default;
  // Stable id stored in the workspace, e.g. "benchscope-run-v1", "google-benchmark-json", "clpeak-text".
  virtual std::string_view id() const = 0;
  virtual std::string_view description() const = 0;
  // Confidence 0..100 that `head` (the first <= 64 KiB of the file) is this format. Content decides; the
  // extension only breaks ties.
  virtual int sniff(std::string_view head, std::string_view path) const = 0;
  // Whether `path` has an extension this format usually carries. Used only to break a tie between equal sniff
  // scores, never to pick a format the content does not support.
  virtual bool usual_extension(std::string_view /*path*/) const { return false; }
  // Binary formats (images) are sniffed on the raw head before the text checks that reject NUL bytes.
  virtual bool binary() const { return false; }
  // Parses the whole file, with the options the format reads (the rest are ignored). Throws ImportError (or
  // Cancelled). Never returns a partial batch.
  virtual ImportBatch parse(const std::string& path, const ParseOptions& options, const ImportLimits& limits,
                            const CancelToken& cancel) const = 0;
};

// Helpers shared by importers. Which importer reads a file (every format, the sniffing, import_file) is the
// registry, services/workspace/registry.h: it names every format folder, which importers/common must not (#52).
std::string read_head(const std::string& path, std::size_t max_bytes = 64 * 1024);  // throws Io
std::string read_whole_file(const std::string& path, std::size_t max_bytes);        // throws Io/TooLarge
// Rejects empty, binary (NUL bytes) and UTF-16/32 content with the right category; strips nothing.
void check_text(std::string_view head, const std::string& path);
// `text` without a leading UTF-8 byte-order mark: the one place a BOM is recognised. Files reach the parsers
// through it (parse_text_file, PowerLineReader), so parse_X() functions never see one from a file.
std::string_view strip_utf8_bom(std::string_view text);

}  // namespace bs
