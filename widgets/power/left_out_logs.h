// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The power logs a view leaves out because they give no power, and why (issue #32.2): the Battery and Platforms
// tabs show this line where the log would have been, instead of dropping it without a word.
#include <QString>
#include <vector>

#include "model/power_trace.h"

namespace bs::ui {

// "Left out: otii (Jetson TX2): current only: no voltage channel and no supply voltage (right-click …)"; one
// line per log, empty when every log gives power.
QString left_out_logs_text(const std::vector<PowerTrace>& traces);

}  // namespace bs::ui
