#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# tools/fuzz.sh - runs the libFuzzer harnesses of tests/fuzz/ (built by
# `make fuzz-harnesses`) one after the other.
#
#   tools/fuzz.sh --seconds N [HARNESS...]
#                               fuzz each harness (or the ones named) for N
#                               seconds (make fuzz)
#   tools/fuzz.sh --brief N     make test: replay every committed corpus and
#                               regression input, then fuzz each harness for
#                               N seconds; ends with "N passed, N failed"
#
# Each harness starts from tests/fuzz/corpus/<name>/ and regressions/<name>/
# and grows its working corpus in build/fuzz/corpus/<harness>/ (--brief:
# build/fuzz/brief/corpus/<harness>/, logs and reproducers there too). Per harness
# it prints executions, coverage (libFuzzer's edge counter "cov") and
# findings; a finding fails the run and leaves its reproducer as
# build/fuzz/<harness>-crash-* (or -timeout-, -oom-, -leak-): replay it
# with build/fuzz/<harness> FILE, then keep it in regressions/<name>/.
set -u
cd "$(dirname "$0")/.."
mode=${1:-}
seconds=${2:-}
if { [ "$mode" != --seconds ] && [ "$mode" != --brief ]; } || ! [ "$seconds" -ge 1 ] 2>/dev/null; then
    echo "usage: tools/fuzz.sh --seconds N | --brief N" >&2
    exit 2
fi
shift 2
harnesses=${*:-api16 api32 predicates predicates32 raster cli}
passed=0
failed=0

# corpus_name HARNESS: both index widths of the API harness share one
# corpus, and both limb widths of the predicates harness.
corpus_name() {
    case $1 in api16 | api32) echo api ;; predicates32) echo predicates ;; *) echo "$1" ;; esac
}

# options HARNESS: the harness's own libFuzzer options.
options() {
    case $1 in cli) echo "-dict=tests/fuzz/cli.dict -timeout=30" ;; *) echo "-timeout=10" ;; esac
}

check() {
    if [ "$1" = 0 ]; then
        passed=$((passed + 1))
    else
        echo "FAIL $2"
        failed=$((failed + 1))
    fi
}

for harness in $harnesses; do
    exe=build/fuzz/fuzz_$harness
    name=$(corpus_name "$harness")
    # make test's brief runs keep apart from a long run going on meanwhile
    out=build/fuzz
    [ "$mode" = --brief ] && out=build/fuzz/brief
    work=$out/corpus/$harness
    log=$out/$harness.log
    mkdir -p "$work"
    if [ ! -x "$exe" ]; then
        check 1 "$harness: $exe is not built (make fuzz-harnesses)"
        continue
    fi
    if [ "$mode" = --brief ]; then
        # every committed input, each run once: none may fail
        inputs=$(find "tests/fuzz/corpus/$name" "tests/fuzz/regressions/$name" -type f ! -name '.*' 2>/dev/null | sort)
        count=$(echo "$inputs" | grep -c .)
        # shellcheck disable=SC2086
        if [ "$count" -gt 0 ] && "$exe" $(options "$harness") $inputs >"$log.replay" 2>&1; then
            echo "$harness: replayed $count committed inputs"
            check 0 ""
        else
            tail -n 20 "$log.replay"
            check 1 "$harness: a committed input failed, or none found ($log.replay)"
        fi
    fi
    # shellcheck disable=SC2046
    "$exe" $(options "$harness") -max_total_time="$seconds" -print_final_stats=1 \
        -artifact_prefix="$out/$harness-" "$work" "tests/fuzz/corpus/$name" \
        >"$log" 2>&1
    status=$?
    executions=$(grep -a -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$')
    coverage=$(grep -a -o 'cov: [0-9]* ft: [0-9]*' "$log" | tail -n 1)
    findings=$(grep -a -c '^artifact_prefix=.*Test unit written to' "$log")
    echo "$harness: ${executions:-?} executions in $seconds s, ${coverage:-no coverage line}, corpus $(find "$work" -type f | wc -l) inputs, $findings findings"
    if [ "$status" != 0 ] || [ "$findings" != 0 ]; then
        grep -a -E 'fuzz finding|ERROR|SUMMARY|Test unit written' "$log" | head -n 10 | sed 's/^/    /'
    fi
    check $((status != 0 || findings != 0)) "$harness: a finding (log $log)"
done
echo "$passed passed, $failed failed"
[ "$failed" = 0 ]
