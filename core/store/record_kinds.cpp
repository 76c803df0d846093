// SPDX-License-Identifier: GPL-3.0-or-later
#include "store/record_kinds.h"

namespace bs {

const RecordKindWords& words_of(RecordKindId kind) {
  static const std::array<RecordKindWords, kRecordKindCount> words = [] {
    std::array<RecordKindWords, kRecordKindCount> w{};
    for_each_record_kind([&](const auto& k) { w[static_cast<std::size_t>(k.id)] = k.words; });
    return w;
  }();
  return words[static_cast<std::size_t>(kind)];
}

bool ImportBatch::empty() const {
  bool none = true;
  for_each_record_kind([&](const auto& kind) { none = none && (this->*kind.in_batch).empty(); });
  return none;
}

void RecordCounts::add(const ImportBatch& batch) {
  for_each_record_kind(
      [&](const auto& kind) { n[static_cast<std::size_t>(kind.id)] += (batch.*kind.in_batch).size(); });
}

std::size_t RecordCounts::total() const {
  std::size_t sum = 0;
  for (const std::size_t k : n) sum += k;
  return sum;
}

std::string RecordCounts::summary() const {
  std::string s;
  for (std::size_t k = 0; k < kRecordKindCount; ++k) {
    if (n[k] == 0) continue;
    const RecordKindWords& w = words_of(static_cast<RecordKindId>(k));
    s += (s.empty() ? "" : ", ") + std::to_string(n[k]) + " " + (n[k] == 1 ? w.one : w.many);
  }
  return s.empty() ? "nothing" : s;
}

}  // namespace bs
