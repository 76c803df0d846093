// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// How a verdict of every requirement judged per platform reads (the control loop, headroom/loop_requirement.h;
// sustained performance, sustain/sustain_requirement.h). Their texts split into terms with util/text.h's
// comma_terms.
#include <string_view>

namespace bs {

// "passes", "FAILS", "unknown": a verdict's status (an enum with Pass, Fail and Unknown) as the tables and the
// decision say it; the failure in capitals so that it stands out among passes.
template <class Status>
std::string_view requirement_status_text(Status s) {
  return s == Status::Pass ? "passes" : s == Status::Fail ? "FAILS" : "unknown";
}

}  // namespace bs
