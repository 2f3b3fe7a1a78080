# port/cortex-m0/port.mk - Cortex-M0 under QEMU's microbit board (nRF51),
# its memory enlarged to 4 MB flash and 2 MB RAM for the test tables.
TARGET_NAME = cortex-m0
CPU_CFLAGS = -mcpu=cortex-m0 -mthumb
QEMU_MACHINE = -M microbit -cpu cortex-m0 \
               -global nrf51-soc.sram-size=2097152 -global nrf51-soc.flash-size=4194304
include $(VOR_ROOT)port/cortex-m/cortex-m.mk
