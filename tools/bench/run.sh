#!/usr/bin/env bash
# tools/bench/run.sh - `make bench`: the Delaunay build benchmark.
#
#   1. host: build/bench/delaunay-host (tools/bench/delaunay.cpp, linked with
#      build/host/libvor.a) times vor, CGAL and Boost.Polygon on 10^4, 10^5
#      and 10^6 sites of four input kinds and measures their memory;
#   2. targets: bench/delaunay.c under QEMU -icount on Cortex-M0, Cortex-M3
#      and RISC-V 32 gives instructions per inserted site for 1,000 and
#      10,000 sites.
#
# Prints both tables and writes them to build/bench/delaunay.md. Extra
# arguments go to the host program (e.g. --sizes 10000,100000 --reps 1).
# Dependencies: tools/bench/install-deps.sh and tools/install-toolchain.sh
# (`make bench` runs both first). Exit status 1 if a check failed.
set -eu
cd "$(dirname "$0")/../.."
out=build/bench
mkdir -p "$out"
ports="cortex-m0 cortex-m3 riscv32"

# Build everything first, so that nothing compiles while the clock runs.
# SANITIZE= : benchmarks use the release builds even under `make SANITIZE=1 bench`.
make -s -j"$(nproc)" PORT=host SANITIZE= build/host/libvor.a build/bench/delaunay-host
for port in $ports; do
    make -s -j"$(nproc)" PORT="$port" SANITIZE= "build/$port/bench-delaunay.elf"
done

status=0
for port in $ports; do
    if ! make -s PORT="$port" SANITIZE= run-bench-delaunay >"$out/delaunay-$port.txt" ||
        ! grep -q '^bench valid ok' "$out/delaunay-$port.txt"; then
        echo "error: $port: bench-delaunay failed:" >&2
        cat "$out/delaunay-$port.txt" >&2
        status=1
    fi
done

rm -f "$out/delaunay-host.md" "$out/delaunay.md" # never report a stale table
host_status=0
build/bench/delaunay-host --out "$out/delaunay-host.md" "$@" \
    2> >(tee "$out/delaunay-host.log" >&2) >/dev/null || host_status=$?
[ -f "$out/delaunay-host.md" ] || exit 1
[ "$host_status" -eq 0 ] || status=1

{
    echo "Host (\`build/bench/delaunay-host\`, $(date -u +%F)):"
    echo
    cat "$out/delaunay-host.md"
    echo
    echo "Targets, vor_build instructions per inserted site (uniform full-range int32, QEMU -icount):"
    echo
    # shellcheck disable=SC2086  # ports is a word list on purpose
    python3 - "$out" $ports <<'PY'
import sys
out, ports = sys.argv[1], sys.argv[2:]
rows, value = [], {}
for port in ports:
    for line in open(f"{out}/delaunay-{port}.txt"):
        f = line.split()
        if len(f) == 5 and f[0] == "bench" and f[1].startswith("build"):
            key = (f[1], int(f[2]))
            if key not in rows:
                rows.append(key)
            value[key, port] = f[3]
order = {"build": "quadtree (default)", "build-input": "input order"}
print("| sites | order | " + " | ".join(ports) + " |")
print("|---|---|" + "---|" * len(ports))
for key in sorted(rows, key=lambda k: (k[1], k[0])):
    cells = [f"{key[1]:,}", order.get(key[0], key[0])] + [value.get((key, p), "-") for p in ports]
    print("| " + " | ".join(cells) + " |")
PY
} >"$out/delaunay.md"
cat "$out/delaunay.md"
exit "$status"
