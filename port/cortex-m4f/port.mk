# SPDX-License-Identifier: MIT
# port/cortex-m4f/port.mk - Cortex-M4F under QEMU's mps2-an386 board.
# Hard-float ABI (vor itself uses no floating point; startup.c enables the
# FPU for code that does).
TARGET_NAME = cortex-m4f
CPU_CFLAGS = -mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16
QEMU_MACHINE = -M mps2-an386 -cpu cortex-m4
# SysTick on the 25 MHz processor clock of MPS2: 40 ns per tick.
HALF_NS_PER_TICK = 80
include $(VOR_ROOT)port/cortex-m/cortex-m.mk
