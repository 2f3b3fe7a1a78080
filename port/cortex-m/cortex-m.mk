# SPDX-License-Identifier: MIT
# port/cortex-m/cortex-m.mk - what every Cortex-M target shares. A target's
# port.mk sets TARGET_NAME, CPU_CFLAGS, QEMU_MACHINE and HALF_NS_PER_TICK
# (its SysTick period under QEMU, in half nanoseconds), then includes this.
# Every path is relative to the repository root, or to $(VOR_ROOT) when set.

EXE = .elf

CROSS ?= arm-none-eabi-
CC = $(CROSS)gcc
AR = $(CROSS)ar
NM = $(CROSS)nm
SIZE = $(CROSS)size
OBJCOPY = $(CROSS)objcopy

# For the library and for firmware objects alike. -ffreestanding: there is
# no C library (only the compiler's own headers). The section flags let
# --gc-sections drop whatever a program does not use.
ARCH_CFLAGS = $(CPU_CFLAGS) -ffreestanding -ffunction-sections -fdata-sections

PORT_SRCS = $(VOR_ROOT)port/cortex-m/startup.c \
            $(VOR_ROOT)port/cortex-m/semihost_call.c \
            $(VOR_ROOT)port/cortex-m/systick.c \
            $(VOR_ROOT)port/common/semihost.c \
            $(VOR_ROOT)port/common/mem.c \
            $(VOR_ROOT)port/common/fault_line.c

# For the port's own sources only (the Makefile's port object rule).
PORT_CFLAGS = -DVOR_PORT_HALF_NS_PER_TICK=$(HALF_NS_PER_TICK)

FW_LDFLAGS = -nostdlib -nostartfiles -T $(VOR_ROOT)port/$(TARGET_NAME)/link.ld \
             -Wl,--gc-sections
FW_LDLIBS = -lgcc

# $(RUN) prog.elf runs it and returns its exit status. -icount shift=0
# makes one instruction one virtual nanosecond, which is what
# vor_port_counter counts.
RUN_TIMEOUT ?= 600
QEMU_ARM ?= qemu-system-arm
RUN = timeout $(RUN_TIMEOUT) $(QEMU_ARM) $(QEMU_MACHINE) \
      -icount shift=0,align=off,sleep=off \
      -nographic -monitor none -serial none \
      -semihosting-config enable=on,target=native -kernel
