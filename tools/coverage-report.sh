#!/bin/sh
# SPDX-License-Identifier: MIT
# tools/coverage-report.sh - `make coverage-report`: line and branch
# coverage of src/ by the host suites, built with gcov's counters
# (COVERAGE=1 in the Makefile: -O0, no forced inlining). The runs, each in
# its own build directory, and their union is the report:
#   build/host-gcov           the test suite, the fault injection test and
#                             the configuration contract (32-bit ids)
#   build/host-limb32-gcov    the test suite with 32-bit limbs
#   build/host-gcov-index16   the test suite with 16-bit ids
# Prints gcovr's summary and the lines not covered per file; writes
# build/coverage-report/index.html (per file, per line) and summary.txt.
# Options of gcovr: docs/testing.md, "Coverage". Exits non-zero if a
# suite fails or the coverage is below the floors of docs/testing.md.
set -eu
cd "$(dirname "$0")/.."
jobs=$(nproc 2>/dev/null || echo 2)
out=build/coverage-report
dirs="build/host-gcov build/host-limb32-gcov build/host-gcov-index16"
rm -rf "$out"
mkdir -p "$out"
# counts of an earlier run would add up with this one's
for dir in $dirs; do
    [ -d "$dir" ] && find "$dir" -name '*.gcda' -delete
done

# run LOG MAKE-ARGS...: build and run host test programs, their output in
# build/coverage-report/LOG.log, their closing lines on stdout.
# Every case runs, whatever ONLY make test was given (make passes its
# command-line variables down to sub-makes).
run() {
    log=$out/$1.log
    shift
    if ! make -s -j"$jobs" PORT=host COVERAGE=1 ONLY= V= LIST= "$@" >>"$log" 2>&1; then
        tail -n 20 "$log"
        echo "coverage-report: a suite failed: make $* (log: $log)" >&2
        exit 1
    fi
    grep -E '^[0-9]+ passed, [0-9]+ failed$' "$log" | sed "s|^|$(basename "$log" .log): |"
}
run tests tests fault-tests config-tests
run tests run-tests
run fault-tests run-fault-tests
run config-tests run-config-tests
run limb32 LIMB_BITS=32 tests
run limb32 LIMB_BITS=32 run-tests
run index16 B=build/host-gcov-index16 WIDTH_DEFS=-DVOR_INDEX_BITS=16 tests
run index16 B=build/host-gcov-index16 WIDTH_DEFS=-DVOR_INDEX_BITS=16 run-tests

# One pass of gcov over the three directories (gcovr merges their counts
# line by line), then the reports from its JSON.
# shellcheck disable=SC2086  # dirs is a word list on purpose
gcovr --root . --filter 'src/' -j "$jobs" \
    --exclude-unreachable-branches --exclude-throw-branches \
    --exclude-branches-by-pattern '.*VOR_ASSERT\(.*' \
    --json "$out/coverage.json" $dirs
gcovr --add-tracefile "$out/coverage.json" --txt "$out/lines.txt" \
    --html-details "$out/index.html" --html-title 'vor: coverage of src/ by the host suites'
gcovr --add-tracefile "$out/coverage.json" --branches --txt "$out/branches.txt" \
    --print-summary --fail-under-line "${COVERAGE_LINES:-98}" \
    --fail-under-branch "${COVERAGE_BRANCHES:-95}" >"$out/summary.txt" 2>&1 || status=$?
cat "$out/lines.txt" "$out/branches.txt" "$out/summary.txt"
echo "report: $out/index.html"
exit "${status:-0}"
