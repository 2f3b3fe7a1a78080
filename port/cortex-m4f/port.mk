# port/cortex-m4f/port.mk - Cortex-M4F under QEMU's mps2-an386 board.
# Included by the top-level Makefile (include port/$(PORT)/port.mk); every
# path is relative to the repository root, or to $(VOR_ROOT) when set.

TARGET_NAME = cortex-m4f
EXE = .elf

CROSS ?= arm-none-eabi-
CC = $(CROSS)gcc
AR = $(CROSS)ar
NM = $(CROSS)nm
SIZE = $(CROSS)size
OBJCOPY = $(CROSS)objcopy

# For the library and for firmware objects alike. Hard-float ABI (vor
# itself uses no floating point; startup.c enables the FPU). -ffreestanding: there is
# no C library (only the compiler's own headers, like on riscv32). The
# section flags let --gc-sections drop whatever a program does not use.
ARCH_CFLAGS = -mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16 \
              -ffreestanding -ffunction-sections -fdata-sections

PORT_SRCS = $(VOR_ROOT)port/cortex-m/startup.c \
            $(VOR_ROOT)port/cortex-m/semihost.c \
            $(VOR_ROOT)port/cortex-m/systick.c \
            $(VOR_ROOT)port/cortex-m/mem.c \
            $(VOR_ROOT)port/cortex-m4f/board.c

FW_LDFLAGS = -nostdlib -nostartfiles -T $(VOR_ROOT)port/cortex-m4f/link.ld \
             -Wl,--gc-sections
FW_LDLIBS = -lgcc

# $(RUN) prog.elf runs it and returns its exit status. -icount shift=0
# makes one instruction one virtual nanosecond, which is what
# vor_port_counter counts.
RUN_TIMEOUT ?= 600
QEMU_ARM ?= qemu-system-arm
RUN = timeout $(RUN_TIMEOUT) $(QEMU_ARM) -M mps2-an386 -cpu cortex-m4 \
      -icount shift=0,align=off,sleep=off \
      -nographic -monitor none -serial none \
      -semihosting-config enable=on,target=native -kernel
