// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The name of an import that a front end measured in-process (#52's one way home): who measured it, on which
// computer and when, "Kernel Runner (robot-nuc, 2026-12-06T10:00:00Z)". Every kind's batch builder (flops_home,
// headroom_import, sustain_import, ...) names its import with it, so the workspace lists measurements alike whichever
// front end or kind stored them.
#include <string>
#include <string_view>

namespace bs {

// `where`: the front end and its place ("Kernel Runner", "benchscope-cli run flops"); `platform`: the computer the
// measurement ran on; `date`: when it began (the record's provenance date).
std::string home_name(std::string_view where, std::string_view platform, std::string_view date);

}  // namespace bs
