// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Netpbm PGM (P5, grey) and PPM (P6, colour) with binary samples: header "P5 <width> <height> <maxval>" separated
// by whitespace, '#' comments to the end of a line, one whitespace byte, then the samples (1 byte each for
// maxval < 256, else 2 bytes big-endian, as the Netpbm specification says). The bit depth is the number of bits
// maxval needs (1023 -> 10). A PGM is taken as a Bayer mosaic, BGGR unless a comment says otherwise
// ("# pattern: RGGB", or "# pattern: grey" for a plain grey image), because that is how raw captures are saved.
// ASCII variants (P2, P3) and PAM (P7) are refused as unsupported.
#include "common/format_importer.h"

namespace bs {

extern const FileFormat kPnmFileFormat;

}  // namespace bs
