# port/cortex-m0/port.mk - Cortex-M0 under QEMU's microbit board (nRF51).
# Included by the top-level Makefile (include port/$(PORT)/port.mk); every
# path is relative to the repository root, or to $(VOR_ROOT) when set.

TARGET_NAME = cortex-m0
EXE = .elf

CROSS ?= arm-none-eabi-
CC = $(CROSS)gcc
AR = $(CROSS)ar
NM = $(CROSS)nm
SIZE = $(CROSS)size
OBJCOPY = $(CROSS)objcopy

# For the library and for firmware objects alike. -ffreestanding: there is
# no C library (only the compiler's own headers, like on riscv32). The
# section flags let --gc-sections drop whatever a program does not use.
ARCH_CFLAGS = -mcpu=cortex-m0 -mthumb -ffreestanding \
              -ffunction-sections -fdata-sections

PORT_SRCS = $(VOR_ROOT)port/cortex-m/startup.c \
            $(VOR_ROOT)port/cortex-m/semihost.c \
            $(VOR_ROOT)port/cortex-m/systick.c \
            $(VOR_ROOT)port/cortex-m/mem.c \
            $(VOR_ROOT)port/cortex-m0/board.c

FW_LDFLAGS = -nostdlib -nostartfiles -T $(VOR_ROOT)port/cortex-m0/link.ld \
             -Wl,--gc-sections
FW_LDLIBS = -lgcc

# $(RUN) prog.elf runs it and returns its exit status. -icount shift=0
# makes one instruction one virtual nanosecond, which is what
# vor_port_counter counts.
RUN_TIMEOUT ?= 600
QEMU_ARM ?= qemu-system-arm
RUN = timeout $(RUN_TIMEOUT) $(QEMU_ARM) -M microbit -cpu cortex-m0 \
      -global nrf51-soc.sram-size=2097152 -global nrf51-soc.flash-size=4194304 \
      -icount shift=0,align=off,sleep=off \
      -nographic -monitor none -serial none \
      -semihosting-config enable=on,target=native -kernel
