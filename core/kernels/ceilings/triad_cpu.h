// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <cstddef>

#include "util/cancel.h"

namespace bs::kernels {

// STREAM triad on the CPU with OpenMP (all threads, static schedule, first-touch initialisation by the same
// threads so pages sit on the right NUMA node), or on one thread. Returns the seconds of one timed pass.
double cpu_triad_seconds(std::size_t elements, bool all_threads, const CancelToken& cancel);

}  // namespace bs::kernels
