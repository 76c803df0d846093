// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/error_category.h"

namespace bs {

std::string_view to_string(ImportErrorCategory category) {
  switch (category) {
    case ImportErrorCategory::Io:
      return "io";
    case ImportErrorCategory::Empty:
      return "empty";
    case ImportErrorCategory::Binary:
      return "binary";
    case ImportErrorCategory::Encoding:
      return "encoding";
    case ImportErrorCategory::UnknownFormat:
      return "unknown-format";
    case ImportErrorCategory::Syntax:
      return "syntax";
    case ImportErrorCategory::MissingField:
      return "missing-field";
    case ImportErrorCategory::WrongType:
      return "wrong-type";
    case ImportErrorCategory::InvalidValue:
      return "invalid-value";
    case ImportErrorCategory::TooLarge:
      return "too-large";
    case ImportErrorCategory::TooDeep:
      return "too-deep";
    case ImportErrorCategory::Unsupported:
      return "unsupported";
  }
  return "unknown";
}

}  // namespace bs
