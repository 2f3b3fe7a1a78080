#!/bin/sh
# SPDX-License-Identifier: MIT
# tools/prove/prove.sh - `make prove`: Frama-C's EVA over each harness of
# tools/prove/ with the library sources it calls, on a 32-bit machine
# (x86_32: 32-bit int and pointers, as on every target) and 32-bit limbs
# (Frama-C's front end has no __int128, so VOR_LIMB_BITS 64 cannot be
# parsed). Each report goes to build/prove/NAME.txt; fails when any
# report shows an alarm, a warning or an unproven property.
set -eu
cd "$(dirname "$0")/../.."
out=build/prove
mkdir -p "$out"
status=0
# each harness, with the library sources it calls (comma-separated)
harnesses="predicates:src/predicates.c predicates_os: multiword: multiword_armv6m:"
for job in $harnesses; do
    name=${job%%:*}
    sources=$(echo "${job#*:}" | tr , ' ')
    report=$out/$name.txt
    start=$(date +%s)
    # -eva-precision 3: enough to follow the small fixed loops of the
    # multi-word arithmetic one iteration at a time (below it, merged
    # iterations read as maybe-uninitialised limbs); higher levels find
    # nothing more and cost minutes.
    # shellcheck disable=SC2086
    if ! frama-c -machdep x86_32 \
        -cpp-extra-args="-Iinclude -Isrc -DVOR_LIMB_BITS=32" \
        -eva -eva-precision 3 -eva-no-show-progress \
        "tools/prove/$name.c" $sources >"$report" 2>&1; then
        cat "$report"
        echo "prove: $name: frama-c failed ($report)" >&2
        status=1
        continue
    fi
    seconds=$(($(date +%s) - start))
    sed -n '/ANALYSIS SUMMARY/,$p' "$report"
    # the summary counts the alarms ("0 alarms generated", "1 alarm
    # generated", ...) and says "No errors or warnings" only when there
    # are none; every property reached must be proven
    if grep -Eq '[1-9][0-9]* alarms? generated' "$report" ||
        ! grep -q 'No errors or warnings raised' "$report" ||
        ! grep -q '100% of the logical properties reached have been proven' "$report"; then
        grep -A1 'eva:alarm' "$report" | grep -v '^--' | paste - - |
            sed 's/\[eva:alarm\] //; s/: Warning: *\t */: /' >&2
        echo "prove: $name: not proven (${seconds} s, $report)" >&2
        status=1
    else
        echo "prove: $name: 0 alarms (${seconds} s, $report)"
    fi
done
exit $status
