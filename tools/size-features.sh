#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# tools/size-features.sh TARGET... - `make size`, second table: what a
# firmware pays for each feature set it uses, at -Os and -O2.
#
# Each program in bench/size/ calls one feature set on inputs the compiler
# cannot see; it is linked like a firmware (the port's startup and linker
# script, --gc-sections) against the library compiled at that level, and
# the library's share of the image is read from the linker map:
#
#   flash       bytes of .text/.rodata/.data input sections from libvor.a
#   static RAM  bytes of .data/.bss input sections from libvor.a
#   stack       the deepest chain (tools/stack-depth.py, -fcallgraph-info)
#               of the public functions the program calls
#
# Port code and the program's own code are not counted. The library and
# the programs are compiled with the Makefile's own $(CC), $(LIB_CFLAGS)
# and $(TEST_CFLAGS) (tools/size-features.mk includes the Makefile), with
# OPT set per level.
#
# tools/size-features.sh --check TARGET (`make test`): links the programs
# at -Os and checks that each keeps only the library files its feature
# set needs (the table of LINKS below); prints "N passed, N failed".
#
# Exit status: 0 all good; 1 a build failed, a stack depth is unknown or
# a check failed.
set -eu
cd "$(dirname "$0")/.."

check=0
if [ "${1-}" = "--check" ]; then
    check=1
    shift
fi
if [ $# -eq 0 ]; then
    echo "usage: tools/size-features.sh [--check] TARGET..." >&2
    exit 2
fi

# The library files (src/NAME.c) each program may link; any other file in
# its image is a dependency that should not be there, and every listed
# file must be there (so the list stays true). everything: all of
# sources.txt.
ALL_FILES=$(sed -n 's|^src/\(.*\)\.c$|\1|p' sources.txt | tr '\n' ' ')
links() {
    case $1 in
    insert_nearest) echo "bucket_grid incremental mesh predicates queries" ;;
    build_nearest)  echo "bucket_grid incremental insertion_order mesh predicates queries" ;;
    locate)         echo "bucket_grid incremental insertion_order mesh predicates queries" ;;
    move)           echo "bucket_grid dynamic incremental mesh predicates queries" ;;
    geometry)       echo "bucket_grid geometry incremental insertion_order mesh predicates queries" ;;
    clip)           echo "bucket_grid geometry incremental insertion_order mesh predicates" ;;
    order)          echo "bucket_grid geometry incremental insertion_order mesh predicates queries" ;;
    constrain)      echo "bucket_grid cdt crossing dynamic incremental insertion_order mesh predicates" ;;
    power)          echo "bucket_grid dynamic incremental insertion_order mesh power predicates queries" ;;
    power_cells)    echo "bucket_grid dynamic geometry incremental insertion_order mesh power predicates queries" ;;
    interpolate)    echo "bucket_grid incremental insertion_order interpolate mesh predicates queries" ;;
    laplace)        echo "bucket_grid incremental insertion_order interpolate mesh predicates queries" ;;
    field)          echo "bucket_grid field incremental insertion_order interpolate mesh predicates queries raster" ;;
    raster_euclid)  echo "raster raster_euclid" ;;
    raster_all)     echo "predicates raster raster_euclid raster_metrics" ;;
    raster_korder)  echo "predicates raster raster_metrics" ;;
    everything)     echo "$ALL_FILES" ;;
    esac
}

# The library files (without .c) with bytes in a linked image, from its map.
map_files() {
    python3 - "$1" <<'PY'
import re, sys
files = set()
kept = False
for line in open(sys.argv[1]):
    if line.startswith("Linker script and memory map"):
        kept = True
    m = re.search(r"0x[0-9a-f]+\s+0x([0-9a-f]+)\s+\S*size-lib\.a\((\w+)\.o\)", line)
    if kept and m and int(m.group(1), 16) > 0:
        files.add(m.group(2))
print(" ".join(sorted(files)))
PY
}
# In the order of the table: from the smallest firmware to everything.
FEATURES="insert_nearest build_nearest locate move geometry clip order constrain power power_cells interpolate laplace field raster_euclid raster_all raster_korder everything"
LEVELS="-Os -O2"

