#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# run-tests.sh - everything `make test` runs, with one summary line at the end.
#
# Suites: the host tests, the host tests under AddressSanitizer and UBSan,
# the fault injection test (wrong predicate signs) on every port, the
# configuration contract (an application and a library compiled with
# different vor_config.h options get VOR_ERR_CONFIG) on every port, the
# line and branch coverage of src/ by the host suites (gcov), the
# command-line tool, the two-core build on the dual Cortex-M33 board,
# the same tests as firmware under QEMU for every target, the check
# that no target's library calls libc, a soft-float routine or anything
# else outside itself (also built with GCC and clang at -O1 to -Oz), GCC's
# static analyser over the library, cppcheck's MISRA C:2012 addon over it
# (every finding a recorded deviation), the check that a firmware links only the
# library files of the features it calls, the memory tables of the docs,
# a fixed sample of the mutation tests (tools/mutants.py), the build-system
# manifests, the layer rule of src/ (tools/check-layers.py),
# the CMake package in consumer programs (tools/test-consumers.sh), the SPDX
# licence line of every file, and the docs (make docs without a warning,
# every Markdown link). Each suite ends with "N passed, N failed"; a suite that does not
# build, does not finish, or prints no such line counts as one failure.
#
# ONLY=PATTERN[,PATTERN...] (make test ONLY=...) runs part of it: a pattern
# that is a suite's name below runs that suite whole; the other patterns
# select test cases ("dynamic", "mesh/brute_force": docs/testing.md) in
# the suites built on the test harness (the test suite, the fault
# injection and configuration tests on every port), and such a suite
# where they select no case is skipped. A skipped suite counts neither as
# passed nor as failed; ONLY that selects nothing fails.
set -u
cd "$(dirname "$0")/.."
jobs=$(nproc 2>/dev/null || echo 2)
logs=build/test-logs
mkdir -p "$logs"
total_passed=0
total_failed=0
cases_passed=0 # in the suites with named cases
cases_failed=0
broken=()
skipped=()

only=${ONLY:-}
unset ONLY LIST # each make below is given its own
targets="cortex-m0 cortex-m3 cortex-m4f riscv32"
suites="host host-sanitize host-faults host-config host-limb32 coverage-report cli cdt-reference power-reference interpolate-reference fuzz coverage room field harness dual"
suites="$suites mutants freestanding analyzer misra prove linking programs memory-tables manifests layers consumers spdx docs"
for target in $targets; do
    suites="$suites $target $target-faults $target-config"
done
cases_only= # the patterns of ONLY that name no suite
used_patterns=" " # those that selected a case in some suite
for pattern in ${only//,/ }; do
    case " $suites " in
        *" $pattern "*) ;;
        *) cases_only="$cases_only${cases_only:+,}$pattern" ;;
    esac
done

# wanted NAME: does ONLY ask for suite NAME whole (or is it not set)?
wanted() {
    [ -z "$only" ] || [[ ",$only," == *",$1,"* ]]
}

# skip NAME: a suite that ONLY leaves out.
skip() {
    skipped+=("$1")
}

