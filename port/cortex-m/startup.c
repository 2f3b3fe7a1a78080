/* SPDX-License-Identifier: MIT */
/*
 * port/cortex-m/startup.c - vector table, reset handler and fault handlers
 * shared by every Cortex-M target (ARMv6-M and ARMv7-M/ARMv7E-M).
 *
 * The reset handler enables the FPU when the code is built for one
 * (__ARM_FP, e.g. cortex-m4f's hard-float ABI), copies .data from flash,
 * zeroes .bss, fills the unused stack with VOR_PORT_STACK_PAINT so the
 * stack high-water mark can be measured (scan up from __stack_bottom for
 * the first other word), enables the configurable faults and the stack
 * guard (ARMv7-M), calls vor_port_init() and main(), and passes main's
 * return value to vor_port_exit().
 *
 * Every fault and every exception without a handler lands in
 * vor__cm_fault_entry, which prints one line
 *     fatal: BusFault pc=0x000002ae lr=0x000002ab sp=0x20000fd0 cfsr=0x00008200
 * and exits with status 99. The names NMI_Handler, SVC_Handler,
 * DebugMon_Handler, PendSV_Handler and SysTick_Handler are weak: define a
 * function of that name to handle the exception instead.
 *
 * On ARMv7-M cores with an MPU it also makes the __stack_guard_size bytes
 * at __stack_guard, just below the stack, inaccessible: a stack overflow
 * then faults ("fatal: MemManage sp=0x... outside the stack (overflow)")
 * instead of silently writing past the stack. On ARMv8-M Mainline
 * (cortex-m33) the main stack limit register does it: MSPLIM =
 * __stack_bottom, and an overflow is a UsageFault.
 *
 * Symbols the linker script must define (see port/cortex-m3/link.ld):
 *   __stack_top, __stack_bottom   initial SP (8-byte aligned) and stack end
 *   __stack_guard, __stack_guard_size   (ARMv7-M only) the guard region, a
 *                                 power of two >= 32 bytes, aligned to it
 *   __data_load                   load address of .data in flash
 *   __data_start, __data_end      run address range of .data in RAM
 *   __bss_start, __bss_end        range of .bss in RAM
 * and the section .vectors must be KEEP()ed at the reset vector address.
 */
#include "../port.h"
#include "../common/fault_line.h"

#include "cortex-m.h"

/* Word written over the unused stack at reset. */
#define VOR_PORT_STACK_PAINT 0x5AA55AA5u

#define SCB_SHCSR (*(volatile uint32_t *)0xE000ED24u)
#define SCB_CFSR (*(volatile uint32_t *)0xE000ED28u)
#define SCB_CPACR (*(volatile uint32_t *)0xE000ED88u)
#define MPU_TYPE (*(volatile uint32_t *)0xE000ED90u)
#define MPU_CTRL (*(volatile uint32_t *)0xE000ED94u)
#define MPU_RNR (*(volatile uint32_t *)0xE000ED98u)
#define MPU_RBAR (*(volatile uint32_t *)0xE000ED9Cu)
#define MPU_RASR (*(volatile uint32_t *)0xE000EDA0u)

#if defined(__ARM_ARCH_7M__) || defined(__ARM_ARCH_7EM__) \
    || defined(__ARM_ARCH_8M_MAIN__)
#define VOR_PORT_HAVE_CFSR 1
#else
#define VOR_PORT_HAVE_CFSR 0
#endif

extern uint32_t __stack_top[];
extern uint32_t __stack_bottom[];
extern const uint32_t __data_load[];
extern uint32_t __data_start[];
extern uint32_t __data_end[];
extern uint32_t __bss_start[];
extern uint32_t __bss_end[];
#if VOR_PORT_HAVE_CFSR
extern uint32_t __stack_guard[];
extern const char __stack_guard_size[];
#endif

int main(void);

void Reset_Handler(void) VOR_PORT_NORETURN;
void vor__cm_fault_entry(void);
void vor__cm_fault(uint32_t pc, uint32_t lr, uint32_t sp) VOR_PORT_NORETURN
    VOR_PORT_USED;
void NMI_Handler(void);
void HardFault_Handler(void);
void MemManage_Handler(void);
void BusFault_Handler(void);
void UsageFault_Handler(void);
void SVC_Handler(void);
void DebugMon_Handler(void);
void PendSV_Handler(void);
void SysTick_Handler(void);

