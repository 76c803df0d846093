// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Where the paper's sample data is (sample_data/paper-2018, Biddulph et al. 2018): what most CLI tests and GUI
// scenarios import first. One definition for the CLI harness and the scenario window.
#include <QString>

namespace bs::test {

inline const QString kPaper = QStringLiteral(BENCHSCOPE_SOURCE_DIR "/sample_data/paper-2018");

}  // namespace bs::test
