#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# tools/peer-bench/run.sh - the benchmarks against other libraries, each a host
# program and a target program:
#
#   run.sh [delaunay] [ARGS...]   `make bench`: the Delaunay build.
#       host: build/bench/delaunay-host (tools/peer-bench/delaunay.cpp) times
#       vor (incremental and both divide-and-conquer variants), CGAL and
#       Boost.Polygon on 10^4, 10^5 and 10^6 sites of four input kinds and
#       measures their memory, then time per site for uniform n = 2^7 ...
#       2^20, plotted by tools/peer-bench/plot_scaling.py into
#       build/bench/delaunay-scaling.png;
#       targets: bench/delaunay.c under QEMU -icount on Cortex-M0, Cortex-M3
#       and RISC-V 32 gives instructions per inserted site for 1,000 and
#       10,000 sites (incremental in both orders, both D&C variants).
#   run.sh dynamic [ARGS...]      `make bench-dynamic`: removal and moves.
#       host: build/bench/dynamic-host (tools/peer-bench/dynamic.cpp) times
#       vor_remove and vor_move against CGAL's remove and move at 10^4,
#       10^5 and 10^6 sites (removals, small moves, large moves);
#       target: bench/dynamic.c under QEMU -icount on Cortex-M3 gives
#       instructions per insertion, remove, small and large move, and with
#       a motion cache per small move, fast move and control-loop move.
#   run.sh query [ARGS...]        `make bench-query`: nearest-site queries.
#       host: build/bench/query-host (tools/peer-bench/query.cpp) times vor,
#       nanoflann and CGAL on coherent and random queries over 10^3 to 10^6
#       sites and checks that their answers agree;
#       target: examples/robot_nearest under QEMU -icount on Cortex-M3
#       gives instructions per coherent query among 500 sites.
#   run.sh cdt [ARGS...]          `make bench-cdt`: constrained Delaunay.
#       host: build/bench/cdt-host (tools/peer-bench/cdt.cpp) times
#       vor_constrain against CGAL's Constrained_Delaunay_triangulation_2,
#       CDT and delaunay32 on disjoint and crossing segments among 10^4,
#       10^5 and 10^6 sites, medians of 5 runs;
#       target: bench/cdt.c under QEMU -icount on Cortex-M3 gives
#       instructions per constraint among 1,000 and 10,000 sites.
#   run.sh power [ARGS...]        `make bench-power`: weighted sites.
#       host: build/bench/power-host (tools/peer-bench/power.cpp) times
#       vor_power_build and vor_power_insert against CGAL's
#       Regular_triangulation_2 (Epick; range insert and one by one) at
#       10^5 and 10^6 sites, light and heavy weights, medians of 5 runs,
#       checks that both agree and measures their memory;
#       target: bench/power.c under QEMU -icount on Cortex-M3 gives
#       instructions per site of vor_power_build and vor_power_insert
#       among 1,000 and 10,000 sites.
#   run.sh interpolate [ARGS...]  `make bench-interpolate`: natural-neighbour
#       interpolation.
#       host: build/bench/interpolate-host (tools/peer-bench/interpolate.cpp)
#       times vor_interpolate and vor_interpolate_laplace against CGAL's
#       natural_neighbor_coordinates_2 and linear_interpolation (Epick and
#       Epeck) on 10^5 random queries among 10^4 and 10^5 sites, medians
#       of 3 runs, and checks that the values agree;
#       target: bench/interpolate.c under QEMU -icount on Cortex-M3 gives
#       instructions per query of vor_sibson, vor_laplace, vor_interpolate
#       and vor_interpolate_laplace among 1,000 and 10,000 sites.
#
# The host programs link build/host/libvor.a. Prints the tables and writes
# them to build/bench/NAME.md. ARGS go to the host program (e.g. --sizes
# 10000,100000 --reps 1). Dependencies: tools/install-deps.sh groups bench
# or bench-query, host, python, toolchains (make runs it first). Exit status
# 1 if a check failed.
set -eu
cd "$(dirname "$0")/../.."
out=build/bench
mkdir -p "$out"

bench=delaunay
case ${1:-} in
delaunay | query | dynamic | cdt | power | interpolate)
    bench=$1
    shift
    ;;
