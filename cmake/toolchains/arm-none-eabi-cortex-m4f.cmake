# SPDX-License-Identifier: MIT
# Cortex-M4F with arm-none-eabi-gcc; the flags of port/cortex-m4f/port.mk.
#   cmake -B build -DCMAKE_TOOLCHAIN_FILE=path/to/vor/cmake/toolchains/arm-none-eabi-cortex-m4f.cmake
set(vor_cpu_flags "-mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16")
include(${CMAKE_CURRENT_LIST_DIR}/arm-none-eabi.cmake)
