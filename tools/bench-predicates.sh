#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# bench-predicates.sh - `make bench-predicates`: the cost of every predicate
# tier on the host (ns per call, best of 5 runs) and on Cortex-M0, Cortex-M3
# and RISC-V 32 (instructions per call, QEMU -icount), as one Markdown table.
set -eu
cd "$(dirname "$0")/.."
ports="host cortex-m0 cortex-m3 riscv32"
out=build/bench
mkdir -p "$out"
for port in $ports; do
    make -s -j"$(nproc)" PORT="$port" "build/$port/bench-predicates$([ "$port" = host ] || echo .elf)" >/dev/null
    runs=1
    [ "$port" = host ] && runs=5
    : >"$out/predicates-$port.txt"
    for _ in $(seq "$runs"); do
        make -s PORT="$port" run-bench-predicates >>"$out/predicates-$port.txt"
    done
    if grep -q 'bench tiers MISMATCH' "$out/predicates-$port.txt"; then
        echo "error: $port: benchmark inputs left their tier" >&2
        exit 1
    fi
done
python3 - "$out" $ports <<'PY'
import sys
out, ports = sys.argv[1], sys.argv[2:]
rows, best = [], {}
for port in ports:
    for line in open(f"{out}/predicates-{port}.txt"):
        f = line.split()
        if len(f) != 5 or f[0] != "bench":
            continue
        key = (f[1], f[2])
        if key not in rows:
            rows.append(key)
        value = float(f[3])
        best[key, port] = min(value, best.get((key, port), value))
head = ["predicate", "tier", "host ns"] + [f"{p} instr" for p in ports[1:]]
print("| " + " | ".join(head) + " |")
print("|" + "---|" * len(head))
for key in rows:
    cells = [key[0], key[1]] + [f"{best[key, p]:.1f}" if (key, p) in best else "-" for p in ports]
    print("| " + " | ".join(cells) + " |")
PY
