# SPDX-License-Identifier: MIT
# port/cortex-m33/port.mk - Cortex-M33 under QEMU's mps2-an521 board (two
# Cortex-M33 cores; the programs run on core 0, and examples/dual starts
# core 1 itself). Soft-float ABI: vor uses no floating point.
TARGET_NAME = cortex-m33
CPU_CFLAGS = -mcpu=cortex-m33 -mthumb
QEMU_MACHINE = -M mps2-an521
# SysTick on the 20 MHz processor clock of QEMU's AN521: 50 ns per tick
# (calibrated with a loop of known length: exact to one tick).
HALF_NS_PER_TICK = 100
include $(VOR_ROOT)port/cortex-m/cortex-m.mk
