// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A strict reader of the YAML subset RobotPerf's benchmark.yaml files use. No YAML library is in BenchScope's stack
// (Debian's libyaml is not among its packages; OpenCV's FileStorage reads only its own YAML dialect and accepts a
// duplicate key silently), so this reads exactly: block mappings and block sequences by indentation ("- key: v"
// items included), plain scalars (continued on more-indented lines, folded with a space), single-quoted scalars
// ('' is a quote) and double-quoted ones (\" \\ \/ \n \t \r \0 \xXX \uXXXX \UXXXXXXXX, a trailing \ joins lines),
// both spanning lines (a line break folds to a space, an empty line is a newline), "#" comments, and one leading
// "---". Everything else is refused with its line: tabs in indentation, anchors, aliases, tags, flow collections,
// block scalars (| >), a second document, and a key used twice in one mapping (naming both lines).
#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "common/importer.h"

namespace bs {

struct YamlEntry;

struct YamlNode {
  enum class Kind { Scalar, Map, Seq };
  Kind kind = Kind::Scalar;
  std::string scalar;
  bool quoted = false;  // a quoted scalar is a string even when it looks like a number
  // A mapping's entries in file order. Not a std::pair: pair<string, YamlNode> would need YamlNode complete here
  // (clang 14 with libstdc++ 12 refuses it); a vector of a type completed below is allowed.
  std::vector<YamlEntry> map;
  std::vector<YamlNode> seq;
  std::size_t line = 0;  // 1-based line where the node starts

  const YamlNode* find(std::string_view key) const;  // a mapping's value, nullptr when absent or not a mapping
};

struct YamlEntry {
  std::string key;
  YamlNode value;
};

// Throws ImportError (Syntax, Unsupported, InvalidValue) naming `file` and the line.
YamlNode parse_yaml_subset(std::string_view text, const std::string& file, const ImportLimits& limits = {});

}  // namespace bs
