// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// How a result set measured in-process goes home (#52's one way home, for this kind): the empirical ceilings of one
// device (the Kernel Runner's Measure ceilings, `benchscope-cli devices --measure-ceilings`, which measures every
// device at once and stores one import per device) and the STREAM triad of `benchscope-cli run bandwidth`. One
// recipe for all of them, so the same device's ceilings are recognised as the same import whichever front end stored
// them (the GUI hashed date + note, the CLI the dates and notes of all its devices together, so the CPU's ceilings
// stored by both became two imports).
#include <string>

#include "model/flops_run.h"
#include "store/home_batch.h"

namespace bs {

// One import of `set` in its own format (its source_format: kernels::kCeilingSource, kBandwidthSource), named
// after `where` ("Kernel Runner: Measure ceilings", "benchscope-cli run bandwidth"; util/home_name.h). The content
// hash is of everything the set holds: device, backend, provenance and every measured value.
HomeBatch measured_set_home(const ResultSet& set, const std::string& where);

}  // namespace bs
