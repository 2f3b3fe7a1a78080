#!/bin/sh
# SPDX-License-Identifier: MIT
# tools/apt-install.sh WHO PACKAGE... - install Debian packages for one of
# the project's scripts: as root, apt-get update then install; otherwise
# print the exact command to run and exit 1. WHO names the caller in the
# messages. Only the packages named and what they depend on are installed:
# never what they merely recommend (hundreds of megabytes of GUI, codec and
# C++ libraries the project does not use).
set -eu
who=$1
shift
if [ "$(id -u)" -ne 0 ]; then
    echo "$who: run as root, or:" >&2
    echo "  sudo apt-get update && sudo DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends $*" >&2
    exit 1
fi
# Two builds started at once (make -j, or two checkouts) may both install:
# the second waits for the first. apt's DPkg::Lock::Timeout waits for
# dpkg's lock but not for the package lists' lock that `apt-get update`
# takes, so the project's installs also queue on a lock of their own
# (flock, util-linux: essential on Debian). Another program's apt run is
# still waited for only at dpkg's lock.
lock_wait="-o DPkg::Lock::Timeout=600"
exec 9>/var/lock/vor-apt-install.lock
flock -w 1200 9
# shellcheck disable=SC2086  # lock_wait is two words on purpose
apt-get $lock_wait update
# shellcheck disable=SC2086
DEBIAN_FRONTEND=noninteractive apt-get $lock_wait install -y --no-install-recommends "$@"
