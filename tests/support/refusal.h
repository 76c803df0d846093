// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a command's reading refuses its words with: the text of the UsageError (or any runtime error) `read` throws,
// or "(accepted)" when it throws none, for tests that compare refusals word for word. `Error` names what a refusal
// is where that is not a runtime error: the core's readers (requirements, lens and tuner files) throw
// std::invalid_argument.
#include <QString>

#include <stdexcept>

namespace bs::test {

template <typename Error = std::runtime_error, typename Read>
QString refusal(Read&& read) {
  try {
    read();
  } catch (const Error& e) {
    return QString::fromUtf8(e.what());
  }
  return QStringLiteral("(accepted)");
}

}  // namespace bs::test
