#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# tools/size-report.sh [-v] TARGET... - `make size`: what vor costs on each
# target, as one table: flash, static RAM and worst-case stack depth.
#
#   flash       text + data of the objects in build/TARGET/libvor.a, from the
#               port's $(SIZE) (Berkeley format: text includes rodata; data
#               is counted because its initial values live in flash)
#   static RAM  data + bss of the same objects
#   worst stack the deepest call chain from any public vor_ function: the sum
#               of GCC's -fstack-usage frames along it (tools/stack-depth.py)
#
# All three are for the whole library; a firmware that links it with
# --gc-sections keeps only the functions it calls, so they are upper bounds.
# -v also prints, per target, every public function's depth and its chain.
#
# How: `make -s PORT=TARGET lib` builds the library as usual, and its
# archive is measured. The call graph needs GCC's -fcallgraph-info=su, which
# the Makefile's LIB_CFLAGS does not have (the host build may be clang), so
# the library's sources are compiled once more into build/size/TARGET/ with
# the Makefile's own rule inputs, $(CC) $(LIB_CFLAGS), plus that flag: a
# rule added with `make --eval`, so the flags can never drift from the real
# build. The fresh objects must match the archive's sizes, which also
# catches an archive left stale by a flags change (`make clean` fixes it).
#
# Exit status: 0 all good; 1 a build failed, or some target's stack depth
# is unknown or unbounded (dynamic stack, a call outside the library, an
# indirect call, recursion: details on stderr), or the archive is stale.
# The table is printed for every target that built either way.
set -eu
cd "$(dirname "$0")/.."

verbose=0
if [ "${1-}" = "-v" ]; then
    verbose=1
    shift
fi
if [ $# -eq 0 ]; then
    echo "usage: tools/size-report.sh [-v] TARGET..." >&2
    exit 2
fi

# Compiles src/*.c into $(VOR_SIZE_DIR) exactly like the Makefile's
# $(B)/lib/%.o rule, plus -fcallgraph-info=su (NAME.ci next to NAME.o), and
# prints the port's size tool. Recipes expand after the Makefile is read,
# so $(CC) and $(LIB_CFLAGS) are the Makefile's final values.
# shellcheck disable=SC2016  # make's $(...), not the shell's
size_rules='
vor-size-objs := $(patsubst src/%.c,$(VOR_SIZE_DIR)/%.o,$(filter src/%.c,$(file < sources.txt)))
.PHONY: vor-size-build vor-size-tool
vor-size-build: $(vor-size-objs)
$(VOR_SIZE_DIR)/%.o: src/%.c
	@mkdir -p $(@D)
	$(CC) $(LIB_CFLAGS) -fcallgraph-info=su -c $< -o $@
vor-size-tool:
	@echo $(SIZE)
'

# Sums a Berkeley-format `size` listing: "text data bss" on stdout.
sum_sizes() {
    awk '$1 ~ /^[0-9]+$/ { t += $1; d += $2; b += $3 } END { print t + 0, d + 0, b + 0 }'
}

status=0
rows=()
details=()
for t in "$@"; do
    dir=build/size/$t
    if ! make -s PORT="$t" lib >&2; then
        echo "size-report: $t: library build failed" >&2
        status=1
        rows+=("$t|-|-|-|build failed")
        continue
    fi
    rm -rf "$dir"
    mkdir -p "$dir"
    if ! make -s PORT="$t" VOR_SIZE_DIR="$dir" --eval "$size_rules" vor-size-build >&2; then
        echo "size-report: $t: call-graph build failed" >&2
        status=1
        rows+=("$t|-|-|-|build failed")
        continue
    fi
    size_tool=$(make -s PORT="$t" VOR_SIZE_DIR="$dir" --eval "$size_rules" vor-size-tool)

    read -r text data bss < <($size_tool "build/$t/libvor.a" | sum_sizes)
    read -r text2 data2 bss2 < <($size_tool "$dir"/*.o | sum_sizes)
    if [ "$text $data $bss" != "$text2 $data2 $bss2" ]; then
        echo "size-report: $t: build/$t/libvor.a ($text $data $bss) differs from a" \
             "fresh compile ($text2 $data2 $bss2); stale? try: make clean" >&2
        status=1
    fi

    # stack-depth.py: 0 known, 1 unknown (a lower bound, ">=N"), 2 no answer.
    set +e
    worst=$(python3 tools/stack-depth.py --worst "$dir")
    rc=$?
    set -e
    [ $rc -eq 0 ] || status=1
    case $rc in
        0|1) stack=${worst%% *} function=${worst#* } ;;
        *)   stack="unknown" function="(see errors above)" ;;
    esac
    if [ $verbose -eq 1 ] && [ $rc -le 1 ]; then
        details+=("" "$t:" "$(python3 tools/stack-depth.py "$dir" 2>/dev/null || true)")
    fi
    rows+=("$t|$((text + data))|$((data + bss))|$stack|$function")
done

line() { printf '%-12s %10s %15s %16s  %s\n' "$@"; }
line target "flash (B)" "static RAM (B)" "worst stack (B)" "deepest public call"
for row in "${rows[@]}"; do
    IFS='|' read -r t flash ram stack function <<<"$row"
    line "$t" "$flash" "$ram" "$stack" "$function"
done
echo "Whole libvor.a (--gc-sections keeps less): flash = text+rodata+data, RAM = data+bss;" \
     "stack = deepest chain of -fstack-usage frames from a public vor_ call (caller and interrupts not included)."
if [ ${#details[@]} -gt 0 ]; then
    printf '%s\n' "${details[@]}"
fi
exit $status
