// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/text_file.h"

namespace bs {

ImportBatch parse_text_file(const std::string& path, const ParseOptions& options, const ImportLimits& limits,
                            const CancelToken& cancel, TextParser parse) {
  std::string text = read_whole_file(path, limits.max_json_bytes);
  text.erase(0, text.size() - strip_utf8_bom(text).size());
  cancel.throw_if_cancelled();
  return parse(text, path, options, limits, cancel);
}

}  // namespace bs
