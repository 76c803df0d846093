// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A scenario that collects what a person would see wrong (a name missing from a figure, words printed over each
// other) and checks it once: QVERIFY2 shows one message, so every problem goes to the log as well.
#include <QString>
#include <QStringList>
#include <QtGlobal>

namespace bs::test {

// Writes each problem to the log and sums them up for QVERIFY2's message: how many, and the first.
inline QString problems_told(const QStringList& problems) {
  for (const QString& p : problems) qWarning("%s", qPrintable(p));
  return QStringLiteral("%1 problem(s), the first: %2").arg(problems.size()).arg(problems.value(0));
}

}  // namespace bs::test
