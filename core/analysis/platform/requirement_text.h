// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A verdict of every requirement judged per platform (the control loop, headroom/loop_requirement.h; sustained
// performance, sustain/sustain_requirement.h): its status, and how it reads. Their texts split into terms with
// util/text.h's comma_terms.
#include <string_view>

namespace bs {

// Whether a platform meets a requirement; unknown when its records cannot tell (none measured, or a term the record
// does not answer).
enum class RequirementStatus { Pass, Fail, Unknown };

// "passes", "FAILS", "unknown", as the tables and the decision say it: the failure in capitals so that it stands out
// among passes.
inline std::string_view to_string(RequirementStatus s) {
  return s == RequirementStatus::Pass ? "passes" : s == RequirementStatus::Fail ? "FAILS" : "unknown";
}

}  // namespace bs
