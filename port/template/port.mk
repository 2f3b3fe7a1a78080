# SPDX-License-Identifier: MIT
# port/template/port.mk - copy to port/<your-target>/port.mk and fill in.
# The top-level Makefile does `include port/$(PORT)/port.mk`, so
# `make PORT=<your-target> test` builds and runs the test suite with it.
# Paths are relative to the repository root ($(VOR_ROOT) is empty there).
# Working examples: port/cortex-m3/port.mk (ARM), port/riscv32/port.mk.

# Name printed in reports, and the suffix of built programs.
TARGET_NAME = my-board
EXE = .elf

# Toolchain. Anything here can be overridden on the make command line.
CROSS ?= arm-none-eabi-
CC = $(CROSS)gcc
AR = $(CROSS)ar
NM = $(CROSS)nm
SIZE = $(CROSS)size
OBJCOPY = $(CROSS)objcopy

# Flags for the library AND the firmware objects: the CPU, the ABI, and
#   -ffreestanding              there is no C library (vor needs none)
#   -ffunction-sections -fdata-sections   so --gc-sections can drop what a
#                               program does not use
ARCH_CFLAGS = -mcpu=cortex-m4 -mthumb -ffreestanding \
              -ffunction-sections -fdata-sections

# The port's sources, compiled with ARCH_CFLAGS and linked into every test,
# example and benchmark program (never into the library): startup code and
# vector table, the port.h functions, and memcpy/memset/memmove/memcmp/
# strlen if no C library provides them (GCC emits calls to them even in
# freestanding code; port/common/mem.c has portable weak ones).
PORT_SRCS = $(VOR_ROOT)port/template/port.c \
            $(VOR_ROOT)port/common/mem.c

# Link flags: your linker script, no C library or its startup files,
# unused sections dropped; -lgcc for the compiler's helpers (64-bit
# division, etc.).
FW_LDFLAGS = -nostdlib -nostartfiles -T $(VOR_ROOT)port/template/link.ld \
             -Wl,--gc-sections
FW_LDLIBS = -lgcc

# `$(RUN) path/to/prog.elf` must run the program and return its exit
# status, as printed by vor_port_exit; a hang must end, hence timeout.
# Under QEMU keep -icount shift=0,align=off,sleep=off so the counter is
# repeatable. For a real board this is a script that flashes the program,
# collects its output and returns its status (e.g. through a debug probe
# with semihosting: pyOCD, OpenOCD).
RUN_TIMEOUT ?= 600
RUN = timeout $(RUN_TIMEOUT) qemu-system-arm -M my-machine \
      -icount shift=0,align=off,sleep=off \
      -nographic -monitor none -serial none \
      -semihosting-config enable=on,target=native -kernel
