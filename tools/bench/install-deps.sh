#!/bin/sh
# tools/bench/install-deps.sh - make sure the host benchmark's peers are
# installed: CGAL (libcgal-dev, header-only in CGAL 5) and Boost.Polygon
# (libboost-dev), both from Debian packages. Only tools/bench uses them;
# the library never does.
#
#   tools/bench/install-deps.sh     check; install what is missing
#
# Quiet and exit 0 when both are present. When something is missing: as
# root, installs the packages with apt-get; otherwise prints the command to
# run and exits 1 (tools/apt-install.sh).
set -eu

PACKAGES="libcgal-dev libboost-dev"

missing_headers() {
    [ -f /usr/include/CGAL/Delaunay_triangulation_2.h ] || printf 'libcgal-dev '
    [ -f /usr/include/boost/polygon/voronoi.hpp ] || printf 'libboost-dev '
    command -v g++ >/dev/null 2>&1 || printf 'g++ '
}

missing=$(missing_headers)
[ -z "$missing" ] && exit 0

echo "install-deps: missing: $missing" >&2
# shellcheck disable=SC2086  # PACKAGES is a word list on purpose
"$(dirname "$0")/../apt-install.sh" install-deps $PACKAGES g++

missing=$(missing_headers)
if [ -n "$missing" ]; then
    echo "install-deps: still missing after install: $missing" >&2
    exit 1
fi
echo "install-deps: benchmark dependencies installed" >&2
