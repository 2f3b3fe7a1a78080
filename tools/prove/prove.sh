#!/bin/sh
# SPDX-License-Identifier: MIT
# tools/prove/prove.sh - `make prove`: Frama-C's EVA over each harness of
# tools/prove/ with the library sources, on a 32-bit machine (32-bit int
# and pointers, as on every target) and 32-bit limbs (Frama-C's front end
# has no __int128, so VOR_LIMB_BITS 64 cannot be parsed). Each report goes
# to build/prove/NAME.txt and its alarms, time and analysed functions are
# printed. Fails when any report shows an alarm, a warning or an unproven
# property, or when the harnesses together analyse less than 95 % of the
# library's functions; and runs tools/prove/filter_error.c, which proves
# the rounding filters' error bounds.
#   tools/prove/prove.sh [HARNESS...]   (default: every harness)
# Harnesses run PROVE_JOBS at a time (default: one a core); each is one
# Frama-C process of one thread.
# With harnesses named (make test's suite prove runs those that finish in
# about a minute), the share of functions is printed but not required.
# Ends with "N passed, M failed": one check per harness, and the share.
set -eu
self=$(cd "$(dirname "$0")" && pwd)/$(basename "$0")
cd "$(dirname "$0")/../.."
out=build/prove
mkdir -p "$out"
status=0
named=$#
passed=0
failed=0
harnesses=${*:-predicates predicates_os multiword multiword_armv6m diagram queries nearest_k locate geometry cells centroid clip order raster field interpolate large cdt power power_cells power_dynamic}

# Options every harness shares.
# -machdep x86_32 and __ARM_ARCH_PROFILE 'M' (below): the configuration of
#   the microcontroller targets, where the cache hints compile away
#   (VOR__PREFETCHING, src/mesh.h).
# typing:implicit-conv-void-ptr off: Frama-C warns on a void * passed to
#   an object pointer parameter, which C99 converts implicitly (6.3.2.3).
# -eva-precision 3: enough to follow the small fixed loops of the
#   multi-word arithmetic one iteration at a time (below it, merged
#   iterations read as maybe-uninitialised limbs); higher levels find
#   nothing more and cost minutes.
common="-machdep x86_32 -kernel-warn-key typing:implicit-conv-void-ptr=inactive
    -eva -eva-precision 3 -eva-no-show-progress"

# Per harness: the options it adds and the sources it needs.
options_of() {
    case $1 in
    predicates | predicates_os | multiword | multiword_armv6m) echo "" ;;
    # large, cells, centroid, cdt, power: every input concrete but a few
    # that end a call early (and power's inserts of any weight, each of
    # whose outcomes is then followed on its own), so every state can be
    # kept apart (a slevel no loop reaches) and EVA follows each build,
    # cell trace, constraint and flip exactly
    large | cells | cdt | power) echo "-eva-split-return full -eva-slevel 1000000" ;;
    # centroid, clip, order, power_cells, field, interpolate: the same, and the
    # scratch at a fixed address (far_sites.h)
    centroid | clip | order | power_cells | field | interpolate) echo "-eva-split-return full -eva-slevel 1000000 -absolute-valid-range 0x10000-0x1FFFF" ;;
    # queries, nearest_k, locate, power_dynamic: loops over a site's fan
    # (the walk, the k nearest's rounds, the disc's tree) run up to 7 turns
    # on these diagrams;
    # EVA widens the slot they read next after 3 merged turns (to an
    # interval past the triangles), after 12 it has met every slot of the
    # fan
    queries | nearest_k | locate | power_dynamic) echo "-eva-split-return full -eva-widening-delay 12" ;;
    # -eva-split-return full: a call's states stay apart by its return
    # value, so a caller's `if (call() != VOR_OK)` leaves only the states
    # where the call succeeded (vor_init's failures leave *d unwritten).
    *) echo "-eva-split-return full" ;;
    esac
}
sources_of() {
    case $1 in
    predicates) echo src/predicates.c ;;
    # these include what they analyse (predicates_os: src/predicates.c as
    # built at -Os; the multi-word ones: src/multiword.h alone)
    predicates_os | multiword | multiword_armv6m) echo "" ;;
    *) grep '^src/' sources.txt | tr '\n' ' ' ;;
    esac
}