/*
 * The fault entry, in assembly so that it can find the stacked frame before
 * a C prologue moves SP. It picks MSP or PSP from EXC_RETURN bit 2; when the
 * frame lies inside the main stack it loads the stacked LR (frame word 5)
 * and PC (word 6), otherwise (stack overflow: stacking itself failed) it
 * passes pc = lr = 0 and reads nothing from the bad stack, which would only
 * fault again and lock the core up. Then it restarts on a fresh stack at
 * __stack_top and reports: vor__cm_fault(pc, lr, sp). Thumb-1 only, so the
 * same code runs on ARMv6-M.
 */
__asm__(
    "  .pushsection .text.vor__cm_fault_entry,\"ax\",%progbits\n"
    "  .syntax unified\n"
    "  .thumb\n"
    "  .balign 4\n"
    "  .global vor__cm_fault_entry\n"
    "  .type vor__cm_fault_entry, %function\n"
    "  .thumb_func\n"
    "vor__cm_fault_entry:\n"
    "  mov r2, lr\n"
    "  movs r3, #4\n"
    "  tst r2, r3\n"
    "  beq 1f\n"
    "  mrs r2, psp\n"
    "  b 2f\n"
    "1:\n"
    "  mrs r2, msp\n"
    "  ldr r3, =__stack_bottom\n"
    "  cmp r2, r3\n"
    "  blo 3f\n"
    "  ldr r3, =__stack_top - 32\n"
    "  cmp r2, r3\n"
    "  bhi 3f\n"
    "2:\n"
    "  ldr r1, [r2, #20]\n"
    "  ldr r0, [r2, #24]\n"
    "  b 4f\n"
    "3:\n"
    "  movs r0, #0\n"
    "  movs r1, #0\n"
    "4:\n"
    "  ldr r3, =__stack_top\n"
    "  mov sp, r3\n"
    "  bl vor__cm_fault\n"
    "  .ltorg\n"
    "  .size vor__cm_fault_entry, . - vor__cm_fault_entry\n"
    "  .global HardFault_Handler\n"
    "  .thumb_set HardFault_Handler, vor__cm_fault_entry\n"
    "  .global MemManage_Handler\n"
    "  .thumb_set MemManage_Handler, vor__cm_fault_entry\n"
    "  .global BusFault_Handler\n"
    "  .thumb_set BusFault_Handler, vor__cm_fault_entry\n"
    "  .global UsageFault_Handler\n"
    "  .thumb_set UsageFault_Handler, vor__cm_fault_entry\n"
    "  .weak NMI_Handler\n"
    "  .thumb_set NMI_Handler, vor__cm_fault_entry\n"
    "  .weak SVC_Handler\n"
    "  .thumb_set SVC_Handler, vor__cm_fault_entry\n"
    "  .weak DebugMon_Handler\n"
    "  .thumb_set DebugMon_Handler, vor__cm_fault_entry\n"
    "  .weak PendSV_Handler\n"
    "  .thumb_set PendSV_Handler, vor__cm_fault_entry\n"
    "  .weak SysTick_Handler\n"
    "  .thumb_set SysTick_Handler, vor__cm_fault_entry\n"
    "  .popsection\n");

/* The 16 system vectors; no peripheral interrupt is used, so an enabled
 * one would find no vector and fault, which vor__cm_fault_entry reports. */
struct vor__cm_vectors {
    uint32_t *initial_sp;
    void (*handler[15])(void);
};

#if defined(__GNUC__)
__attribute__((section(".vectors"), used))
#endif
const struct vor__cm_vectors vor__cm_vectors = {
    __stack_top,
    {
        Reset_Handler,      /*  1 */
        NMI_Handler,        /*  2 */
        HardFault_Handler,  /*  3 */
        MemManage_Handler,  /*  4, ARMv7-M */
        BusFault_Handler,   /*  5, ARMv7-M */
        UsageFault_Handler, /*  6, ARMv7-M */
        0,                  /*  7 */
        0,                  /*  8 */
        0,                  /*  9 */
        0,                  /* 10 */
        SVC_Handler,        /* 11 */
        DebugMon_Handler,   /* 12, ARMv7-M */
        0,                  /* 13 */
        PendSV_Handler,     /* 14 */
        SysTick_Handler,    /* 15 */
    },
};

static const char *exception_name(uint32_t number)
{
    switch (number) {
    case 2u: return "NMI";
    case 3u: return "HardFault";
    case 4u: return "MemManage";
    case 5u: return "BusFault";
    case 6u: return "UsageFault";
    case 11u: return "SVCall";
    case 12u: return "DebugMon";
    case 14u: return "PendSV";
    case 15u: return "SysTick";
    default: return "unexpected exception";
    }
}


