// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Where a GUI test's QSettings live: under the organisation "BenchScopeTest" and the test's own name, never the
// person's BenchScope settings, and not another test's (the windows and dialogs remember sizes and choices).
#include <QCoreApplication>
#include <QSettings>
#include <QString>

namespace bs::test {

inline void use_test_settings(const QString& test_name) {
  QCoreApplication::setOrganizationName("BenchScopeTest");
  QCoreApplication::setApplicationName(test_name);
}

// ... and empty: what an earlier run of the test remembered (a dialog's last choices) does not steer this one.
inline void use_fresh_test_settings(const QString& test_name) {
  use_test_settings(test_name);
  QSettings().clear();
}

}  // namespace bs::test
