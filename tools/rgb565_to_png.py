#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""rgb565_to_png.py IN.rgb565 W H OUT.png - turns a raw frame of native
little-endian RGB565 pixels (row 0 first), as the demo streams it out of
the microcontroller, into a PNG. Python's standard library only."""
import struct
import sys
import zlib


def main():
    src, w, h, dst = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), sys.argv[4]
    data = open(src, "rb").read()
    if len(data) != 2 * w * h:
        sys.exit(f"error: {src} has {len(data)} bytes, expected {2 * w * h}")
    rows = bytearray()
    for j in range(h):
        rows.append(0)  # filter: none
        for (p,) in struct.iter_unpack("<H", data[2 * w * j:2 * w * (j + 1)]):
            r, g, b = p >> 11, (p >> 5) & 0x3F, p & 0x1F
            rows += bytes(((r * 255 + 15) // 31, (g * 255 + 31) // 63, (b * 255 + 15) // 31))

    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))

    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(bytes(rows), 9)) + chunk(b"IEND", b"")
    open(dst, "wb").write(png)


if __name__ == "__main__":
    main()
