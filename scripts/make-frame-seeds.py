#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
# Writes the small PNG and TIFF files under tests/data/importers/frames/{png,tiff}/: valid images of every layout
# the PNG/TIFF importers accept (grey/colour, 8/16 bit, sBIT, alpha, palette; strips and tiles, both byte orders),
# the seeds of the png and tiff fuzz targets (tests/fuzz/targets.txt) and fixtures for the importer tests.
# Also two images well formed on the outside that the decoder or the importer then refuses (a damaged IDAT stream,
# 32-bit float samples): seeds of the fuzz targets in tests/fuzz/seeds/{png,tiff}/.
# Standard library only: PNG is zlib + CRC-32, TIFF a handful of directory entries. Deterministic output.
import os
import struct
import zlib

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "data", "importers", "frames")
SEEDS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "fuzz", "seeds")


def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)


def png(name, width, height, bit_depth, colour_type, channels, extra=b"", damage=False, folder=None):
    bytes_per_sample = 2 if bit_depth == 16 else 1
    rows = b""
    for y in range(height):
        row = b"\x00"  # filter type 0
        for x in range(width):
            for c in range(channels):
                v = (x * 37 + y * 91 + c * 53) % (1 << min(bit_depth, 8))
                row += v.to_bytes(bytes_per_sample, "big") if bytes_per_sample == 2 else bytes([v])
        rows += row
    ihdr = struct.pack(">IIBBBBB", width, height, bit_depth, colour_type, 0, 0, 0)
    idat = zlib.compress(rows, 9)
    if damage:  # the chunk chain stays intact (CRCs right); the deflate stream inside it does not
        idat = idat[:2] + bytes((b * 7 + 3) % 256 for b in idat[2:])
    data = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + extra + chunk(b"IDAT", idat)
    data += chunk(b"IEND", b"")
    with open(os.path.join(folder or os.path.join(ROOT, "png"), name), "wb") as f:
        f.write(data)


def tiff(name, big_endian, width, height, bits, spp, tile=None, strips=1, sample_format=None, folder=None):
    e = ">" if big_endian else "<"
    bps = bits // 8
    pixels = bytes(((x * 37 + y * 91 + c * 53) % 256) for y in range(height) for x in range(width) for c in range(spp * bps))
    header = (b"MM\x00*" if big_endian else b"II*\x00") + struct.pack(e + "I", 8)
    entries = []  # (tag, type, count, value bytes)

    def short(tag, *vals):
        entries.append((tag, 3, len(vals), struct.pack(e + "%dH" % len(vals), *vals)))

    def long(tag, *vals):
        entries.append((tag, 4, len(vals), struct.pack(e + "%dI" % len(vals), *vals)))

    if tile:
        tw, th = tile
        across, down = (width + tw - 1) // tw, (height + th - 1) // th
        pieces = []
        for ty in range(down):
            for tx in range(across):
                t = b""
                for y in range(ty * th, ty * th + th):
                    for x in range(tx * tw, tx * tw + tw):
                        if y < height and x < width:
                            i = (y * width + x) * spp * bps
                            t += pixels[i:i + spp * bps]
                        else:
                            t += b"\x00" * (spp * bps)
                pieces.append(t)
    else:
        rows_per = (height + strips - 1) // strips
        row_bytes = width * spp * bps
        pieces = [pixels[s * rows_per * row_bytes:(s + 1) * rows_per * row_bytes] for s in range(strips)]
    n_entries = 9 + (2 if tile else 1) + (1 if sample_format else 0)
    ifd_size = 2 + 12 * n_entries + 4
    data_at = 8 + ifd_size + 64  # room for out-of-line values
    offsets, at = [], data_at
    for p in pieces:
        offsets.append(at)
        at += len(p)
    short(256, width)
    short(257, height)
    short(258, *([bits] * spp))
    short(259, 1)
    short(262, 2 if spp == 3 else 1)
    short(277, spp)
    short(284, 1)
    if sample_format:
        short(339, *([sample_format] * spp))
    if tile:
        short(322, tile[0])
        short(323, tile[1])
        long(324, *offsets)
        long(325, *[len(p) for p in pieces])
    else:
        short(278, rows_per)
        long(273, *offsets)
        long(279, *[len(p) for p in pieces])
    entries.sort()
    ifd = struct.pack(e + "H", len(entries))
    out_of_line = b""
    ool_at = 8 + 2 + 12 * len(entries) + 4
    for tag, typ, count, value in entries:
        if len(value) <= 4:
            ifd += struct.pack(e + "HHI", tag, typ, count) + value.ljust(4, b"\x00")
        else:
            ifd += struct.pack(e + "HHII", tag, typ, count, ool_at + len(out_of_line))
            out_of_line += value
    ifd += struct.pack(e + "I", 0)
    body = header + ifd + out_of_line
    assert len(body) <= data_at, name
    body = body.ljust(data_at, b"\x00") + b"".join(pieces)
    with open(os.path.join(folder or os.path.join(ROOT, "tiff"), name), "wb") as f:
        f.write(body)


png("grey-8bit-4x3.png", 4, 3, 8, 0, 1)
png("grey-16bit-sbit12-4x3.png", 4, 3, 16, 0, 1, chunk(b"sBIT", b"\x0c"))
png("rgb-8bit-3x2.png", 3, 2, 8, 2, 3)
png("rgba-8bit-2x2.png", 2, 2, 8, 6, 4)
png("grey-alpha-8bit-2x2.png", 2, 2, 8, 4, 2)
png("palette-2x2.png", 2, 2, 8, 3, 1, chunk(b"PLTE", bytes(i % 256 for i in range(3 * 256))))
tiff("grey-8bit-le-4x3.tif", False, 4, 3, 8, 1)
tiff("grey-16bit-be-4x4-2strips.tif", True, 4, 4, 16, 1, strips=2)
tiff("rgb-8bit-le-3x2.tif", False, 3, 2, 8, 3)
tiff("grey-8bit-le-tiled-20x20.tif", False, 20, 20, 8, 1, tile=(16, 16))
png("damaged-idat-4x3.png", 4, 3, 8, 0, 1, damage=True, folder=os.path.join(SEEDS, "png"))
tiff("float32-le-2x2.tif", False, 2, 2, 32, 1, sample_format=3, folder=os.path.join(SEEDS, "tiff"))
