#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# tools/test-consumers.sh - vor as a CMake package, the way users take it:
# tests/consumers/cmake built through add_subdirectory and through
# find_package(vor CONFIG) after cmake --install into a prefix under
# build/, on the host and cross-built with
# cmake/toolchains/arm-none-eabi-cortex-m3.cmake, run under QEMU. Each
# build asks for a VOR_INDEX_BITS that is not the target's default, and
# the program checks that it sees it and that its nearest sites match
# brute force. Closing line "N passed, N failed" for tools/run-tests.sh.
set -u
cd "$(dirname "$0")/.."
root=$PWD
work=build/consumers
jobs=${CONSUMER_JOBS:-2}
passed=0
failed=0
rm -rf "$work"
mkdir -p "$work"

if ! command -v cmake >/dev/null 2>&1; then
    tools/install-deps.sh cmake || { echo "cmake is missing"; echo "0 passed, 1 failed"; exit 1; }
fi

# The Cortex-M3 runner of port/cortex-m3/port.mk.
qemu_m3=(timeout 120 qemu-system-arm -M mps2-an385 -cpu cortex-m3 -nographic -monitor none
         -serial none -semihosting-config enable=on,target=native -kernel)

# check NAME COMMAND...: one check; its output goes to $work/NAME.log.
check() {
    local name=$1
    shift
    if "$@" >"$work/$name.log" 2>&1; then
        passed=$((passed + 1))
        echo "ok   $name"
    else
        failed=$((failed + 1))
        echo "FAIL $name (log: $work/$name.log)"
        tail -n 10 "$work/$name.log" | sed 's/^/    /'
    fi
}

# run_consumer BUILD-DIR RUNNER...: the program passes every check.
run_consumer() {
    local dir=$1 exe
    shift
    exe=$dir/consumer
    [ -f "$exe.elf" ] && exe=$exe.elf
    "$@" "$exe" >"$dir/run.out" 2>&1
    local status=$?
    cat "$dir/run.out"
    [ "$status" = 0 ] && grep -Eq '^[1-9][0-9]* passed, 0 failed$' "$dir/run.out"
}

# consumer NAME INDEX-BITS CMAKE-ARGS...: configure and build the consumer.
consumer() {
    local name=$1 bits=$2
    shift 2
    cmake -S tests/consumers/cmake -B "$work/$name" -DVOR_ROOT="$root" \
        -DCMAKE_BUILD_TYPE=Release -DVOR_INDEX_BITS="$bits" \
        -DCONSUMER_EXPECTED_INDEX_BITS="$bits" "$@" &&
        cmake --build "$work/$name" -j"$jobs"
}

# install NAME INDEX-BITS CMAKE-ARGS...: build vor and install it into
# $work/NAME-prefix.
install_vor() {
    local name=$1 bits=$2
    shift 2
    cmake -S . -B "$work/$name" -DVOR_INDEX_BITS="$bits" "$@" &&
        cmake --build "$work/$name" -j"$jobs" &&
        cmake --install "$work/$name" --prefix "$root/$work/$name-prefix"
}

m3_toolchain=-DCMAKE_TOOLCHAIN_FILE=$root/cmake/toolchains/arm-none-eabi-cortex-m3.cmake

# host: the default is 16-bit indices everywhere, so ask for 32; with the trap
# assertions of the tests, through the generated configuration header.
check host-subdirectory-build consumer host-sub 32 -DVOR_CONSUME=subdirectory -DVOR_ASSERT_TRAP=ON
check host-subdirectory-run run_consumer "$work/host-sub"
check host-install install_vor host-vor 32
check host-package-build consumer host-pkg 32 -DVOR_CONSUME=package \
    -DCMAKE_PREFIX_PATH="$root/$work/host-vor-prefix"
check host-package-run run_consumer "$work/host-pkg"

# Added by a project that sets no build type (CMake then passes no -O
# flag), vor is still compiled optimised: -O2 on the host, -Os in a cross
# build; an -O flag of the project's own wins. Configured only: the
# compile commands are written then.
vor_level() {
    local name=$1 want=$2
    shift 2
    cmake -S tests/consumers/cmake -B "$work/$name" -DVOR_ROOT="$root" -DVOR_CONSUME=subdirectory \
        -DCMAKE_EXPORT_COMPILE_COMMANDS=ON "$@" || return 1
    python3 - "$work/$name/compile_commands.json" "$root/src/" "$want" <<'PY'
import json, re, sys
path, src, want = sys.argv[1:]
commands = [c for c in json.load(open(path)) if c["file"].startswith(src)]
# the last -O flag of each vor source's command decides its level
levels = {(re.findall(r"(?:^|\s)(-O\S*)", c["command"]) or ["no -O flag"])[-1] for c in commands}
print(f"{len(commands)} vor sources, levels {sorted(levels)}, wanted {want}")
sys.exit(0 if commands and levels == {want} else 1)
PY
}
check host-no-build-type-O2 vor_level host-level -O2
check host-own-level-wins vor_level host-own-level -O1 -DCMAKE_C_FLAGS=-O1
check m3-no-build-type-Os vor_level m3-level -Os -DCONSUMER_PORT=cortex-m3 "$m3_toolchain"

