#!/usr/bin/env python3
"""Writes the PNG seeds of the weather_png corpus (committed under fuzz/corpus; run again only to
change them): small images of every colour type and bit depth PNG has, interlaced and not, so the
fuzzer starts from each of the decoder's paths.  python3 fuzz/tools/make_png_seeds.py fuzz/corpus
"""
import os
import struct
import sys
import zlib


def chunk(kind, data):
    body = kind + data
    return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)


def png(width, height, colour_type, depth, rows, palette=None, interlace=0, extra=b""):
    ihdr = struct.pack(">IIBBBBB", width, height, depth, colour_type, 0, 0, interlace)
    raw = b"".join(bytes([i % 5]) + row for i, row in enumerate(rows))  # every filter type
    out = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr)
    if palette:
        out += chunk(b"PLTE", palette)
    return out + extra + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")


def rows(width, height, channels, depth):
    bits_per_row = width * channels * depth
    nbytes = (bits_per_row + 7) // 8
    return [bytes((x * 37 + y * 11) & 0xFF for x in range(nbytes)) for y in range(height)]


def main():
    out = os.path.join(sys.argv[1] if len(sys.argv) > 1 else "fuzz/corpus", "weather_png")
    os.makedirs(out, exist_ok=True)
    channels = {0: 1, 2: 3, 3: 1, 4: 2, 6: 4}
    depths = {0: (1, 2, 4, 8, 16), 2: (8, 16), 3: (1, 2, 4, 8), 4: (8, 16), 6: (8, 16)}
    for colour, ds in depths.items():
        for depth in ds:
            w, h = 9, 7
            palette = bytes(range(48)) if colour == 3 else None
            data = png(w, h, colour, depth, rows(w, h, channels[colour], depth), palette)
            with open(os.path.join(out, f"type{colour}_{depth}bit.png"), "wb") as f:
                f.write(data)
    # Interlaced (Adam7) rows are laid out per pass; a plain layout of the right length is enough
    # for a seed, the decoder's checks do the rest.
    w, h = 16, 16
    with open(os.path.join(out, "rgb_interlaced.png"), "wb") as f:
        f.write(png(w, h, 2, 8, rows(w, h + 8, 3, 8), interlace=1))
    with open(os.path.join(out, "rgba_1x1.png"), "wb") as f:
        f.write(png(1, 1, 6, 8, [b"\x10\x20\x30\xff"]))
    with open(os.path.join(out, "rgb_transparency.png"), "wb") as f:
        f.write(png(4, 4, 2, 8, rows(4, 4, 3, 8), extra=chunk(b"tRNS", b"\x00\x01\x00\x02\x00\x03")))
    with open(os.path.join(out, "palette_transparency.png"), "wb") as f:
        f.write(png(4, 4, 3, 8, rows(4, 4, 1, 8), bytes(range(48)), extra=chunk(b"tRNS", b"\x80" * 4)))
    with open(os.path.join(out, "rgb_wide.png"), "wb") as f:
        f.write(png(64, 2, 2, 8, rows(64, 2, 3, 8)))


if __name__ == "__main__":
    main()