# Sums the libvor input sections of a GNU ld map: "flash ram". An input
# section line is "[name] address size file"; a long name sits alone on
# the line before. Sections the linker discarded are listed before
# "Linker script and memory map" and are not counted.
map_sizes() {
    python3 - "$1" <<'PY'
import re, sys
flash = ram = 0
name = None
kept = False
for line in open(sys.argv[1]):
    if line.startswith("Linker script and memory map"):
        kept = True
        continue
    fields = line.split()
    if not kept or not fields:
        continue
    if fields[0].startswith(".") and len(fields) == 1:
        name = fields[0]
        continue
    if fields[0].startswith(".") and len(fields) >= 4:
        name, fields = fields[0], fields[1:]
    if len(fields) < 3 or not fields[0].startswith("0x") or not re.search(r"size-lib\.a\(", fields[2]):
        continue
    size = int(fields[1], 16)
    if re.match(r"\.(text|rodata)", name):
        flash += size
    elif re.match(r"\.s?data", name):
        flash += size
        ram += size
    elif re.match(r"\.s?bss", name):
        ram += size
print(flash, ram)
PY
}

status=0
if [ $check -eq 1 ]; then
    passed=0
    failed=0
    for t in "$@"; do
        dir=build/size-features/$t-Os
        if ! make -s -f tools/size-features.mk PORT="$t" OPT=-Os B="$dir" vor-features; then
            echo "FAIL $t: the feature programs did not build"
            failed=$((failed + 1))
            continue
        fi
        for f in $FEATURES; do
            got=$(map_files "$dir/size-$f.map")
            want=$(tr ' ' '\n' <<<"$(links "$f")" | sed '/^$/d' | sort | tr '\n' ' ')
            if [ "$got " = "$want" ]; then
                passed=$((passed + 1))
            else
                echo "FAIL $t $f links: $got; expected: $want"
                failed=$((failed + 1))
            fi
        done
    done
    echo "$passed passed, $failed failed"
    [ "$failed" = 0 ]
    exit
fi

rows=()
for t in "$@"; do
    for level in $LEVELS; do
        dir=build/size-features/$t$level
        if ! make -s -f tools/size-features.mk PORT="$t" OPT="$level" B="$dir" vor-features >&2; then
            echo "size-features: $t $level: build failed" >&2
            status=1
            continue
        fi
        # a program that never attaches constraint memory never runs the
        # upkeep its calls reach through a pointer: its depths leave the
        # constraints' files out (tools/stack-depth.py --without)
        attached=$(python3 tools/stack-depth.py "$dir/lib" 2>/dev/null) || status=1
        bare=$(python3 tools/stack-depth.py --without cdt.c,crossing.c "$dir/lib" 2>/dev/null) ||
            status=1
        for f in $FEATURES; do
            read -r flash ram < <(map_sizes "$dir/size-$f.map")
            # the public functions the program calls, and the deepest of them
            calls=$(nm -u "$dir/size-$f.o" | awk '$2 ~ /^vor_[a-z]/ { print $2 }')
            depths=$bare
            grep -qx vor_cdt_attach <<<"$calls" && depths=$attached
            stack=0
            for c in $calls; do
                d=$(awk -v fn="$c" '$1 == fn { print $2; exit }' <<<"$depths")
                [ -n "$d" ] || { echo "size-features: no stack depth for $c" >&2; status=1; continue; }
                [ "${d#>=}" -gt "$stack" ] && stack=${d#>=}
            done
            rows+=("$t|$level|$f|$flash|$ram|$stack")
        done
    done
done

printf '%-11s %-4s %-15s %10s %15s %10s\n' target opt "feature set" "flash (B)" "static RAM (B)" "stack (B)"
for row in "${rows[@]}"; do
    IFS='|' read -r t level f flash ram stack <<<"$row"
    printf '%-11s %-4s %-15s %10s %15s %10s\n' "$t" "$level" "$f" "$flash" "$ram" "$stack"
done
echo "Library bytes in a firmware linked with --gc-sections (port and program excluded); stack: deepest public call the program makes (interrupts on top)."
exit $status
