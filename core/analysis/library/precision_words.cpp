// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/library/precision_words.h"

#include <regex>
#include <set>

#include "util/text.h"

namespace bs {
namespace {

// scripts/build-library.py's DTYPE.
const char* const kType = "(u?int[0-9]+|fp[0-9]+|bf16|float[0-9]+)";

std::string lower_trimmed(std::string_view s) { return lower(trim(s)); }

std::optional<std::string> final_type(std::string_view text) {
  const std::string t = lower_trimmed(text);
  std::string alone = t;
  while (!alone.empty() && alone.back() == '.') alone.pop_back();
  if (std::regex_match(alone, std::regex(kType))) return alone;
  // "transform the original fp32 weight to int8 weight": the type after "to" (one word may sit between).
  std::smatch m;
  if (std::regex_search(t, m, std::regex(std::string("\\bto\\s+(?:\\w+\\s+)?") + kType))) return m[1].str();
  std::set<std::string> found;
  const std::regex word(std::string("\\b") + kType + "\\b");
  for (auto it = std::sregex_iterator(t.begin(), t.end(), word); it != std::sregex_iterator(); ++it)
    found.insert((*it)[1].str());
  if (found.size() == 1) return *found.begin();
  return std::nullopt;
}

}  // namespace

std::optional<PrecisionFromWords> precision_from_words(std::string_view weight_data_types,
                                                       std::string_view weight_transformations) {
  const std::string weights = lower_trimmed(weight_data_types);
  if (!weights.empty())
    if (auto t = final_type(weight_data_types))
      return PrecisionFromWords{*t, "weight_data_types", std::string(weight_data_types)};
  std::string said = weights;
  while (!said.empty() && said.back() == '.') said.pop_back();
  if (said == "no change" || said == "none" || said.empty())
    if (!lower_trimmed(weight_transformations).empty())
      if (auto t = final_type(weight_transformations))
        return PrecisionFromWords{*t, "weight_transformations", std::string(weight_transformations)};
  return std::nullopt;
}

}  // namespace bs
