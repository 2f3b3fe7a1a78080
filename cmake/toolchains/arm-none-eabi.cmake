# SPDX-License-Identifier: MIT
# Shared part of the arm-none-eabi toolchain files: bare metal, GCC from
# PATH (or ARM_NONE_EABI_PREFIX, e.g. /opt/gcc-arm/bin/arm-none-eabi-).
# The file that includes this sets vor_cpu_flags, the -mcpu/-mthumb/FPU
# flags of port/<target>/port.mk.
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)
if(NOT DEFINED ARM_NONE_EABI_PREFIX)
    set(ARM_NONE_EABI_PREFIX arm-none-eabi-)
endif()
set(CMAKE_C_COMPILER ${ARM_NONE_EABI_PREFIX}gcc)
set(CMAKE_ASM_COMPILER ${ARM_NONE_EABI_PREFIX}gcc)
set(CMAKE_AR ${ARM_NONE_EABI_PREFIX}ar CACHE FILEPATH "")
# A test program cannot link without a startup file and linker script.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
set(CMAKE_C_FLAGS_INIT "${vor_cpu_flags}")
set(CMAKE_ASM_FLAGS_INIT "${vor_cpu_flags}")
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
