/* SPDX-License-Identifier: MIT */
/*
 * fork_join_an521.c - the two-core fork/join hook of fork_join_an521.h:
 * core 1 of QEMU's mps2-an521 (SSE-200) released from reset on the first
 * fork, a mailbox in shared RAM, and MHU0 as the doorbell each way.
 */
#include "fork_join_an521.h"

#include <stddef.h>

#include "port.h"

#define REG(address) (*(volatile uint32_t *)(address))

/* SSE-200 system control (secure alias): core 1's initial vector table
 * and the per-core wait bits (bit 1: core 1 held in reset). */
#define SYSCTL_INITSVTOR1 REG(0x50021114u)
#define SYSCTL_CPUWAIT REG(0x50021118u)
/* MHU0 (secure alias): a set/clear register pair per core; a nonzero
 * status raises that core's interrupt 6. */
#define MHU0_CPU0INTR_SET REG(0x50003004u)
#define MHU0_CPU0INTR_CLR REG(0x50003008u)
#define MHU0_CPU1INTR_SET REG(0x50003014u)
#define MHU0_CPU1INTR_CLR REG(0x50003018u)
#define MHU0_IRQ 6u
/* Each core's own NVIC (private peripheral bus). */
#define NVIC_ISER0 REG(0xE000E100u)
#define NVIC_ICER0 REG(0xE000E180u)
#define NVIC_ICPR0 REG(0xE000E280u)

#define STACK_PAINT 0xC0DE1111u
#define STACK_WORDS (AN521_CORE1_STACK_BYTES / 4u)

/* The mailbox. Core 0 writes work, arg and posted; core 1 writes
 * finished. A work is pending while finished != posted. */
static struct {
    void (*volatile work)(void *arg);
    void *volatile arg;
    volatile uint32_t posted;
    volatile uint32_t finished;
    uint32_t started; /* core 0 only: core 1 released */
} mailbox;

static uint32_t core1_stack[STACK_WORDS] __attribute__((aligned(8)));

static void core1_reset(void);
static void core1_fault(void);

/* Core 1's vector table: its own stack, its own entry, every exception to
 * core1_fault. Aligned to 128 bytes for INITSVTOR1. */
struct an521_vectors {
    uint32_t *initial_sp;
    void (*handler[15])(void);
};
static const struct an521_vectors core1_vectors __attribute__((aligned(128))) = {
    core1_stack + STACK_WORDS,
    {core1_reset, core1_fault, core1_fault, core1_fault, core1_fault, core1_fault, 0, 0, 0, 0,
     core1_fault, core1_fault, 0, core1_fault, core1_fault},
};

static void barrier_dmb(void)
{
    __asm__ volatile("dmb" ::: "memory");
}

static void barrier_dsb(void)
{
    __asm__ volatile("dsb" ::: "memory");
}

/* Sleep until *a == *b, waking at each ring of this core's MHU0 doorbell
 * (clear: its clear register). The interrupt is enabled in this core's
 * NVIC but masked by PRIMASK, so it wakes wfi without being taken (no
 * handler). The doorbell is cleared before the condition is read: a ring
 * after the read leaves the interrupt pending, and wfi then returns at
 * once. */
static void sleep_until(volatile uint32_t *a, volatile uint32_t *b, volatile uint32_t *clear)
{
    uint32_t primask;
    __asm__ volatile("mrs %0, primask" : "=r"(primask));
    __asm__ volatile("cpsid i" ::: "memory");
    NVIC_ISER0 = 1u << MHU0_IRQ;
    for (;;) { /* ends when the other core publishes its count */
        *clear = 1u;
        NVIC_ICPR0 = 1u << MHU0_IRQ;
        barrier_dsb();
        if (*a == *b) {
            break;
        }
        __asm__ volatile("wfi" ::: "memory");
    }
    NVIC_ICER0 = 1u << MHU0_IRQ;
    *clear = 1u;
    NVIC_ICPR0 = 1u << MHU0_IRQ;
    barrier_dsb();
    barrier_dmb(); /* the work's writes, published before *a, are read after */
    if ((primask & 1u) == 0u) {
        __asm__ volatile("cpsie i" ::: "memory");
    }
}

/* Core 1: wait for a posted work, run it, publish, ring core 0. */
static void core1_reset(void)
{
    uint32_t next;
    __asm__ volatile("msr msplim, %0" : : "r"(core1_stack) : "memory");
    __asm__ volatile("cpsid i" ::: "memory");
    NVIC_ISER0 = 1u << MHU0_IRQ;
    for (;;) { /* core 1 runs until the machine stops */
        MHU0_CPU1INTR_CLR = 1u;
        NVIC_ICPR0 = 1u << MHU0_IRQ;
        barrier_dsb();
        next = mailbox.finished + 1u;
        if (mailbox.posted == next) {
            barrier_dmb(); /* work and arg were written before posted */
            mailbox.work(mailbox.arg);
            barrier_dmb(); /* everything the work wrote before finished */
            mailbox.finished = next;
            barrier_dsb();
            MHU0_CPU0INTR_SET = 1u;
            continue;
        }
        __asm__ volatile("wfi" ::: "memory");
    }
}

static void core1_fault(void)
{
    static const char text[] = "fatal: fault on core 1\n";
    vor_port_write(text, sizeof text - 1u);
    vor_port_exit(99);
}

int an521_fork(void *context, void (*work)(void *arg), void *arg)
{
    an521_fork_join_t *state = context;
    state->at_fork = vor_port_counter();
    if (mailbox.finished != mailbox.posted) {
        return 1; /* core 1 busy: vor runs the work itself */
    }
    mailbox.work = work;
    mailbox.arg = arg;
    barrier_dmb(); /* the work, its argument and the arena before posted */
    mailbox.posted = mailbox.posted + 1u;
    barrier_dsb();
    if (mailbox.started == 0u) {
        for (uint32_t i = 0; i < STACK_WORDS; i++) {
            core1_stack[i] = STACK_PAINT;
        }
        barrier_dsb();
        mailbox.started = 1u;
        SYSCTL_INITSVTOR1 = (uint32_t)(uintptr_t)&core1_vectors;
        barrier_dsb();
        SYSCTL_CPUWAIT = SYSCTL_CPUWAIT & ~2u;
    } else {
        MHU0_CPU1INTR_SET = 1u;
    }
    state->forks++;
    if (state->measure != 0u) {
        sleep_until(&mailbox.finished, &mailbox.posted, &MHU0_CPU0INTR_CLR);
        state->at_core1_done = vor_port_counter();
    }
    return 0;
}

void an521_join(void *context)
{
    an521_fork_join_t *state = context;
    state->at_join = vor_port_counter();
    state->joins++;
    sleep_until(&mailbox.finished, &mailbox.posted, &MHU0_CPU0INTR_CLR);
}

uint32_t an521_core1_runs(void)
{
    return mailbox.finished;
}

uint32_t an521_core1_stack_used(void)
{
    uint32_t i = 0;
    while (i < STACK_WORDS && core1_stack[i] == STACK_PAINT) { /* at most STACK_WORDS */
        i++;
    }
    return (STACK_WORDS - i) * 4u;
}
