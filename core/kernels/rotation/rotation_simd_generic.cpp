// SPDX-License-Identifier: GPL-3.0-or-later
// The rotation kernel compiled for one instruction set; flags are set per file in CMakeLists.txt.
#define BS_SIMD_NS generic
#define BS_SIMD_BYTES 16
#if defined(__aarch64__)
#define BS_SIMD_CHAINS 8  // NEON has 32 vector registers
#else
#define BS_SIMD_CHAINS 6  // 6 chains x (x, y) state vectors + 2 constants + 2 temporaries fit 16 SSE registers
#endif
#include "kernels/rotation/rotation_simd_impl.h"
