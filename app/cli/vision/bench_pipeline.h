// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <iosfwd>
#include <string>
#include <vector>

namespace bs::cli {

// `benchscope-cli bench pipeline`: the vision pipeline's stages run one after another on one thread against the
// concurrent pipeline (capture, preprocessing, N detection workers), same frames, same stage functions, same
// process; prints per-stage times, both throughputs, their ratio and the theoretical bound.
int bench_pipeline(const std::vector<std::string>& args, std::ostream& out);

}  // namespace bs::cli
