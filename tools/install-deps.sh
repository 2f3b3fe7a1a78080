#!/bin/sh
# SPDX-License-Identifier: MIT
# tools/install-deps.sh GROUP... - make sure the Debian/Ubuntu packages a
# build needs are installed; the Makefile runs it before each build that
# needs them, so `make`, `make demo` and `make test` work on a fresh machine.
#
#   host        the host C compiler and C library headers (make: library,
#               CLI, host tests)
#   cli         stb_image_write.h from libstb-dev (the CLI's PNG output
#               and examples/contours; host programs only, never the library)
#   python      python3 (test vectors, CLI tests, the demo's PNG)
#   toolchains  the cross compilers and QEMU of every target (the firmware
#               is linked with -nostdlib: no cross C library)
#   clang       clang, for make test's freestanding check (the library
#               compiled with a second compiler at every level)
#   cmake       cmake, for make test's consumers of the CMake package
#   bench       the Delaunay benchmark's peers, CGAL and Boost.Polygon
#   bench-query the query benchmark's peers, CGAL and nanoflann
#   svg         xmllint and rsvg-convert, for the tests of `vor draw` (the
#               SVG must parse and render like the exact raster)
#   fuzz        clang 14 and its libFuzzer runtime, for make fuzz and make
#               test's fuzz suite (tests/fuzz/)
#   doxygen     doxygen, for make docs (the API reference from the headers)
#               and make test's docs suite
#   gcovr       gcovr, for make coverage-report (line and branch coverage of
#               src/ by the host suites; gcov comes with gcc)
#   prove       Frama-C (frama-c-base: the EVA analyser), for make prove
#   analyzer    clang and its static analyser's scan-build (clang-tools),
#               for make test's analyzer suite (GCC's -fanalyzer comes with
#               gcc, group host)
#   misra       cppcheck and python3 (its MISRA C:2012 addon is a Python
#               script), for make misra and make test's misra suite
#   jcv         picolibc for Cortex-M, the C library of the embedded peer
#               benchmark (make bench-jcv: malloc and libm for jc_voronoi)
#
# Quiet and exit 0 when every package of the named groups is present; safe
# to run any number of times. When something is missing: as root, installs
# all missing packages with one apt-get call; otherwise prints the command
# to run and exits 1 (tools/apt-install.sh). Recommended packages are not
# installed (--no-install-recommends), so each group lists everything its
# builds need, even what a package only recommends (gcc recommends the C
# library headers, libc6-dev). A new group is one more case in members().
set -eu

# members GROUP: one "PACKAGE PROBE" line per package of GROUP. The probe
# shows the package is installed: a command on PATH, or the absolute path
# of a file it installs.
members() {
    case $1 in
    host)
        echo "gcc gcc"
        echo "libc6-dev /usr/include/stdio.h"
        ;;
    cli) echo "libstb-dev /usr/include/stb/stb_image_write.h" ;;
    python) echo "python3 python3" ;;
    toolchains)
        echo "gcc-arm-none-eabi arm-none-eabi-gcc"
        echo "gcc-riscv64-unknown-elf riscv64-unknown-elf-gcc"
        echo "qemu-system-arm qemu-system-arm"
        echo "qemu-system-misc qemu-system-riscv32"
        ;;
    clang) echo "clang clang" ;;
    cmake) echo "cmake cmake" ;;
    bench)
        echo "g++ g++"
        echo "libcgal-dev /usr/include/CGAL/Delaunay_triangulation_2.h"
        echo "libboost-dev /usr/include/boost/polygon/voronoi.hpp"
        ;;
    bench-query)
        echo "g++ g++"
        echo "libcgal-dev /usr/include/CGAL/Delaunay_triangulation_2.h"
        echo "libnanoflann-dev /usr/include/nanoflann.hpp"
        ;;
    svg)
        echo "libxml2-utils /usr/bin/xmllint"
        echo "librsvg2-bin /usr/bin/rsvg-convert"
        ;;
    misra)
        echo "cppcheck cppcheck"
        echo "python3 python3"
        ;;
    jcv) echo "picolibc-arm-none-eabi /usr/lib/picolibc/arm-none-eabi/picolibc.specs" ;;
    fuzz)
        echo "clang-14 clang-14"
        echo "libclang-rt-14-dev /usr/lib/llvm-14/lib/clang/14.0.6/lib/linux/libclang_rt.fuzzer-x86_64.a"
        ;;
    doxygen) echo "doxygen doxygen" ;;
    gcovr) echo "gcovr gcovr" ;;
    prove) echo "frama-c-base /usr/bin/frama-c" ;;
    analyzer)
        echo "clang clang"
        echo "clang-tools /usr/bin/scan-build"
        ;;
    *)
        echo "install-deps: unknown group $1" >&2
        exit 2
        ;;
    esac
}

present() {
    case $1 in
    /*) [ -e "$1" ] ;;
    *) command -v "$1" >/dev/null 2>&1 ;;
    esac
}

# missing_packages GROUP...: the packages whose probe fails, each once.
missing_packages() {
    for group in "$@"; do
        members "$group"
    done | while read -r package probe; do
        present "$probe" || echo "$package"
    done | sort -u | tr '\n' ' '
}

if [ $# -eq 0 ]; then
    echo "usage: tools/install-deps.sh GROUP... (host cli python toolchains clang cmake bench bench-query svg fuzz doxygen gcovr prove analyzer misra jcv)" >&2
    exit 2
fi
# an unknown group is an error even when nothing is missing
for group in "$@"; do members "$group" >/dev/null; done

missing=$(missing_packages "$@")
[ -z "$missing" ] && exit 0

echo "install-deps: missing: $missing" >&2
# shellcheck disable=SC2086  # missing is a word list on purpose
"$(dirname "$0")/apt-install.sh" install-deps $missing

missing=$(missing_packages "$@")
if [ -n "$missing" ]; then
    echo "install-deps: still missing after install: $missing" >&2
    exit 1
fi
echo "install-deps: installed what $* need" >&2
