// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Internal to benchscope_vision: the vectorised row kernel of FusedTable and the packed table entry it reads.
#include <cstddef>
#include <cstdint>

namespace bs::vision::detail {

// The vectorised path reads one 32-bit entry per output pixel and one FusedBlock per 16 output pixels of a row.
//
// Gather blocks (rows == 0): bits 0-21 hold the mosaic offset (y0 - 1) * width + (x0 - 1) of the 4x4 window around
// the bilinear taps (x0, y0)..(x0 + 1, y0 + 1); its row parity is found as floor((offset + 0.5) / width) in float,
// exact while width * height < 2^22 (the rounding error stays below 0.5 / width).
// Tiled blocks (rows 1..kMaxTileRows): the 16 windows lie in a tile of `rows` + 3 mosaic rows and `bytes` (<= 64)
// columns starting at `base`; bits 0-5 hold the window's column in the tile, bits 6-8 its row, bit 9 and bit 10
// the parity of its mosaic column and row. The tile's rows are loaded whole and each pixel's 4 bytes picked with
// one byte permutation (AVX-512 VBMI) instead of gathered: gathers cost two thirds of the time otherwise.
// Both: bits 22-26 the x and bits 27-31 the y fraction in 1/32 pixel. kPackedSpecial marks a pixel the scalar
// code writes (no source, or a window that leaves the mosaic).
constexpr std::uint32_t kPackedSpecial = 0xFFFFFFFFu;
constexpr int kPackedOffsetBits = 22;
constexpr std::int64_t kPackedMaxPixels = (std::int64_t{1} << kPackedOffsetBits) - 2;
constexpr int kBlockPixels = 16;
constexpr int kMaxTileRows = 6;  // a tile of up to 6 + 3 rows still costs less than 4 gathers

struct FusedBlock {
  std::int32_t base = 0;   // tiled: mosaic offset of the tile's top-left byte
  std::uint8_t rows = 0;   // 0: gather block; else distinct window rows in the tile
  std::uint8_t bytes = 0;  // tiled: columns to load (<= 64)
};

// True when this CPU runs the vector kernel: AVX-512 F + BW + VBMI (Ice Lake, Sapphire Rapids, Zen 4 and later;
// Skylake-X and Cascade Lake lack VBMI and take the scalar path).
bool fused_avx512_supported();

// Writes `count` BGR pixels of one output row from the entries `lut` and the row's blocks (special entries get
// arbitrary values, the caller overwrites them). `blue_col`/`blue_row`: parity of the columns/rows that carry blue.
void fused_row_avx512(const std::uint32_t* lut, const FusedBlock* blocks, int count, const std::uint8_t* mosaic,
                      int width, int blue_col, int blue_row, std::uint8_t* out);

}  // namespace bs::vision::detail
