// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a core reader (a requirement, a lens or tuner file, a list of picked lines) refuses its input with: the text
// of the std::invalid_argument `read` throws, or "(accepted)" when it throws none, so a test checks a refusal's
// wording in one line. refusal.h is the same for the CLI's words, which are refused with runtime errors.
#include <QString>

#include <stdexcept>

namespace bs::test {

template <typename Read>
QString invalid_argument_of(Read&& read) {
  try {
    read();
  } catch (const std::invalid_argument& e) {
    return QString::fromUtf8(e.what());
  }
  return QStringLiteral("(accepted)");
}

}  // namespace bs::test
