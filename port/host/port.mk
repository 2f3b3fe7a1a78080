# SPDX-License-Identifier: MIT
# port/host/port.mk - the machine the build runs on (Linux, macOS, BSD):
# tests, examples and benchmarks run as ordinary programs.
# Included by the top-level Makefile (include port/$(PORT)/port.mk); every
# path is relative to the repository root, or to $(VOR_ROOT) when set.

TARGET_NAME = host
EXE =

# gcc unless the command line or environment names another (CC=clang).
ifeq ($(origin CC),default)
CC = gcc
endif
ifeq ($(origin AR),default)
AR = ar
endif
NM ?= nm
SIZE ?= size
OBJCOPY ?= objcopy

ARCH_CFLAGS =

PORT_SRCS = $(VOR_ROOT)port/host/port.c

FW_LDFLAGS =
FW_LDLIBS =

# Host programs run directly: $(RUN) prog is just prog.
RUN_TIMEOUT ?= 600
RUN =
