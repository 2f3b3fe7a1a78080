# SPDX-License-Identifier: MIT
# port/cortex-m3/port.mk - Cortex-M3 under QEMU's mps2-an385 board.
TARGET_NAME = cortex-m3
CPU_CFLAGS = -mcpu=cortex-m3 -mthumb
QEMU_MACHINE = -M mps2-an385 -cpu cortex-m3
# SysTick on the 25 MHz processor clock of MPS2: 40 ns per tick.
HALF_NS_PER_TICK = 80
include $(VOR_ROOT)port/cortex-m/cortex-m.mk