# patterns_for PROGRAM: the case patterns of ONLY that may select cases of
# PROGRAM: the fault injection test's are all named faults/..., the
# configuration contract's config/..., the test suite's the others.
patterns_for() {
    local pattern out=
    for pattern in ${cases_only//,/ }; do
        case $1-${pattern%%/*} in
            fault-tests-faults | config-tests-config) ;;
            tests-faults | tests-config | fault-tests-* | config-tests-*) continue ;;
        esac
        out="$out${out:+,}$pattern"
    done
    echo "$out"
}

# closing_counts FILE: the last "N passed, N failed" line of FILE as
# "N N", or nothing if it has none (the run did not finish).
closing_counts() {
    sed -n -E 's/^([0-9]+) passed, ([0-9]+) failed$/\1 \2/p' "$1" | tail -n 1
}

# record NAME LOG STATUS BEGAN: add the suite's closing counts to the
# totals; its line says how long it took since BEGAN ($SECONDS).
record() {
    local name=$1 log=$2 status=$3 counts passed failed cases took
    took="[$((SECONDS - $4)) s]"
    counts=$(closing_counts "$log")
    if [ -z "$counts" ]; then
        echo "$name: did not run to the end (exit $status) $took; last lines of $log:"
        tail -n 15 "$log" | sed 's/^/    /'
        total_failed=$((total_failed + 1))
        broken+=("$name")
        return
    fi
    read -r passed failed <<<"$counts"
    if [ "$failed" = 0 ] && [ "$status" != 0 ]; then
        echo "$name: all checks passed but the program exited with status $status"
        failed=1
    fi
    grep -E '^(FAIL|fatal)' "$log" | head -n 20 | sed "s/^/$name: /"
    cases=$(grep -E '^cases: [0-9]+ passed, [0-9]+ failed$' "$log" | tail -n 1)
    if [ -n "$cases" ]; then # a suite with named cases
        set -- ${cases//,/}
        cases_passed=$((cases_passed + $2))
        cases_failed=$((cases_failed + $4))
        echo "$name: $passed passed, $failed failed ($cases) $took"
    else
        echo "$name: $passed passed, $failed failed $took"
    fi
    total_passed=$((total_passed + passed))
    total_failed=$((total_failed + failed))
    [ "$failed" = 0 ] || broken+=("$name")
}

# check NAME COMMAND...: suite NAME, unless ONLY leaves it out: COMMAND
# (a program, or a function of this file) writes to the suite's log, whose
# last "N passed, N failed" line is added to the totals. With LANE=1 it
# is queued for the lane (below).
check() {
    local name=$1 log="$logs/$1.log" began=$SECONDS
    shift
    if ! wanted "$name"; then
        skip "$name"
    elif [ "${LANE:-0}" = 1 ]; then
        queued+=("$name||@|$*")
    else
        "$@" >"$log" 2>&1
        record "$name" "$log" $? "$began"
    fi
}

# one COMMAND...: a suite that is one check, COMMAND's success.
one() {
    if "$@"; then
        echo "1 passed, 0 failed"
    else
        echo "0 passed, 1 failed"
        return 1
    fi
}

# suite NAME PROGRAM MAKE-ARGS...: build and run a test program of one port
# (PROGRAM tests: the test suite; fault-tests: the fault injection test;
# config-tests: the configuration contract), all its cases or those ONLY
# selects. With LANE=1 the program is built here and queued for the lane
# (below), which runs it beside the suites that follow.
queued=()
suite() {
    local name=$1 program=$2 log="$logs/$1.log" status filter= began=$SECONDS
    shift 2
    if ! wanted "$name"; then
        filter=$(patterns_for "$program")
        [ -n "$filter" ] || { skip "$name"; return; }
    fi
    rm -f "$log.status"
    if make -s -j"$jobs" "$@" ONLY="$filter" "$program" >"$log" 2>&1; then
        if [ "${LANE:-0}" = 1 ]; then
            queued+=("$name|$filter|$program|$*")
            return
        fi
        make -s "$@" ONLY="$filter" "run-$program" >>"$log" 2>&1
        status=$?
    else
        status=$?
        echo "(build failed)" >>"$log"
    fi
    suite_record "$name" "$filter" "$status" "$began"
}

# suite_record NAME FILTER STATUS BEGAN: a test program's run recorded.
suite_record() {
    local name=$1 filter=$2 log="$logs/$1.log" pattern
    if [ -n "$filter" ] && grep -q '^no case matches' "$log"; then
        skip "$name"
        return
    fi
    for pattern in ${filter//,/ }; do
        grep -qx "note: ONLY pattern '$pattern' matches no case here" "$log" ||
            used_patterns="$used_patterns $pattern "
    done
    record "$name" "$log" "$3" "$4"
}

# The lane: the queued programs (each under QEMU, one core) and checks
# run one after another in the background, each writing its exit status
# and run time beside its log; lane_record waits for it and records them
# in order.
lane_run() {
    local entry name filter program args began
    for entry in "${queued[@]}"; do
        IFS='|' read -r name filter program args <<<"$entry"
        began=$SECONDS
        if [ "$program" = @ ]; then # a check: its command
            # shellcheck disable=SC2086
            $args >"$logs/$name.log" 2>&1
        else
            # shellcheck disable=SC2086
            make -s $args ONLY="$filter" "run-$program" >>"$logs/$name.log" 2>&1
        fi
        echo "$? $((SECONDS - began))" >"$logs/$name.log.status"
    done
}
lane_record() {
    local entry name filter program args status took
    wait "$lane"
    for entry in "${queued[@]}"; do
        IFS='|' read -r name filter program args <<<"$entry"
        read -r status took <"$logs/$name.log.status" 2>/dev/null || { status=1 took=0; }
        suite_record "$name" "$filter" "$status" "$((SECONDS - took))"
    done
}

# The emulated targets' test programs first: built here and run in the
# lane while the host's suites and the rest use the other core.
for target in $targets; do
    LANE=1 suite "$target" tests PORT="$target"
    LANE=1 suite "$target-faults" fault-tests PORT="$target"
    LANE=1 suite "$target-config" config-tests PORT="$target"
done

# Mutation testing (tools/mutants.py, docs/testing.md): about one in
# MUTANTS_EVERY mutants (chosen by each one's file, line text and
# mutation) of the predicates, the multi-word arithmetic, the
# perturbation and the mesh updates must be killed by the host suite, be
# listed as equivalent in tools/mutants-equivalent.txt or as still open in
# tools/mutants-open.txt (which may only shrink), with at least
# MUTANTS_FLOOR % killed: the share the sample reaches (issue 24's 95 %);
# its self-test shows an unmutated build passes and a broken one is
# killed. make mutants runs them all. It runs in the lane, after the
# emulated targets, whose QEMU runs leave a core free beside them.
mutants() {
    make -s build/gen/predicate_vectors.c &&
        nice -n 10 python3 tools/mutants.py --jobs "$jobs" --every "${MUTANTS_EVERY:-32}" \
            --floor "${MUTANTS_FLOOR:-95}"
}
LANE=1 check mutants mutants
lane_run &
lane=$!

suite host tests PORT=host
suite host-sanitize tests PORT=host SANITIZE=1
suite host-faults fault-tests PORT=host SANITIZE=1
suite host-config config-tests PORT=host SANITIZE=1
suite host-limb32 tests PORT=host SANITIZE=1 LIMB_BITS=32

# Line and branch coverage of src/ by the host suites (gcov, gcovr):
# tools/coverage-report.sh fails if a suite fails or the coverage falls
# below the floors of docs/testing.md, "Coverage".
check coverage-report one tools/coverage-report.sh

# The host command-line tool and examples/contours, against a Python
# big-integer oracle.
cli() {
    make -s -j"$jobs" PORT=host all build/host/example-contours &&
        python3 tests/cli/test_cli.py build/host/vor
}
check cli cli

# vor cdt against CGAL's constrained Delaunay triangulation with exact
# intersections (tests/reference/).
cdt_reference() {
    make -s -j"$jobs" PORT=host build/host/vor build/host/cgal-cdt &&
        python3 tests/reference/compare_cdt.py build/host/vor build/host/cgal-cdt
}
check cdt-reference cdt_reference

# vor power against CGAL's Regular_triangulation_2 (tests/reference/).
power_reference() {
    make -s -j"$jobs" PORT=host build/host/vor build/host/cgal-power &&
        python3 tests/reference/compare_power.py build/host/vor build/host/cgal-power
}
check power-reference power_reference

# vor_sibson, vor_laplace, vor_interpolate and vor_interpolate_laplace
# against CGAL's natural-neighbour coordinates with exact constructions,
# every coordinate and value compared as exact rationals (tests/reference/).
interpolate_reference() {
    make -s -j"$jobs" PORT=host build/host/vor-interpolate build/host/cgal-interpolate &&
        python3 tests/reference/compare_interpolate.py build/host/vor-interpolate build/host/cgal-interpolate
}
check interpolate-reference interpolate_reference

# The libFuzzer harnesses (tests/fuzz/): every committed corpus and
# regression input replayed, then each harness fuzzed for FUZZ_BRIEF
# seconds (make fuzz runs them for long).
fuzz() {
    make -s -j"$jobs" fuzz-harnesses && tools/fuzz.sh --brief "${FUZZ_BRIEF:-15}"
}
check fuzz fuzz

# examples/coverage on the emulated Cortex-M3: Lloyd coverage control with
# vor_cell_centroid and vor_move, checked against brute-force samples.
coverage() {
    make -s -j"$jobs" PORT=cortex-m3 build/cortex-m3/example-coverage.elf &&
        make -s PORT=cortex-m3 run-example-coverage
}
check coverage coverage

# examples/dual on the two Cortex-M33 cores of the emulated mps2-an521:
# vor_build_dc_forked with core 1 building one half through the example's
# fork/join hook, at 100 to 20,000 sites; each forked diagram must be the
# one-core build's byte for byte, and the hook must have been used (a
# fork, a join, core 1 running the work). Instructions and the speedup
# are printed, never checked.
dual() {
    make -s -j"$jobs" PORT=cortex-m33 build/cortex-m33/example-dual.elf &&
        make -s PORT=cortex-m33 run-example-dual
}
check dual dual

# Builds and runs examples/NAME (make target example-NAME) on the host
# and on every emulated target, adding up the checks each run prints. A
# hook, if named, runs before each port ("HOOK before PORT") and after it
# ("HOOK after PORT"), where its status counts as one more check (it
# prints its own FAIL line).
example_on_ports() {
    local name=$1 hook=${2:-} passed=0 failed=0 port exe out status counts p f
    for port in host $targets; do
        exe=$([ "$port" = host ] || echo .elf)
        out=$logs/$name-$port.out
        if [ -n "$hook" ]; then "$hook" before "$port"; fi
        make -s -j"$jobs" PORT="$port" "build/$port/example-$name$exe" >"$out" 2>&1 &&
            make -s PORT="$port" "run-example-$name" >>"$out" 2>&1
        status=$?
        sed -n "s/^FAIL /FAIL $port: /p" "$out"
        counts=$(closing_counts "$out")
        p=0
        f=0
        if [ -n "$counts" ]; then
            read -r p f <<<"$counts"
            passed=$((passed + p))
            failed=$((failed + f))
        fi
        if [ "$status" != 0 ] && [ "$f" = 0 ]; then
            echo "FAIL $port: examples/$name exited with status $status ($out)"
            failed=$((failed + 1))
        fi
        if [ -n "$hook" ]; then
            if "$hook" after "$port"; then
                passed=$((passed + 1))
            else
                failed=$((failed + 1))
            fi
        fi
    done
    echo "$passed passed, $failed failed"
}

# examples/room on the host and on every emulated target: a navigation
# mesh from walls as constraints, checked against the floor plan (the
# shoelace area, Euler's triangle count, even-odd point location, a way
# through the doors). Its checks add up over the ports.
room() {
    example_on_ports room
}
check room room

# examples/field at every 4th pixel (example-field-quick, 80x60) on the
# host and on every emulated target: 50 sensors' Sibson interpolant
# rendered by vor_field_raster, every pixel checked on the target (linear
# reproduction, the brute-force hull, the readings, their range, the
# colours). Each target's frames must equal the host's byte for byte, and
# the host's values are checked against the exact brute force of
# tools/check_field.py (one row and column in 4, and the sensors).
field_frames() {
    if [ "$1" = before ]; then
        rm -f build/field-quick.values build/field-quick.rgb565
    elif [ "$2" = host ]; then
        cp build/field-quick.values "$logs/field-host.values" 2>/dev/null
        cp build/field-quick.rgb565 "$logs/field-host.rgb565" 2>/dev/null
        python3 tools/check_field.py --every 4 build/field-quick ||
            { echo "FAIL host: tools/check_field.py found values unlike the brute force" && false; }
    else
        { cmp -s build/field-quick.values "$logs/field-host.values" &&
            cmp -s build/field-quick.rgb565 "$logs/field-host.rgb565"; } ||
            { echo "FAIL $2: the field's frames differ from the host's" && false; }
    fi
}
field() {
    example_on_ports field-quick field_frames
}
check field field

# The harness itself: on every port a failing check, a failing or empty
# named case, a filter that selects no case and a trap must end the run
# with a non-zero status, so that no broken target can pass.
harness() {
    local passed=0 failed=0 port status out exited
    for port in host cortex-m0 cortex-m3 cortex-m4f riscv32; do
        # make exits 2 for any failed program and names its status as "Error N"
        out=$logs/harness-$port.out
        make -s PORT="$port" run-selftest-failing_check >"$out" 2>&1
        status=$(grep -o 'Error [0-9]*' "$out" | tail -n 1)
        if [ "$status" = "Error 1" ] && grep -qx '0 passed, 1 failed' "$out"; then
            passed=$((passed + 1))
        else
            echo "FAIL $port: a failing check ended with status $status"
            failed=$((failed + 1))
        fi
        # named cases under a filter: the failing and the empty case fail
        # by name, the case left out does not run
        make -s PORT="$port" run-selftest-cases >"$out" 2>&1
        status=$(grep -o 'Error [0-9]*' "$out" | tail -n 1)
        if [ "$status" = "Error 1" ] && grep -qx 'FAIL case selftest/fails: 1 of 1 checks failed' "$out" &&
            grep -qx 'FAIL case selftest/empty ran no check' "$out" &&
            grep -qx 'cases: 1 passed, 2 failed' "$out" && grep -qx '1 passed, 2 failed' "$out" &&
            ! grep -q 'filter leaves out' "$out"; then
            passed=$((passed + 1))
        else
            echo "FAIL $port: named cases under a filter ended with status $status"
            failed=$((failed + 1))
        fi
        # a filter that selects no case fails
        make -s PORT="$port" run-selftest-no_case >"$out" 2>&1
        status=$(grep -o 'Error [0-9]*' "$out" | tail -n 1)
        if [ "$status" = "Error 1" ] && grep -qx 'no case matches ONLY=selftest/missing' "$out" &&
            grep -qx '0 passed, 1 failed' "$out"; then
            passed=$((passed + 1))
        else
            echo "FAIL $port: a filter that selects no case ended with status $status"
            failed=$((failed + 1))
        fi
        make -s PORT="$port" run-selftest-fault >"$out" 2>&1
        exited=$?
        status=$(grep -o 'Error [0-9]*' "$out" | tail -n 1)
        # targets: the port's fault handler prints "fatal:" and exits 99;
        # host: the trap kills the process with a signal
        if { [ "$port" = host ] && [ "$exited" != 0 ] && grep -q 'trapping now' "$out"; } ||
            { [ "$status" = "Error 99" ] && grep -q 'fatal:' "$out"; }; then
            passed=$((passed + 1))
        else
            echo "FAIL $port: a trap ended with status $status"
            failed=$((failed + 1))
        fi
    done
    echo "$passed passed, $failed failed"
}
check harness harness

# The freestanding check, and a proof that it catches what it looks for.
freestanding() {
    local passed=0 failed=0 target nm
    for target in cortex-m0 cortex-m3 cortex-m4f riscv32; do
        nm=arm-none-eabi-nm
        [ "$target" = riscv32 ] && nm=riscv64-unknown-elf-nm
        make -s -j"$jobs" PORT="$target" lib 2>&1
        if tools/check-freestanding.sh "$nm" "build/$target/libvor.a" 2>&1; then
            passed=$((passed + 1))
        else
            echo "FAIL build/$target/libvor.a calls outside the library"
            failed=$((failed + 1))
        fi
    done
    # The sources as a firmware may compile them: Cortex-M0 and RISC-V 32,
    # with GCC and clang, at every optimisation level, warnings as errors,
    # with no special flag (GCC's case tables on ARMv6-M at -Os would call
    # libgcc's __gnu_thumb1_case_*). Every level must be clean: no
    # exception is allowed.
    local compiler level dir opt
    local -a args
    for target in cortex-m0 riscv32; do
        nm=arm-none-eabi-nm
        [ "$target" = riscv32 ] && nm=riscv64-unknown-elf-nm
        for compiler in gcc clang; do
            for level in -O0 -Og -O1 -O2 -O3 -Os -Oz; do
                dir=build/freestanding/$compiler-$target$level
                opt=$level
                args=(PORT="$target" B="$dir")
                case $compiler-$target in
                    clang-cortex-m0) args+=(CC="clang --target=armv6m-none-eabi") ;;
                    clang-riscv32) args+=(CC="clang --target=riscv32-unknown-elf") ;;
                esac
                if make -s -j"$jobs" "${args[@]}" OPT="$opt" lib 2>&1 &&
                    tools/check-freestanding.sh "$nm" "$dir/libvor.a" 2>&1; then
                    passed=$((passed + 1))
                else
                    echo "FAIL $compiler $target $opt: a warning, or a call outside the library"
                    failed=$((failed + 1))
                fi
            done
        done
    done
    # an object that uses float and memcpy must be rejected
    local bad=build/test-logs/bad
    mkdir -p "$bad"
    # (memcpy declared by hand: the cross compilers come without a C library)
    printf 'void *memcpy(void *, const void *, __SIZE_TYPE__);\nfloat f(float a, float b, char *d, const char *s) { memcpy(d, s, 40); return a / b; }\n' >"$bad/bad.c"
    if arm-none-eabi-gcc -mcpu=cortex-m0 -mthumb -O2 -c "$bad/bad.c" -o "$bad/bad.o" 2>&1 &&
        arm-none-eabi-ar rcs "$bad/libbad.a" "$bad/bad.o" &&
        ! tools/check-freestanding.sh arm-none-eabi-nm "$bad/libbad.a" >"$bad/out.txt" 2>&1 &&
        grep -q 'soft-float routine __aeabi_fdiv' "$bad/out.txt" &&
        grep -q 'libc function memcpy' "$bad/out.txt"; then
        passed=$((passed + 1))
    else
        echo "FAIL the freestanding check did not catch float and memcpy"
        failed=$((failed + 1))
    fi
    echo "$passed passed, $failed failed"
}
check freestanding freestanding

# GCC's static analyser (-fanalyzer) over every library source, with the
# release build's flags (make lib: -std=c99 -ffreestanding, the warning
# set, -O2, -Werror, so a finding fails the build), in each configuration
# the library ships in: 16- and 32-bit ids, with and without the counters
# (VOR_STATS=1). Then clang's (scan-build --status-bugs: a report fails)
# over the test build of the library (16- and 32-bit ids, VOR_STATS=1),
# whose VOR_ASSERTs tell it the mesh's invariants. Each run starts from
# nothing, so every file is analysed every time; and a file with a NULL
# dereference shows that each analyser's finding fails the suite.
analyzer() {
    local passed=0 failed=0 bits dir target
    rm -rf build/analyzer
    for bits in 16 32; do
        dir=build/analyzer/gcc-$bits
        for target in lib "$dir/libvor-stats.a"; do
            if make -s -j"$jobs" PORT=host CC=gcc B="$dir" WIDTH_DEFS=-DVOR_INDEX_BITS="$bits" \
                OPT="-O2 -fanalyzer" "$target" 2>&1; then
                passed=$((passed + 1))
            else
                echo "FAIL gcc -fanalyzer, VOR_INDEX_BITS=$bits, $target: a finding (above)"
                failed=$((failed + 1))
            fi
        done
        dir=build/analyzer/clang-$bits
        if scan-build --status-bugs --use-cc=clang -o "$dir-reports" make -s -j"$jobs" PORT=host B="$dir" \
            WIDTH_DEFS=-DVOR_INDEX_BITS="$bits" "$dir/libvor-checked.a" 2>&1; then
            passed=$((passed + 1))
        else
            echo "FAIL scan-build, VOR_INDEX_BITS=$bits: a report (above, and in $dir-reports/)"
            failed=$((failed + 1))
        fi
    done
    local bad=build/test-logs/analyzer-bad
    mkdir -p "$bad"
    printf 'int bad(int k)\n{\n    int *p = 0;\n    if (k > 3)\n        p = &k;\n    return *p;\n}\n' >"$bad/bad.c"
    if ! gcc -std=c99 -ffreestanding -Wall -Werror -O2 -fanalyzer -c "$bad/bad.c" -o "$bad/bad.o" \
        >"$bad/gcc.txt" 2>&1 && grep -q 'analyzer-null-dereference' "$bad/gcc.txt"; then
        passed=$((passed + 1))
    else
        echo "FAIL gcc -fanalyzer did not fail on a NULL dereference ($bad/bad.c)"
        failed=$((failed + 1))
    fi
    rm -rf "$bad/reports"
    if ! scan-build --status-bugs --use-cc=clang -o "$bad/reports" clang -std=c99 -ffreestanding -O2 \
        -c "$bad/bad.c" -o "$bad/bad.o" >"$bad/clang.txt" 2>&1 &&
        grep -q 'core.NullDereference' "$bad/clang.txt"; then
        passed=$((passed + 1))
    else
        echo "FAIL scan-build did not fail on a NULL dereference ($bad/bad.c)"
        failed=$((failed + 1))
    fi
    echo "$passed passed, $failed failed"
}
check analyzer analyzer

# cppcheck's MISRA C:2012 addon over the library in three configurations
# (tools/misra.sh): every finding must be a deviation of
# tools/misra-deviations.txt, every deviation must still be needed, every
# header must be analysed, and a file with known violations must be
# reported (so the suite cannot pass with the addon broken).
check misra tools/misra.sh

# Frama-C's EVA (tools/prove/prove.sh) over the harnesses that finish in
# about a minute each: the predicates (as built at
# -O2 and -Os), the multi-word arithmetic (generic and Cortex-M0), every
# diagram update, the Voronoi vertices and edges, the raster and the
# field frames. make prove runs every harness (each takes minutes more).
check prove tools/prove/prove.sh predicates predicates_os multiword multiword_armv6m diagram geometry raster field

# A firmware links only what it calls: the bench/size/ programs, linked
# at -Os with --gc-sections, keep only the library files of their feature
# set (no divide and conquer under vor_build, no other metric under
# vor_raster_euclid, no geometry under the queries).
check linking tools/size-features.sh --check cortex-m0 cortex-m3 riscv32

# docs/benchmarks.md's stack and RAM budget tables, against the call graphs,
# the compilers and VOR_ARENA_BYTES they are computed from.
check memory-tables python3 tools/memory-tables.py --check docs/benchmarks.md

# The build-system manifests (CMake, Zephyr, ESP-IDF, PlatformIO) name
# files that exist, the version of vor.h and every vor_config.h option.
check manifests python3 tools/check-manifests.py

# vor as a CMake package (add_subdirectory, find_package after an install)
# on the host and on the emulated Cortex-M3.
check consumers tools/test-consumers.sh

# The layer rule of docs/design.md: src/'s #include lines point one way
# and every cross-part call goes through a header the caller includes;
# --self-test shows each kind of break is caught.
check layers python3 tools/check-layers.py --self-test

# Every benchmark program and example builds, on the host and on the
# emulated Cortex-M3 (contours is a host program): the tests do not link
# them, so a changed call or helper would otherwise break them unseen.
programs() {
    local passed=0 failed=0 name port exe
    for name in $(ls bench/*.c | sed 's|bench/\(.*\)\.c|bench-\1|') \
        $(ls -d examples/*/ | sed 's|examples/\(.*\)/|example-\1|' | grep -v '^example-common$'); do
        ports="host cortex-m3"
        # examples/dual runs on the two cores of mps2-an521 only (suite dual)
        [ "$name" = example-dual ] && ports=cortex-m33
        for port in $ports; do
            [ "$port" != host ] && [ "$name" = example-contours ] && continue
            exe=$([ "$port" = host ] || echo .elf)
            if make -s PORT="$port" "build/$port/$name$exe" 2>&1; then
                passed=$((passed + 1))
            else
                echo "FAIL $port: $name does not build"
                failed=$((failed + 1))
            fi
        done
    done
    echo "$passed passed, $failed failed"
}
check programs programs

# Every source, header, script and build file names its licence.
check spdx tools/check-spdx.sh

# The API reference (make docs: Doxygen over include/*.h) builds without
# a warning, and every relative link and #anchor of the Markdown docs
# leads to a file and heading that exist.
docs() {
    local passed=0 failed=0 links p f
    if make -s docs 2>&1; then
        passed=1
    else
        echo "FAIL make docs: a Doxygen warning or error"
        sed 's/^/FAIL /' build/docs/warnings.log 2>/dev/null
        failed=1
    fi
    python3 tools/check-doc-links.py >"$logs/doc-links.log" 2>&1
    cat "$logs/doc-links.log"
    links=$(closing_counts "$logs/doc-links.log")
    if [ -n "$links" ]; then
        read -r p f <<<"$links"
        passed=$((passed + p))
        failed=$((failed + f))
    else
        echo "FAIL tools/check-doc-links.py did not finish"
        failed=$((failed + 1))
    fi
    echo "$passed passed, $failed failed"
}
check docs docs

lane_record
for pattern in ${cases_only//,/ }; do
    if [[ "$used_patterns" != *" $pattern "* ]]; then
        echo "ONLY: '$pattern' names no suite and selects no case"
        total_failed=$((total_failed + 1))
    fi
done
if [ ${#skipped[@]} -gt 0 ]; then
    echo "skipped (ONLY=$only selects nothing in them): ${skipped[*]}"
fi
if [ ${#broken[@]} -gt 0 ]; then
    echo "failing: ${broken[*]} (logs in $logs/)"
fi
echo "cases: $cases_passed passed, $cases_failed failed"
echo "took: $((SECONDS / 60)) min $((SECONDS % 60)) s"
echo "total: $total_passed passed, $total_failed failed"
[ "$total_failed" = 0 ]
