// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// PNG and TIFF frames, decoded by OpenCV's imgcodecs (8- and 16-bit, grey or colour; alpha is dropped). Before
// OpenCV sees the file, its structure is checked here: the PNG chunk chain (every chunk inside the file, IHDR
// first, IEND present) or the TIFF header, first IFD and strip/tile extents, so a truncated file or a header
// claiming a giant image is refused with the file, the offset and the reason, before any pixel buffer exists.
// A grey image is taken as a BGGR Bayer mosaic (how raw captures are saved); PNG's sBIT chunk gives the
// significant bits of a 16-bit capture (10 or 12).
#include "common/format_importer.h"

namespace bs {

extern const FileFormat kPngFileFormat;

extern const FileFormat kTiffFileFormat;

}  // namespace bs
