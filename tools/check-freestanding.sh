#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# check-freestanding.sh NM ARCHIVE
#
# The library must call nothing outside itself: no libc (memcpy, printf,
# malloc, ...), no soft-float routines (__aeabi_f*, __aeabi_d*, __addsf3, ...)
# and no other compiler runtime helper either, so it links into any firmware
# with no surprises. Any undefined symbol in ARCHIVE fails the check; the
# message says which kind each one is.
set -u
nm_tool=$1
archive=$2
# nm prints nothing for a missing archive, which must not pass
if [ ! -f "$archive" ]; then
    echo "$archive: no such archive"
    exit 1
fi
# undefined in some object and defined in none: calls leaving the library
defined=$("$nm_tool" --defined-only "$archive" 2>/dev/null | awk 'NF == 3 { print $3 }' | sort -u)
undefined=$("$nm_tool" -u "$archive" 2>/dev/null | awk 'NF == 2 && $1 == "U" { print $2 }' | sort -u |
    comm -23 - <(printf '%s\n' "$defined"))
status=0
for symbol in $undefined; do
    case "$symbol" in
        __aeabi_f*|__aeabi_d*|__aeabi_i2f|__aeabi_i2d|__aeabi_l2f|__aeabi_l2d|__aeabi_ui2*|__aeabi_ul2*|__*sf[23]|__*df[23]|__*sf[23]_vfp|__*df[23]_vfp|__fix*|__float*|__extend*|__trunc*)
            kind="soft-float routine" ;;
        mem*|str*|*printf|malloc|calloc|realloc|free|abort|exit|assert|__assert*|puts|putchar|sqrt*|floor*|ceil*|pow*)
            kind="libc function" ;;
        *)
            kind="external symbol" ;;
    esac
    echo "$archive: calls $kind $symbol"
    status=1
done
exit $status
