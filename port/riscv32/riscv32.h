/* SPDX-License-Identifier: MIT */
/*
 * port/riscv32/riscv32.h - private declarations shared by the RISC-V port
 * files (not part of vor's interface; see port/port.h for that).
 */
#ifndef VOR_PORT_RISCV32_H
#define VOR_PORT_RISCV32_H

#include <stdint.h>

#include "../common/fault_line.h"

/*
 * CSR access without the Zicsr extension in -march: -march=rv32imac_zicsr
 * picks a wrong multilib with some toolchains, and binutils >= 2.38 refuses
 * csrr under plain rv32imac. `.insn i SYSTEM, funct3, rd, rs1, csr` is the
 * same instruction (CSRRS = 2 reads, CSRRW = 1 writes); the 12-bit CSR
 * number goes in as a signed immediate, hence VOR_RV_CSR_IMM.
 */
#define VOR_RV_CSR_IMM(csr) ((csr) >= 0x800 ? (csr)-0x1000 : (csr))
#define VOR_RV_CSR_READ(csr, var) \
    __asm__ volatile(".insn i 0x73, 2, %0, x0, %1" \
                     : "=r"(var) : "n"(VOR_RV_CSR_IMM(csr)) : "memory")
#define VOR_RV_CSR_WRITE(csr, value) \
    __asm__ volatile(".insn i 0x73, 1, x0, %0, %1" \
                     : : "r"(value), "n"(VOR_RV_CSR_IMM(csr)) : "memory")

#define VOR_RV_CSR_MTVEC 0x305
#define VOR_RV_CSR_MEPC 0x341
#define VOR_RV_CSR_MCAUSE 0x342
#define VOR_RV_CSR_MTVAL 0x343
#define VOR_RV_CSR_PMPCFG0 0x3A0
#define VOR_RV_CSR_PMPADDR0 0x3B0
#define VOR_RV_CSR_MINSTRET 0xB02
#define VOR_RV_CSR_MINSTRETH 0xB82

/* QEMU virt's SiFive test device: writing (status << 16) | 0x3333 makes
 * QEMU exit with that status (0x5555: exit 0). The last resort when
 * semihosting itself fails. */
#define VOR_RV_VIRT_TEST (*(volatile uint32_t *)0x00100000u)

/* Exit through the SiFive test device, without semihosting. */
void vor__rv_test_exit(int status) VOR_PORT_NORETURN;

#endif