# One harness: its report, functions and result (passed or failed) in
# build/prove/NAME.*, and the line that says so.
functions=$out/functions.txt
prove_one() {
    name=$1
    report=$out/$name.txt
    start=$(date +%s)
    # shellcheck disable=SC2046,SC2086
    if ! frama-c $common $(options_of "$name") \
        -cpp-extra-args="-Iinclude -Isrc -DVOR_LIMB_BITS=32 -D__ARM_ARCH_PROFILE=77" \
        "tools/prove/$name.c" $(sources_of "$name") >"$report" 2>&1; then
        cat "$report"
        echo "prove: $name: frama-c failed ($report)" >&2
        echo failed >"$out/$name.result"
        return
    fi
    seconds=$(($(date +%s) - start))
    # the functions EVA analysed (it prints each one's final values);
    # Frama-C renames a static function defined in several files NAME_N
    sed -n 's/^\[eva:final-states\] Values at end of function \([A-Za-z0-9_]*\):$/\1/p' \
        "$report" | while read -r f; do
        if grep -qx "$f" "$functions"; then
            echo "$f"
        elif grep -qx "${f%_[0-9]*}" "$functions"; then
            echo "${f%_[0-9]*}"
        fi
    done | sort -u >"$out/$name.functions"
    alarms=$(grep -c '^\[eva:alarm\]' "$report" || true)
    # the summary says "No errors or warnings" only when there are none;
    # every property reached must be proven (a harness that reaches no
    # annotation says so instead)
    if [ "$alarms" -ne 0 ] ||
        ! grep -q 'No errors or warnings raised' "$report" ||
        ! grep -q -e '100% of the logical properties reached have been proven' \
            -e 'No logical properties have been reached' "$report"; then
        grep -A1 '^\[eva:alarm\]' "$report" | grep -v '^--' | paste - - |
            sed 's/\[eva:alarm\] //; s/: Warning: *\t */: /' >&2
        # warnings other than alarms, with the line that says what
        awk '/Warning/ && !/eva:alarm/ { print; getline; print }' "$report" >&2
        echo "prove: $name: not proven: $alarms alarms ($seconds s, $(wc -l <"$out/$name.functions") functions, $report)" >&2
        echo failed >"$out/$name.result"
    else
        echo passed >"$out/$name.result"
        echo "prove: $name: 0 alarms ($seconds s, $(wc -l <"$out/$name.functions") functions, $report)"
    fi
}

if [ "${1:-}" = "--one" ]; then
    prove_one "$2"
    exit 0
fi

# The library's functions: every function defined in src/ or include/
# (static and inline ones included), by name, from the symbols of each
# source compiled with every function kept, in the configuration Frama-C
# parses (32-bit limbs, M profile, no __OPTIMIZE__; VOR__COVERAGE turns the
# forced inlining off, which would keep a function out of the symbols).
objects=$(mktemp -d)
trap 'rm -rf "$objects"' EXIT
grep '^src/' sources.txt | while read -r source; do
    "${CC:-cc}" -std=c99 -ffreestanding -O0 -DVOR_LIMB_BITS=32 -D__ARM_ARCH_PROFILE=77 -DVOR__COVERAGE -Iinclude -Isrc \
        -fkeep-static-functions -fkeep-inline-functions -c "$source" \
        -o "$objects/$(basename "$source" .c).o"
done
nm "$objects"/*.o | awk '$2 == "T" || $2 == "t" { print $3 }' | sort -u >"$functions"

# shellcheck disable=SC2086
rm -f $(for name in $harnesses; do echo "$out/$name.result"; done)
printf '%s\n' $harnesses | xargs -P "${PROVE_JOBS:-$(nproc)}" -I '{}' sh "$self" --one '{}'
: >"$out/analysed.txt"
for name in $harnesses; do
    if [ "$(cat "$out/$name.result" 2>/dev/null)" = passed ]; then
        passed=$((passed + 1))
    else
        status=1
        failed=$((failed + 1))
    fi
    if [ -f "$out/$name.functions" ]; then
        sort -u "$out/analysed.txt" "$out/$name.functions" -o "$out/analysed.txt"
    fi
done

# The two filters of src/predicates.c that round their entries to 15 bits
# (32-bit limbs): their rounding errors proven below the code's three
# bounds by exact interval arithmetic (tools/prove/filter_error.c), a
# second or so.
if "${CC:-cc}" -std=gnu99 -O2 -Wall -Wextra -Werror tools/prove/filter_error.c -lm \
    -o "$out/filter_error" && "$out/filter_error" >"$out/filter_error.txt"; then
    passed=$((passed + 1))
else
    status=1
    failed=$((failed + 1))
fi
grep '^filter_error' "$out/filter_error.txt" || true

total=$(wc -l <"$functions")
analysed=$(wc -l <"$out/analysed.txt")
share=$((analysed * 100 / total))
echo "prove: $analysed of the library's $total functions analysed ($share %); the others: $out/not-analysed.txt"
comm -23 "$functions" "$out/analysed.txt" >"$out/not-analysed.txt"
if [ "$named" -eq 0 ]; then
    if [ "$share" -lt 95 ]; then
        echo "prove: less than 95 % of the library's functions analysed" >&2
        status=1
        failed=$((failed + 1))
    else
        passed=$((passed + 1))
    fi
fi
echo "$passed passed, $failed failed"
exit $status
