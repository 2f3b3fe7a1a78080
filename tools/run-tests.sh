#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# run-tests.sh - everything `make test` runs, with one summary line at the end.
#
# Suites: the host tests, the host tests under AddressSanitizer and UBSan,
# the fault injection test (wrong predicate signs) on every port, the
# configuration contract (an application and a library compiled with
# different vor_config.h options get VOR_ERR_CONFIG) on every port, the
# command-line tool,
# the same tests as firmware under QEMU for every target, the check
# that no target's library calls libc, a soft-float routine or anything
# else outside itself (also built with GCC and clang at -O1 to -Oz), the check that a firmware links only the
# library files of the features it calls, the memory tables of the docs,
# the build-system manifests, the CMake package in consumer programs
# (tools/test-consumers.sh), and the SPDX licence line of every file. Each suite ends with "N passed, N failed"; a suite that does not
# build, does not finish, or prints no such line counts as one failure.
set -u
cd "$(dirname "$0")/.."
jobs=$(nproc 2>/dev/null || echo 2)
logs=build/test-logs
mkdir -p "$logs"
total_passed=0
total_failed=0
broken=()

# record NAME LOG STATUS: add the suite's closing counts to the totals.
record() {
    local name=$1 log=$2 status=$3 counts passed failed
    counts=$(grep -E '^[0-9]+ passed, [0-9]+ failed$' "$log" | tail -n 1)
    if [ -z "$counts" ]; then
        echo "$name: did not run to the end (exit $status); last lines of $log:"
        tail -n 15 "$log" | sed 's/^/    /'
        total_failed=$((total_failed + 1))
        broken+=("$name")
        return
    fi
    passed=${counts%% passed*}
    failed=${counts#*, }
    failed=${failed%% failed}
    if [ "$failed" = 0 ] && [ "$status" != 0 ]; then
        echo "$name: all checks passed but the program exited with status $status"
        failed=1
    fi
    grep -E '^(FAIL|fatal)' "$log" | head -n 20 | sed "s/^/$name: /"
    echo "$name: $passed passed, $failed failed"
    total_passed=$((total_passed + passed))
    total_failed=$((total_failed + failed))
    [ "$failed" = 0 ] || broken+=("$name")
}

# suite NAME PROGRAM MAKE-ARGS...: build and run a test program of one port
# (PROGRAM tests: the test suite; fault-tests: the fault injection test;
# config-tests: the configuration contract).
suite() {
    local name=$1 program=$2 log="$logs/$1.log" status
    shift 2
    if make -s -j"$jobs" "$@" "$program" >"$log" 2>&1; then
        make -s "$@" "run-$program" >>"$log" 2>&1
        status=$?
    else
        status=$?
        echo "(build failed)" >>"$log"
    fi
    record "$name" "$log" "$status"
}

suite host tests PORT=host
suite host-sanitize tests PORT=host SANITIZE=1
suite host-faults fault-tests PORT=host SANITIZE=1
suite host-config config-tests PORT=host SANITIZE=1
suite host-limb32 tests PORT=host SANITIZE=1 LIMB_BITS=32

# The host command-line tool and examples/contours, against a Python
# big-integer oracle.
cli_log="$logs/cli.log"
if make -s -j"$jobs" PORT=host all build/host/example-contours >"$cli_log" 2>&1; then
    python3 tests/cli/test_cli.py build/host/vor >>"$cli_log" 2>&1
    record cli "$cli_log" $?
else
    record cli "$cli_log" 1
fi

# The libFuzzer harnesses (tests/fuzz/): every committed corpus and
# regression input replayed, then each harness fuzzed for FUZZ_BRIEF
# seconds (make fuzz runs them for long).
fuzz_log="$logs/fuzz.log"
if make -s -j"$jobs" fuzz-harnesses >"$fuzz_log" 2>&1; then
    tools/fuzz.sh --brief "${FUZZ_BRIEF:-15}" >>"$fuzz_log" 2>&1
    record fuzz "$fuzz_log" $?
else
    record fuzz "$fuzz_log" 1
fi

for target in cortex-m0 cortex-m3 cortex-m4f riscv32; do
    suite "$target" tests PORT="$target"
    suite "$target-faults" fault-tests PORT="$target"
    suite "$target-config" config-tests PORT="$target"
done

# examples/coverage on the emulated Cortex-M3: Lloyd coverage control with
# vor_cell_centroid and vor_move, checked against brute-force samples.
coverage_log="$logs/coverage.log"
mkdir -p build
if make -s -j"$jobs" PORT=cortex-m3 build/cortex-m3/example-coverage.elf >"$coverage_log" 2>&1; then
    make -s PORT=cortex-m3 run-example-coverage >>"$coverage_log" 2>&1
    record coverage "$coverage_log" $?
else
    record coverage "$coverage_log" 1
fi

# The harness itself: on every port a failing check and a trap must end
# the run with a non-zero status, so that no broken target can pass.
harness() {
    local log="$logs/harness.log" passed=0 failed=0 port status
    : >"$log"
    for port in host cortex-m0 cortex-m3 cortex-m4f riscv32; do
        # make exits 2 for any failed program and names its status as "Error N"
        make -s PORT="$port" run-selftest-failing_check >"$logs/harness-$port.out" 2>&1
        status=$(grep -o 'Error [0-9]*' "$logs/harness-$port.out" | tail -n 1)
        if [ "$status" = "Error 1" ] && grep -qx '0 passed, 1 failed' "$logs/harness-$port.out"; then
            passed=$((passed + 1))
        else
            echo "FAIL $port: a failing check ended with status $status" >>"$log"
            failed=$((failed + 1))
        fi
        make -s PORT="$port" run-selftest-fault >"$logs/harness-$port.out" 2>&1
        local exited=$?
        status=$(grep -o 'Error [0-9]*' "$logs/harness-$port.out" | tail -n 1)
        # targets: the port's fault handler prints "fatal:" and exits 99;
        # host: the trap kills the process with a signal
        if { [ "$port" = host ] && [ "$exited" != 0 ] && grep -q 'trapping now' "$logs/harness-$port.out"; } ||
            { [ "$status" = "Error 99" ] && grep -q 'fatal:' "$logs/harness-$port.out"; }; then
            passed=$((passed + 1))
        else
            echo "FAIL $port: a trap ended with status $status" >>"$log"
            failed=$((failed + 1))
        fi
    done
    echo "$passed passed, $failed failed" >>"$log"
    record harness "$log" 0
}
harness

# The freestanding check, and a proof that it catches what it looks for.
freestanding() {
    local log="$logs/freestanding.log" passed=0 failed=0 target nm
    : >"$log"
    for target in cortex-m0 cortex-m3 cortex-m4f riscv32; do
        nm=arm-none-eabi-nm
        [ "$target" = riscv32 ] && nm=riscv64-unknown-elf-nm
        make -s -j"$jobs" PORT="$target" lib >>"$log" 2>&1
        if tools/check-freestanding.sh "$nm" "build/$target/libvor.a" >>"$log" 2>&1; then
            passed=$((passed + 1))
        else
            echo "FAIL build/$target/libvor.a calls outside the library" >>"$log"
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
                if make -s -j"$jobs" "${args[@]}" OPT="$opt" lib >>"$log" 2>&1 &&
                    tools/check-freestanding.sh "$nm" "$dir/libvor.a" >>"$log" 2>&1; then
                    passed=$((passed + 1))
                else
                    echo "FAIL $compiler $target $opt: a warning, or a call outside the library" >>"$log"
                    failed=$((failed + 1))
                fi
            done
        done
    done
    # an object that uses float and memcpy must be rejected
    local bad=build/test-logs/bad
    mkdir -p "$bad"
    printf '#include <string.h>\nfloat f(float a, float b, char *d, const char *s) { memcpy(d, s, 40); return a / b; }\n' >"$bad/bad.c"
    if arm-none-eabi-gcc -mcpu=cortex-m0 -mthumb -O2 -c "$bad/bad.c" -o "$bad/bad.o" >>"$log" 2>&1 &&
        arm-none-eabi-ar rcs "$bad/libbad.a" "$bad/bad.o" &&
        ! tools/check-freestanding.sh arm-none-eabi-nm "$bad/libbad.a" >"$bad/out.txt" 2>&1 &&
        grep -q 'soft-float routine __aeabi_fdiv' "$bad/out.txt" &&
        grep -q 'libc function memcpy' "$bad/out.txt"; then
        passed=$((passed + 1))
    else
        echo "FAIL the freestanding check did not catch float and memcpy" >>"$log"
        failed=$((failed + 1))
    fi
    echo "$passed passed, $failed failed" >>"$log"
    record freestanding "$log" 0
}
freestanding

# A firmware links only what it calls: the bench/size/ programs, linked
# at -Os with --gc-sections, keep only the library files of their feature
# set (no divide and conquer under vor_build, no other metric under
# vor_raster_euclid, no geometry under the queries).
linking_log="$logs/linking.log"
tools/size-features.sh --check cortex-m0 cortex-m3 riscv32 >"$linking_log" 2>&1
record linking "$linking_log" $?

# docs/porting.md's stack and RAM budget tables, against the call graphs,
# the compilers and VOR_ARENA_BYTES they are computed from.
memory_log="$logs/memory-tables.log"
python3 tools/memory-tables.py --check docs/porting.md >"$memory_log" 2>&1
record memory-tables "$memory_log" $?

# The build-system manifests (CMake, Zephyr, ESP-IDF, PlatformIO) name
# files that exist, the version of vor.h and every vor_config.h option.
python3 tools/check-manifests.py >"$logs/manifests.log" 2>&1
record manifests "$logs/manifests.log" $?

# vor as a CMake package (add_subdirectory, find_package after an install)
# on the host and on the emulated Cortex-M3.
tools/test-consumers.sh >"$logs/consumers.log" 2>&1
record consumers "$logs/consumers.log" $?

# Every source, header, script and build file names its licence.
tools/check-spdx.sh >"$logs/spdx.log" 2>&1
record spdx "$logs/spdx.log" $?

if [ ${#broken[@]} -gt 0 ]; then
    echo "failing: ${broken[*]} (logs in $logs/)"
fi
echo "total: $total_passed passed, $total_failed failed"
[ "$total_failed" = 0 ]