esac

# The target program (build/PORT/$target.elf, run by `make run-$target`),
# the ports it runs on, and the line its output must have.
case $bench in
delaunay)
    target=bench-delaunay
    ports="cortex-m0 cortex-m3 riscv32"
    target_ok='^bench valid ok'
    ;;
dynamic)
    target=bench-dynamic
    ports="cortex-m3"
    target_ok='^bench valid ok'
    ;;
cdt)
    target=bench-cdt
    ports="cortex-m3"
    target_ok='^bench valid ok'
    ;;
power)
    target=bench-power
    ports="cortex-m3"
    target_ok='^bench valid ok'
    ;;
interpolate)
    target=bench-interpolate
    ports="cortex-m3"
    target_ok='^bench valid ok'
    ;;
query)
    target=example-robot_nearest
    ports="cortex-m3"
    target_ok='brute force: all agree$'
    ;;
esac
host=build/bench/$bench-host

# Build everything first, so that nothing compiles while the clock runs.
# SANITIZE= : benchmarks use the release builds even under `make SANITIZE=1 bench`.
make -s -j"$(nproc)" PORT=host SANITIZE= build/host/libvor.a "$host"
for port in $ports; do
    make -s -j"$(nproc)" PORT="$port" SANITIZE= "build/$port/$target.elf"
done

status=0
for port in $ports; do
    if ! make -s PORT="$port" SANITIZE= "run-$target" >"$out/$bench-$port.txt" ||
        ! grep -q "$target_ok" "$out/$bench-$port.txt"; then
        echo "error: $port: $target failed:" >&2
        cat "$out/$bench-$port.txt" >&2
        status=1
    fi
done

rm -f "$out/$bench-host.md" "$out/$bench.md" # never report a stale table
host_args=()
if [ "$bench" = delaunay ]; then
    rm -f "$out/delaunay-scaling.csv" "$out/delaunay-scaling.png"
    host_args=(--scaling-csv "$out/delaunay-scaling.csv")
fi
host_status=0
"$host" --out "$out/$bench-host.md" "${host_args[@]}" "$@" \
    2> >(tee "$out/$bench-host.log" >&2) >/dev/null || host_status=$?
[ -f "$out/$bench-host.md" ] || exit 1
[ "$host_status" -eq 0 ] || status=1
# time per site against log2 n, as a plot (docs/delaunay-scaling.png is one)
if [ -f "$out/delaunay-scaling.csv" ]; then
    python3 tools/peer-bench/plot_scaling.py "$out/delaunay-scaling.csv" \
        "$out/delaunay-scaling.png" || status=1
fi

# The target table of each benchmark, from "$out/$bench-PORT.txt".
delaunay_targets() {
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
order = {"build": "quadtree (default)", "build-input": "input order",
         "build-dc": "D&C x-split", "build-dc-quadtree": "D&C quadtree"}
print("| sites | order | " + " | ".join(ports) + " |")
print("|---|---|" + "---|" * len(ports))
for key in sorted(rows, key=lambda k: (k[1], list(order).index(k[0]) if k[0] in order else 9)):
    cells = [f"{key[1]:,}", order.get(key[0], key[0])] + [value.get((key, p), "-") for p in ports]
    print("| " + " | ".join(cells) + " |")
# the targets of the performance issue (16): default build, per site
limit = {"cortex-m3": 3000, "cortex-m0": 9000}
print()
print("| port | sites | instructions / site | target | status |")
print("|---|---|---|---|---|")
for port in ports:
    for n in sorted({k[1] for k in rows}):
        v = value.get((("build", n), port))
        if v is None:
            continue
        if port in limit:
            verdict = "met" if float(v) <= limit[port] else "**not met**"
            print(f"| {port} | {n:,} | {v} | <= {limit[port]:,} | {verdict} |")
        else:
            print(f"| {port} | {n:,} | {v} | reported | - |")
PY
}

