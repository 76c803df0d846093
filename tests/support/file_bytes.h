// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A file's bytes as Qt reads them, for tests that look into what was written (a figure's SVG, a report's HTML, a
// workspace before and after). An unreadable or missing file gives no bytes: the check on its content then fails.
#include <QByteArray>
#include <QFile>
#include <QString>

namespace bs::test {

inline QByteArray bytes_of(const QString& path) {
  QFile f(path);
  return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

}  // namespace bs::test
