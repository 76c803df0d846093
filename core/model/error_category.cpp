// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/error_category.h"

#include "util/enum_words.h"

namespace bs {
namespace {

// The words messages and the bad-input corpus (tests/data/bad) name each category by.
constexpr EnumWord<ImportErrorCategory> kCategoryWords[] = {{ImportErrorCategory::Io, "io"},
                                                            {ImportErrorCategory::Empty, "empty"},
                                                            {ImportErrorCategory::Binary, "binary"},
                                                            {ImportErrorCategory::Encoding, "encoding"},
                                                            {ImportErrorCategory::UnknownFormat, "unknown-format"},
                                                            {ImportErrorCategory::Syntax, "syntax"},
                                                            {ImportErrorCategory::MissingField, "missing-field"},
                                                            {ImportErrorCategory::WrongType, "wrong-type"},
                                                            {ImportErrorCategory::InvalidValue, "invalid-value"},
                                                            {ImportErrorCategory::TooLarge, "too-large"},
                                                            {ImportErrorCategory::TooDeep, "too-deep"},
                                                            {ImportErrorCategory::Unsupported, "unsupported"}};
static_assert(names_every_value(kCategoryWords, ImportErrorCategory::Unsupported));

}  // namespace

std::string_view to_string(ImportErrorCategory category) { return word_of(kCategoryWords, category, "unknown"); }

}  // namespace bs
