# SPDX-License-Identifier: MIT
# Cortex-M0 with arm-none-eabi-gcc; the flags of port/cortex-m0/port.mk.
#   cmake -B build -DCMAKE_TOOLCHAIN_FILE=path/to/vor/cmake/toolchains/arm-none-eabi-cortex-m0.cmake
set(vor_cpu_flags "-mcpu=cortex-m0 -mthumb")
include(${CMAKE_CURRENT_LIST_DIR}/arm-none-eabi.cmake)