/*
 * Print one line and exit with VOR_PORT_FAULT_STATUS:
 *     fatal: BusFault pc=0x000002ae lr=0x000002ab sp=0x20000fd0 cfsr=0x00008200
 *     fatal: HardFault sp=0x1ffffff0 outside the stack (overflow)
 * Runs on a fresh stack at __stack_top, still in handler mode. A second
 * fault while reporting the first skips the report and just exits.
 */
void vor__cm_fault(uint32_t pc, uint32_t lr, uint32_t sp)
{
    static volatile int reporting = 0;
    char line[128];
    size_t n = 0;
    uint32_t ipsr;

    if (reporting) {
        vor_port_exit(VOR_PORT_FAULT_STATUS);
    }
    reporting = 1;
    __asm__ volatile("mrs %0, ipsr" : "=r"(ipsr));
    n = vor__line_text(line, n, sizeof line, "fatal: ");
    n = vor__line_text(line, n, sizeof line, exception_name(ipsr & 0x1FFu));
    if (pc == 0u && lr == 0u) {
        n = vor__line_hex(line, n, sizeof line, " sp=0x", sp);
        n = vor__line_text(line, n, sizeof line, " outside the stack (overflow)");
    } else {
        n = vor__line_hex(line, n, sizeof line, " pc=0x", pc);
        n = vor__line_hex(line, n, sizeof line, " lr=0x", lr);
        n = vor__line_hex(line, n, sizeof line, " sp=0x", sp);
    }
#if VOR_PORT_HAVE_CFSR
    n = vor__line_hex(line, n, sizeof line, " cfsr=0x", SCB_CFSR);
#endif
    line[n++] = '\n';
    vor_port_write(line, n);
    vor_port_exit(VOR_PORT_FAULT_STATUS);
}

#if VOR_PORT_HAVE_CFSR && defined(__ARM_ARCH_8M_MAIN__)
/* ARMv8-M: the main stack limit register. A push below __stack_bottom
 * raises a UsageFault (STKOF) instead of writing into the guard; the
 * PMSAv8 MPU has no no-access region to make one. */
static void guard_stack(void)
{
    __asm__ volatile("msr msplim, %0" : : "r"(__stack_bottom) : "memory");
}
#elif VOR_PORT_HAVE_CFSR
/* MPU region 0: __stack_guard, no access, never execute; everything else
 * keeps the default memory map (PRIVDEFENA). Skipped without an MPU. */
static void guard_stack(void)
{
    uint32_t size = (uint32_t)(uintptr_t)__stack_guard_size;
    uint32_t log2 = 0u;

    if (((MPU_TYPE >> 8) & 0xFFu) == 0u || size < 32u) {
        return;
    }
    while ((2u << log2) <= size) { /* at most 31 steps */
        log2++;
    }
    MPU_RNR = 0u;
    MPU_RBAR = (uint32_t)(uintptr_t)__stack_guard;
    MPU_RASR = (1u << 28)      /* XN */
               | (0u << 24)    /* AP: no access */
               | ((log2 - 1u) << 1)
               | 1u;           /* enable */
    MPU_CTRL = (1u << 2) | 1u; /* PRIVDEFENA | ENABLE */
    __asm__ volatile("dsb\n\tisb" ::: "memory");
}
#endif

void Reset_Handler(void)
{
    const uint32_t *src;
    uint32_t *dst;
    volatile uint32_t *paint;
    uint32_t *sp;

#if defined(__ARM_FP)
    /* CP10 and CP11 full access, before any floating-point instruction. */
    SCB_CPACR |= 0xFu << 20;
    __asm__ volatile("dsb\n\tisb" ::: "memory");
#endif

    /* Copy .data from flash to RAM; the bounds come from the linker. */
    src = __data_load;
    for (dst = __data_start; dst < __data_end; dst++) {
        *dst = *src++;
    }
    for (dst = __bss_start; dst < __bss_end; dst++) {
        *dst = 0u;
    }

    /* Paint the stack below the current frame; volatile keeps the compiler
     * from turning the loop into a memset call that would run on the very
     * memory being painted. */
    __asm__ volatile("mov %0, sp" : "=r"(sp));
    for (paint = __stack_bottom; paint < (volatile uint32_t *)sp; paint++) {
        *paint = VOR_PORT_STACK_PAINT;
    }

#if VOR_PORT_HAVE_CFSR
    /* Report MemManage, BusFault and UsageFault under their own names
     * instead of escalating them to HardFault. */
    SCB_SHCSR |= (1u << 16) | (1u << 17) | (1u << 18);
    __asm__ volatile("dsb\n\tisb" ::: "memory");
    guard_stack();
#endif

    /* main() calls vor_port_init() first too; calling it here as well
     * (it is idempotent) means the counter runs even if a program forgets. */
    vor_port_init();
    vor_port_exit(main());
}
