// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Waiting for the Reprojection tuner's preview: it reprojects on a worker thread, and a test reads the output pane
// only once the image of the newest settings is shown (within `timeout_ms`, a failure of the test otherwise).
#include <QTest>

#include "vision/preview_pane.h"
#include "vision/reprojection_tuner.h"

namespace bs::test {

inline void wait_for_preview(ui::ReprojectionTuner& t, int timeout_ms = 30000) {
  QTRY_VERIFY_WITH_TIMEOUT(t.shown_generation() == t.requested_generation() && !t.output_pane()->image().isNull(),
                           timeout_ms);
}

}  // namespace bs::test
