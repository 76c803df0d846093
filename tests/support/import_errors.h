// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The ImportError a parse throws, for tests that check category, place and wording. Input that is accepted fails
// the test (an exception Qt Test reports) instead of returning a stand-in error a careless check could pass on.
#include <stdexcept>
#include <string>
#include <utility>

#include "common/format_importer.h"
#include "common/import_error.h"

namespace bs::test {

template <class Parse>
ImportError import_error_of(Parse&& parse) {
  try {
    (void)std::forward<Parse>(parse)();
  } catch (const ImportError& e) {
    return e;
  }
  throw std::runtime_error("expected an ImportError, but the input was accepted");
}

// A format's texts that must be refused: the returned function gives the ImportError `format` throws for a text,
// read as a file named `file` (the name its errors carry), so a test file states its format and name once:
//   const auto error_of = bs::test::import_errors_of(bs::kPowerCsvFileFormat, "log.csv");
inline auto import_errors_of(const FileFormat& format, std::string file) {
  return [&format, file = std::move(file)](const std::string& text) {
    return import_error_of([&] { return format.parse_text(text, file); });
  };
}

}  // namespace bs::test
