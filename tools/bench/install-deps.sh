#!/bin/sh
# tools/bench/install-deps.sh - make sure the host benchmarks' peers are
# installed, all from Debian packages: CGAL (libcgal-dev, header-only in
# CGAL 5), Boost.Polygon (libboost-dev) and nanoflann (libnanoflann-dev).
# Only tools/bench uses them; the library never does.
#
#   tools/bench/install-deps.sh [PACKAGE...]   check; install what is missing
#
# PACKAGE is one of the three above; without any, the two that `make bench`
# needs (libcgal-dev libboost-dev). `make bench-query` asks for
# libcgal-dev libnanoflann-dev.
#
# Quiet and exit 0 when all are present. When something is missing: as
# root, installs the packages with apt-get; otherwise prints the command to
# run and exits 1 (tools/apt-install.sh).
set -eu

[ $# -gt 0 ] || set -- libcgal-dev libboost-dev

# The header that shows each package is installed.
header_of() {
    case $1 in
    libcgal-dev) echo /usr/include/CGAL/Delaunay_triangulation_2.h ;;
    libboost-dev) echo /usr/include/boost/polygon/voronoi.hpp ;;
    libnanoflann-dev) echo /usr/include/nanoflann.hpp ;;
    *)
        echo "install-deps: unknown package $1" >&2
        exit 2
        ;;
    esac
}

missing_packages() {
    for package in "$@"; do
        [ -f "$(header_of "$package")" ] || printf '%s ' "$package"
    done
    command -v g++ >/dev/null 2>&1 || printf 'g++ '
}

for package in "$@"; do header_of "$package" >/dev/null; done
missing=$(missing_packages "$@")
[ -z "$missing" ] && exit 0

echo "install-deps: missing: $missing" >&2
"$(dirname "$0")/../apt-install.sh" install-deps "$@" g++

missing=$(missing_packages "$@")
if [ -n "$missing" ]; then
    echo "install-deps: still missing after install: $missing" >&2
    exit 1
fi
echo "install-deps: benchmark dependencies installed" >&2
