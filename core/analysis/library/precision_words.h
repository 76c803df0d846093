// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The data type an MLPerf result's weights end up in, from the words of its measurements JSON: the rule the
// library's builder applies (scripts/build-library.py, data_type_of), here so that an imported LoadGen result gets
// the same precision as the library's copy of the same run. A type named alone ("int8"); a change said in words
// ("We transform the original fp32 weight to int8 weight": the type after "to"); "No change." reads the starting
// type from weight_transformations ("from int8 ... to int8"); else one type named once in the text. Nothing found:
// the precision is not stated, and the stated words are kept beside it.
#include <optional>
#include <string>
#include <string_view>

namespace bs {

struct PrecisionFromWords {
  std::string type;   // "int8", "fp16", "fp32", "bf16", "uint8"
  std::string field;  // "weight_data_types" or "weight_transformations": which field said it
  std::string text;   // that field's words, as written
};

// `weight_data_types` and `weight_transformations` as the measurements JSON writes them (either may be empty).
std::optional<PrecisionFromWords> precision_from_words(std::string_view weight_data_types,
                                                       std::string_view weight_transformations);

}  // namespace bs
