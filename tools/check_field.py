#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""check_field.py [--every N] [PREFIX] - checks the VALUE frame examples/field
wrote (PREFIX.values, default build/field.values) against an exact brute
force: the Sibson coordinates of tools/gen_interpolate_vectors.py (exact
rational clipping with fractions.Fraction, independent of the library)
from the sensors of PREFIX.sensors.

PREFIX.sensors holds "frame OX OY SX SY W H", "outside V" and one
"s X Y VALUE" line per sensor; PREFIX.values is the frame's int32 values,
little-endian, row-major. The pixels checked are those of every Nth row
and every Nth column (N = 8 by default, about 1,200 of the 320 x 240
frame), plus every sensor's pixel: inside the sensors' convex hull each
must be sum(lambda_i value_i) rounded once, halves away from zero;
outside, the outside value. Prints what it checked; exits 1 on any
mismatch (each printed), 2 on a malformed input.
"""
import os
import struct
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gen_interpolate_vectors import field_value, natural  # noqa: E402 (the one brute force)


def read_sensors(path):
    frame, outside, sites, values = None, None, [], []
    with open(path) as f:
        for line in f:
            words = line.split()
            if not words or words[0].startswith("#"):
                continue
            if words[0] == "frame" and len(words) == 7:
                frame = tuple(int(w) for w in words[1:])
            elif words[0] == "outside" and len(words) == 2:
                outside = int(words[1])
            elif words[0] == "s" and len(words) == 4:
                sites.append((int(words[1]), int(words[2])))
                values.append(int(words[3]))
            else:
                sys.exit(f"error: {path}: cannot read {line.strip()!r}")
    if frame is None or outside is None or not sites:
        sys.exit(f"error: {path}: no frame, outside value or sensor")
    if len(set(sites)) != len(sites):
        sys.exit(f"error: {path}: two sensors at one point")
    return frame, outside, sites, values


def main():
    args = sys.argv[1:]
    every = 8
    if len(args) >= 2 and args[0] == "--every":
        every = int(args[1])
        args = args[2:]
    if len(args) > 1 or every < 1:
        sys.exit(__doc__)
    prefix = args[0] if args else "build/field"
    frame, outside, sites, values = read_sensors(prefix + ".sensors")
    ox, oy, sx, sy, w, h = frame
    data = open(prefix + ".values", "rb").read()
    if len(data) != 4 * w * h:
        sys.exit(f"error: {prefix}.values has {len(data)} bytes, expected {4 * w * h}")
    frame_values = struct.unpack(f"<{w * h}i", data)

    pixels = {(i, j) for j in range(0, h, every) for i in range(0, w, every)}
    for x, y in sites:  # every sensor on a pixel centre of the frame
        i, j = (x - ox) // sx, (y - oy) // sy
        if (x - ox) % sx == 0 and (y - oy) % sy == 0 and 0 <= i < w and 0 <= j < h:
            pixels.add((i, j))
    inside = wrong = 0
    for i, j in sorted(pixels, key=lambda p: (p[1], p[0])):
        q = (ox + i * sx, oy + j * sy)
        want, neighbours = field_value(sites, values, q, natural)
        if neighbours == 0:
            want = outside
        else:
            inside += 1
        got = frame_values[j * w + i]
        if got != want:
            wrong += 1
            print(f"FAIL pixel ({i}, {j}) at {q}: {prefix}.values has {got}, "
                  f"the brute force {want}")
    print(f"check_field: {len(pixels)} pixels of the {w}x{h} frame (one row and column in "
          f"{every}, and the {len(sites)} sensors' pixels; {inside} inside the hull, "
          f"{len(pixels) - inside} outside) against the exact Sibson brute force of "
          f"tools/gen_interpolate_vectors.py: "
          + ("all equal" if wrong == 0 else f"{wrong} DIFFER"))
    sys.exit(1 if wrong else 0)


if __name__ == "__main__":
    main()