query_targets() {
    echo "Targets, instructions per coherent query (examples/robot_nearest: 500 sites, vor_track, net of the counter's own reads, QEMU -icount; hinted vor_nearest for comparison):"
    echo
    echo "| port | vor_track instructions per query | hinted vor_nearest | issue 4 target | status |"
    echo "|---|---|---|---|---|"
    for port in $ports; do
        count=$(sed -n 's/^ *vor_track: \([0-9][0-9]*\) instructions per query.*/\1/p' "$out/query-$port.txt")
        hinted=$(sed -n 's/.*vor_nearest with the last answer as hint: \([0-9][0-9]*\).*/\1/p' "$out/query-$port.txt")
        verdict="**not met**"
        if [ -z "$count" ]; then
            count="-" verdict="no figure"
            status=1
        elif [ "$count" -le 150 ]; then
            verdict="met"
        fi
        echo "| $port | $count | ${hinted:--} | <= 150 | $verdict |"
    done
}

dynamic_targets() {
    echo "Targets, instructions per operation on 1,000 sites (bench/dynamic.c, QEMU -icount):"
    echo
    # shellcheck disable=SC2086  # ports is a word list on purpose
    python3 - "$out" $ports <<'PY' || status=1
import sys
out, ports = sys.argv[1], sys.argv[2:]
cost = {}
for port in ports:
    for line in open(f"{out}/dynamic-{port}.txt"):
        f = line.split()
        if len(f) == 5 and f[0] == "bench":
            cost[port, f[1]] = float(f[3])
ok = True

def row(port, need, cells):
    """One table row, or "no figures" (and a failed exit) if one is missing."""
    global ok
    if not all((port, k) in cost for k in need):
        ok = False
        return f"| {port} | no figures |"
    return f"| {port} | " + " | ".join(cells({k: cost[port, k] for k in need})) + " |"

print("| port | insert | remove | small move, no cache | large move | remove <= 2x insert |")
print("|---|---|---|---|---|---|")
for port in ports:
    print(row(port, ("insert", "remove", "small-move", "large-move"), lambda c: [
        f"{c['insert']:.1f}", f"{c['remove']:.1f}", f"{c['small-move']:.1f}",
        f"{c['large-move']:.1f}",
        ("met" if c["remove"] <= 2 * c["insert"] else "**not met**")
        + f" ({c['remove'] / c['insert']:.2f}x)"]))
print()
print("With a motion cache (vor_motion_attach): the small moves again, and a control loop of")
print("20 rounds where every site steps up to 1/10,000 of the spacing:")
print()
print("| port | small move, cached | fast move | control loop, per move | fast moves | fast move <= 400 |")
print("|---|---|---|---|---|---|")
for port in ports:
    print(row(port, ("small-move-cached", "fast-move", "robot-loop", "fast-fraction"), lambda c: [
        f"{c['small-move-cached']:.1f}", f"{c['fast-move']:.1f}", f"{c['robot-loop']:.1f}",
        f"{c['fast-fraction']:.1f} %", "met" if c["fast-move"] <= 400 else "**not met**"]))
sys.exit(0 if ok else 1)
PY
}

cdt_targets() {
    echo "Targets, instructions per operation (bench/cdt.c, QEMU -icount):"
    echo
    # shellcheck disable=SC2086  # ports is a word list on purpose
    python3 - "$out" $ports <<'PY' || status=1
import sys
out, ports = sys.argv[1], sys.argv[2:]
ok = True
print("| port | sites | vor_build / site | vor_cdt_attach / site | vor_constrain, disjoint | vor_constrain, crossing | crossings / segments | constraint memory (B) |")
print("|---|---|---|---|---|---|---|---|")
for port in ports:
    rows = {}
    for line in open(f"{out}/cdt-{port}.txt"):
        f = line.split()
        if len(f) >= 4 and f[0] == "bench" and f[1] != "valid":
            rows.setdefault(f[1], []).append(f[2:])
    need = ("build", "attach", "constrain-disjoint", "constrain-crossing", "crossings", "memory")
    if not all(k in rows and len(rows[k]) == len(rows["build"]) for k in need):
        print(f"| {port} | no figures |")
        ok = False
        continue
    for i, (n, build, _) in enumerate(rows["build"]):
        segs, crossings = rows["crossings"][i]
        print(f"| {port} | {int(n):,} | {build} | {rows['attach'][i][1]} | "
              f"{rows['constrain-disjoint'][i][1]} | {rows['constrain-crossing'][i][1]} | "
              f"{int(crossings):,} / {int(segs):,} | {int(rows['memory'][i][1]):,} |")
sys.exit(0 if ok else 1)
PY
}

