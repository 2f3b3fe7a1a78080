# SPDX-License-Identifier: MIT
# port/riscv32/port.mk - RV32IMAC in machine mode under QEMU's virt board.
# Included by the top-level Makefile (include port/$(PORT)/port.mk); every
# path is relative to the repository root, or to $(VOR_ROOT) when set.

TARGET_NAME = riscv32
EXE = .elf

CROSS ?= riscv64-unknown-elf-
CC = $(CROSS)gcc
AR = $(CROSS)ar
NM = $(CROSS)nm
SIZE = $(CROSS)size
OBJCOPY = $(CROSS)objcopy

# For the library and for firmware objects alike. No _zicsr in -march: it
# picks a wrong multilib (the port reads CSRs with .insn). -ffreestanding:
# there is no C library, and this compiler's <stdint.h> looks for one
# unless told. The section flags let --gc-sections drop whatever a
# program does not use.
ARCH_CFLAGS = -march=rv32imac -mabi=ilp32 -mcmodel=medany -ffreestanding \
              -ffunction-sections -fdata-sections

PORT_SRCS = $(VOR_ROOT)port/riscv32/startup.c \
            $(VOR_ROOT)port/riscv32/semihost_call.c \
            $(VOR_ROOT)port/riscv32/counter.c \
            $(VOR_ROOT)port/common/semihost.c \
            $(VOR_ROOT)port/common/mem.c \
            $(VOR_ROOT)port/common/fault_line.c

FW_LDFLAGS = -nostdlib -nostartfiles -T $(VOR_ROOT)port/riscv32/link.ld \
             -Wl,--gc-sections
FW_LDLIBS = -lgcc

# $(RUN) prog.elf runs it and returns its exit status. QEMU's minstret
# counts instructions only under -icount (without it, host CPU ticks).
RUN_TIMEOUT ?= 600
QEMU_RISCV32 ?= qemu-system-riscv32
RUN = timeout $(RUN_TIMEOUT) $(QEMU_RISCV32) -M virt -bios none \
      -icount shift=0,align=off,sleep=off \
      -nographic -monitor none -serial none \
      -semihosting-config enable=on,target=native -kernel
