// SPDX-License-Identifier: GPL-3.0-or-later
// The rotation kernel compiled for one instruction set; flags are set per file in CMakeLists.txt.
#define BS_SIMD_NS avx512
#define BS_SIMD_BYTES 64
#define BS_SIMD_CHAINS 8  // 8 chains x (x, y) state vectors + 2 constants + 2 temporaries fit its register file
#include "kernels/rotation/rotation_simd_impl.h"