check host-fetchcontent-build consumer host-fetch 32 -DVOR_CONSUME=fetchcontent
check host-fetchcontent-run run_consumer "$work/host-fetch"

# The ESP-IDF and Zephyr glue with their Kconfig values, under stand-ins
# for the build-system functions they call (the real tools are not here).
check esp-idf-mock-build consumer host-esp 32 -DVOR_CONSUME=esp-idf-mock
check esp-idf-mock-run run_consumer "$work/host-esp"
check esp-idf-mock-options grep -q 'VOR_TRACKER_EDGES=16' "$work/host-esp/vor/CMakeFiles/idf_vor.dir/flags.make"
check zephyr-mock-build consumer host-zephyr 32 -DVOR_CONSUME=zephyr-mock
check zephyr-mock-run run_consumer "$work/host-zephyr"
check zephyr-mock-options grep -q 'VOR_LIMB_BITS=32' "$work/host-zephyr/CMakeFiles/consumer.dir/flags.make"
# ESP-IDF first reads the file in script mode for its requirements.
esp_idf_early_expansion() {
    cat >"$work/early.cmake" <<'SCRIPT'
set(CMAKE_BUILD_EARLY_EXPANSION 1)
macro(idf_component_register)
    cmake_parse_arguments(arg "" "" "SRCS;INCLUDE_DIRS" ${ARGN})
    message("SRCS ${arg_SRCS}")
    message("INCLUDE_DIRS ${arg_INCLUDE_DIRS}")
endmacro()
include("${VOR_ROOT}/CMakeLists.txt")
SCRIPT
    cmake -DVOR_ROOT="$root" -P "$work/early.cmake" >"$work/early.out" 2>&1 || return 1
    cat "$work/early.out"
    grep -qx "SRCS $(grep '^src/' sources.txt | paste -sd ';')" "$work/early.out" &&
        grep -qx 'INCLUDE_DIRS include' "$work/early.out"
}
check esp-idf-early-expansion esp_idf_early_expansion

# Cortex-M3: the default is 16-bit indices, so ask for 32.
check m3-subdirectory-build consumer m3-sub 32 -DVOR_CONSUME=subdirectory \
    -DCONSUMER_PORT=cortex-m3 "$m3_toolchain"
check m3-subdirectory-run run_consumer "$work/m3-sub" "${qemu_m3[@]}"
check m3-install install_vor m3-vor 32 "$m3_toolchain"
check m3-package-build consumer m3-pkg 32 -DVOR_CONSUME=package -DCONSUMER_PORT=cortex-m3 \
    -DCMAKE_PREFIX_PATH="$root/$work/m3-vor-prefix" "$m3_toolchain"
check m3-package-run run_consumer "$work/m3-pkg" "${qemu_m3[@]}"

# The other toolchain files build the library.
for toolchain in arm-none-eabi-cortex-m0 arm-none-eabi-cortex-m4f riscv32; do
    check "toolchain-$toolchain" install_vor "$toolchain" "" \
        -DCMAKE_TOOLCHAIN_FILE="$root/cmake/toolchains/$toolchain.cmake"
done

# The installed package: version from vor.h, the option recorded for the
# application, and a request for an incompatible version refused.
version=$(for part in MAJOR MINOR PATCH; do
    sed -n "s/^#define VOR_VERSION_$part \([0-9]*\)$/\1/p" include/vor.h
done | paste -sd.)
check package-version grep -q "set(PACKAGE_VERSION \"$version\")" \
    "$work/host-vor-prefix/lib/cmake/vor/vorConfigVersion.cmake"
check package-records-options grep -q 'INTERFACE_COMPILE_DEFINITIONS "VOR_INDEX_BITS=32"' \
    "$work/host-vor-prefix/lib/cmake/vor/vorTargets.cmake"
refuse_version() {
    mkdir -p "$work/old-version"
    printf 'cmake_minimum_required(VERSION 3.16)\nproject(old LANGUAGES C)\nfind_package(vor 0.1 CONFIG REQUIRED)\n' \
        >"$work/old-version/CMakeLists.txt"
    ! cmake -S "$work/old-version" -B "$work/old-version/build" \
        -DCMAKE_PREFIX_PATH="$root/$work/host-vor-prefix"
}
check package-refuses-0.1 refuse_version
# Built with the toolchain file at -Os, the library still calls nothing
# outside itself (the Makefile's builds are checked by run-tests.sh).
check m3-package-freestanding tools/check-freestanding.sh arm-none-eabi-nm \
    "$work/m3-vor-prefix/lib/libvor.a"

echo "$passed passed, $failed failed"
[ "$failed" = 0 ]
