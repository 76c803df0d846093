// SPDX-License-Identifier: GPL-3.0-or-later
// The empirical-ceiling micro-kernels compiled for one instruction set; flags are set per file in CMakeLists.txt.
#define BS_SIMD_NS sse4
#define BS_SIMD_BYTES 16
#include "kernels/ceilings/ceiling_simd_impl.h"
