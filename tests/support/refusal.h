// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a command's reading refuses its words with: the text of the UsageError (or any runtime error) `read` throws,
// or "(accepted)" when it throws none, for tests that compare refusals word for word.
#include <QString>

#include <stdexcept>

namespace bs::test {

template <typename Read>
QString refusal(Read&& read) {
  try {
    read();
  } catch (const std::runtime_error& e) {
    return QString::fromUtf8(e.what());
  }
  return QStringLiteral("(accepted)");
}

}  // namespace bs::test
