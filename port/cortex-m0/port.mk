# SPDX-License-Identifier: MIT
# port/cortex-m0/port.mk - Cortex-M0 under QEMU's microbit board (nRF51),
# its memory enlarged to 4 MB flash and 2 MB RAM for the test tables.
TARGET_NAME = cortex-m0
CPU_CFLAGS = -mcpu=cortex-m0 -mthumb
QEMU_MACHINE = -M microbit -cpu cortex-m0 \
               -global nrf51-soc.sram-size=2097152 -global nrf51-soc.flash-size=4194304
# QEMU gives the nRF51 a SysTick on its 16 MHz HCLK (real nRF51 silicon has
# none: use TIMER0 there): 62.5 ns per tick.
HALF_NS_PER_TICK = 125
include $(VOR_ROOT)port/cortex-m/cortex-m.mk
