// SPDX-License-Identifier: GPL-3.0-or-later
#include "headroom/headroom_args.h"

namespace bs::cli {

headroom::ProbeConfig probe_config(const ParsedArgs& args) {
  headroom::ProbeConfig c = commands::read_probe(args);
  if (const std::string e = headroom::validate(c); !e.empty()) throw UsageError(e);
  return c;
}

}  // namespace bs::cli
