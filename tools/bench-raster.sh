#!/bin/sh
# SPDX-License-Identifier: MIT
# tools/bench-raster.sh - `make bench-raster`: vor_raster's speed on the
# host (megapixels per second, 320x240 and 1920x1080) and instructions per
# pixel under QEMU -icount (320x240 RGB565 in 16-row bands), each against
# the brute-force path, from bench/raster.c. The lines go to stdout and to
# build/bench/raster.txt, from which docs/benchmarks.md is written.
set -eu
cd "$(dirname "$0")/.."
mkdir -p build/bench
out=build/bench/raster.txt
: >"$out"
for port in host cortex-m0 cortex-m3 riscv32; do
    make -s -j2 PORT=$port "build/$port/bench-raster$( [ $port = host ] || echo .elf)" >/dev/null
    echo "# $port" | tee -a "$out"
    make -s PORT=$port run-bench-raster | tee -a "$out"
done