power_targets() {
    echo "Targets, instructions per site (bench/power.c, QEMU -icount):"
    echo
    # shellcheck disable=SC2086  # ports is a word list on purpose
    python3 - "$out" $ports <<'PY' || status=1
import sys
out, ports = sys.argv[1], sys.argv[2:]
ok = True
print("| port | sites | weights | hidden | vor_power_build / site | vor_power_insert / site | insert / build | arena (B) |")
print("|---|---|---|---|---|---|---|---|")
for port in ports:
    cost, hidden, memory, sizes = {}, {}, {}, []
    for line in open(f"{out}/power-{port}.txt"):
        f = line.split()
        if len(f) < 4 or f[0] != "bench" or f[1] == "valid":
            continue
        n = int(f[2])
        if f[1] == "memory":
            memory[n] = int(f[3])
            continue
        what, _, kind = f[1].partition("-")
        if n not in sizes:
            sizes.append(n)
        if what == "hidden":
            hidden[n, kind] = int(f[3])
        else:
            cost[n, kind, what] = float(f[3])
    rows = 0
    for n in sizes:
        for kind, label in (("light", "< s^2 / 100"), ("heavy", "< s^2")):
            if not all((n, kind, w) in cost for w in ("build", "insert")) or (n, kind) not in hidden:
                continue
            b, i = cost[n, kind, "build"], cost[n, kind, "insert"]
            h = hidden[n, kind]
            print(f"| {port} | {n:,} | {label} | {h:,} ({100 * h / n:.1f} %) | {b:.1f} | {i:.1f} | "
                  f"{i / b:.2f} | {memory.get(n, 0):,} |")
            rows += 1
    if rows == 0:
        print(f"| {port} | no figures |")
        ok = False
sys.exit(0 if ok else 1)
PY
}

interpolate_targets() {
    echo "Targets, instructions per query (bench/interpolate.c, QEMU -icount):"
    echo
    # shellcheck disable=SC2086  # ports is a word list on purpose
    python3 - "$out" $ports <<'PY' || status=1
import sys
out, ports = sys.argv[1], sys.argv[2:]
ok = True
calls = ("sibson", "laplace", "interpolate", "interpolate-laplace")
print("| port | sites | queries | neighbours | vor_sibson | vor_laplace | vor_interpolate | vor_interpolate_laplace | Sibson / Laplace |")
print("|---|---|---|---|---|---|---|---|---|")
for port in ports:
    cost, k, sizes = {}, {}, []
    for line in open(f"{out}/interpolate-{port}.txt"):
        f = line.split()
        if len(f) < 4 or f[0] != "bench" or f[1] == "valid":
            continue
        n = int(f[2])
        if n not in sizes:
            sizes.append(n)
        if f[1] == "neighbours":
            k[n] = (f[3], int(f[4]), int(f[5]))
        else:
            cost[n, f[1]] = float(f[3])
    rows = 0
    for n in sizes:
        for suffix in ("", "-k6"):
            if n not in k or not all((n, c + suffix) in cost for c in calls):
                continue
            c = [cost[n, name + suffix] for name in calls]
            queries, what = (f"{k[n][2]:,}", f"{k[n][0]} (mean)") if suffix == "" else (f"{k[n][1]:,} of them", "6")
            print(f"| {port} | {n:,} | {queries} | {what} | " + " | ".join(f"{v:,.0f}" for v in c)
                  + f" | {c[2] / c[3]:.2f} |")
            rows += 1
    if rows == 0:
        print(f"| {port} | no figures |")
        ok = False
sys.exit(0 if ok else 1)
PY
}

{
    echo "Host (\`$host\`, $(date -u +%F)):"
    echo
    cat "$out/$bench-host.md"
    echo
    "${bench}_targets"
} >"$out/$bench.md"
cat "$out/$bench.md"
exit "$status"
