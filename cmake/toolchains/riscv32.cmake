# SPDX-License-Identifier: MIT
# RV32IMAC, ilp32, with riscv64-unknown-elf-gcc (or RISCV_PREFIX); the
# flags of port/riscv32/port.mk. No _zicsr in -march: with Debian's
# picolibc it selects a wrong multilib.
#   cmake -B build -DCMAKE_TOOLCHAIN_FILE=path/to/vor/cmake/toolchains/riscv32.cmake
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR riscv32)
if(NOT DEFINED RISCV_PREFIX)
    set(RISCV_PREFIX riscv64-unknown-elf-)
endif()
set(CMAKE_C_COMPILER ${RISCV_PREFIX}gcc)
set(CMAKE_ASM_COMPILER ${RISCV_PREFIX}gcc)
set(CMAKE_AR ${RISCV_PREFIX}ar CACHE FILEPATH "")
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
set(CMAKE_C_FLAGS_INIT "-march=rv32imac -mabi=ilp32 -mcmodel=medany")
set(CMAKE_ASM_FLAGS_INIT "-march=rv32imac -mabi=ilp32 -mcmodel=medany")
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
