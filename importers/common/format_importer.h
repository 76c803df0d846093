// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Every format is the same Importer: an id, a description, a sniff, one function from a file to a batch (and, for a
// text format, the same parser over text in memory), the extension it usually carries and whether it is binary.
// A FileFormat holds those as data and FormatImporter serves it, so a new format is one FileFormat in its .cpp and
// one declaration in its header, instead of another class declaring and overriding the whole interface.
#include <initializer_list>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "common/importer.h"
#include "common/text_file.h"
#include "util/text.h"

namespace bs {

// The fields in this order, so a format can be listed positionally:
// {id, description, sniff, parse, text parser, usual extension, binary}.
struct FileFormat {
  std::string_view id;
  std::string_view description;
  int (*sniff)(std::string_view head, std::string_view path) = nullptr;
  ImportBatch (*parse)(const std::string& path, const ParseOptions& options, const ImportLimits& limits,
                       const CancelToken& cancel) = nullptr;
  TextParser text_parser = nullptr;  // none: a binary format, or one read only from its files
  // The file name endings, space-separated and matched in any case (".tif .tiff"), that break a tie of sniff scores
  // in this format's favour; "" none.
  std::string_view usual_endings = "";
  bool binary = false;

  // The format's parser over text in memory (tests, fuzzing); `file` names it in errors. Only for a format with a
  // text_parser.
  ImportBatch parse_text(const std::string& text, const std::string& file, const ParseOptions& options = {},
                         const ImportLimits& limits = {}, const CancelToken& cancel = CancelToken{}) const {
    return text_parser(text, file, options, limits, cancel);
  }
};

class FormatImporter : public Importer {
 public:
  explicit FormatImporter(const FileFormat& format) : format_(format) {}
  std::string_view id() const final { return format_.id; }
  std::string_view description() const final { return format_.description; }
  int sniff(std::string_view head, std::string_view path) const final { return format_.sniff(head, path); }
  bool usual_extension(std::string_view path) const final { return ends_with_any_ci(path, format_.usual_endings); }
  bool binary() const final { return format_.binary; }
  ImportBatch parse(const std::string& path, const ParseOptions& options, const ImportLimits& limits,
                    const CancelToken& cancel) const final {
    return format_.parse(path, options, limits, cancel);
  }

 private:
  FileFormat format_;
};

// One FormatImporter per format, in the order given (the order that breaks a tie between equal sniff scores).
inline std::vector<std::unique_ptr<Importer>> importers_of(std::initializer_list<const FileFormat*> formats) {
  std::vector<std::unique_ptr<Importer>> list;
  for (const FileFormat* format : formats) list.push_back(std::make_unique<FormatImporter>(*format));
  return list;
}

}  // namespace bs
