#!/bin/sh
# tools/install-toolchain.sh - make sure the cross toolchains and emulators
# vor's target builds and tests need are installed (Debian/Ubuntu); clang
# for the freestanding check, which compiles the library with it too.
#
#   tools/install-toolchain.sh        check; install what is missing
#
# Quiet and exit 0 when everything is present; safe to run any number of
# times. When something is missing: as root, installs the packages with
# apt-get; otherwise prints the command to run and exits 1
# (tools/apt-install.sh).
set -eu

PACKAGES="gcc-arm-none-eabi libnewlib-arm-none-eabi picolibc-arm-none-eabi \
gcc-riscv64-unknown-elf picolibc-riscv64-unknown-elf \
qemu-system-arm qemu-system-misc clang"

missing_tools() {
    for tool in arm-none-eabi-gcc riscv64-unknown-elf-gcc \
                qemu-system-arm qemu-system-riscv32 python3 clang; do
        command -v "$tool" >/dev/null 2>&1 || printf '%s ' "$tool"
    done
}

missing=$(missing_tools)
[ -z "$missing" ] && exit 0

echo "install-toolchain: missing: $missing" >&2
# shellcheck disable=SC2086  # PACKAGES is a word list on purpose
"$(dirname "$0")/apt-install.sh" install-toolchain $PACKAGES python3

missing=$(missing_tools)
if [ -n "$missing" ]; then
    echo "install-toolchain: still missing after install: $missing" >&2
    exit 1
fi
echo "install-toolchain: toolchains installed" >&2
