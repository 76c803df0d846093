// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A file's bytes as Qt reads and writes them: what a test looks into after it was written (a figure's SVG, a
// report's HTML, a workspace before and after), and the small fixture files a test writes itself (a log, a broken
// JSON). An unreadable or missing file gives no bytes: the check on its content then fails.
#include <QByteArray>
#include <QFile>
#include <QString>

namespace bs::test {

inline QByteArray bytes_of(const QString& path) {
  QFile f(path);
  return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

// Writes `bytes` as the whole of `path`, closed when it returns; false when it could not be written whole.
inline bool write_file(const QString& path, const QByteArray& bytes) {
  QFile f(path);
  return f.open(QIODevice::WriteOnly) && f.write(bytes) == bytes.size();
}

}  // namespace bs::test
