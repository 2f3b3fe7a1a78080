/* SPDX-License-Identifier: MIT */
// tools/peer-bench/bench_memory.hpp - how the host benchmarks measure a
// build's memory: each library builds once more in a fresh child process
// of the same program (`PROGRAM --mem ARGS`), which resets its peak-RSS
// mark, builds, and prints its peak RSS growth and its peak of live heap
// bytes. Include it in one program's one translation unit only: it replaces
// the global operator new and delete to count the heap.
#ifndef VOR_BENCH_MEMORY_HPP
#define VOR_BENCH_MEMORY_HPP

#include "bench_common.hpp"

#include <malloc.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>
#include <string>

// gcc warns that the replaced operator delete frees what operator new
// returned: both are ours and use malloc/free, so that is right.
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"

// Counting is switched on only in --mem children, so timed runs pay
// nothing but one predictable branch per allocation.
static bool heap_counting;
static long long heap_live, heap_peak; // signed: frees of older blocks may come first

static inline void heap_add(void *p)
{
    if (heap_counting && p != nullptr) {
        heap_live += (long long)malloc_usable_size(p);
        heap_peak = std::max(heap_peak, heap_live);
    }
}

static inline void heap_sub(void *p)
{
    if (heap_counting && p != nullptr) {
        heap_live -= (long long)malloc_usable_size(p);
    }
}

void *operator new(size_t n)
{
    void *p = std::malloc(n != 0 ? n : 1);
    if (p == nullptr) {
        throw std::bad_alloc();
    }
    heap_add(p);
    return p;
}
void *operator new[](size_t n) { return operator new(n); }
void operator delete(void *p) noexcept
{
    heap_sub(p);
    std::free(p);
}
void operator delete[](void *p) noexcept { operator delete(p); }
void operator delete(void *p, size_t) noexcept { operator delete(p); }
void operator delete[](void *p, size_t) noexcept { operator delete(p); }

// vor's arenas come from here, so the heap figure counts them too.
static inline void *counted_malloc(size_t n)
{
    void *p = std::malloc(n);
    heap_add(p);
    return p;
}

static inline void counted_free(void *p)
{
    heap_sub(p);
    std::free(p);
}

// A field of /proc/self/status in kB; -1 if absent.
static inline long status_kb(const char *field)
{
    FILE *f = std::fopen("/proc/self/status", "r");
    if (f == nullptr) {
        return -1;
    }
    char line[256];
    long kb = -1;
    size_t len = std::strlen(field);
    while (std::fgets(line, sizeof line, f) != nullptr) {
        if (std::strncmp(line, field, len) == 0 && line[len] == ':') {
            kb = std::strtol(line + len + 1, nullptr, 10);
            break;
        }
    }
    std::fclose(f);
    return kb;
}

// The child's side. mem_child_start resets VmHWM to the current RSS (Linux
// >= 4.0, by writing 5 to /proc/self/clear_refs; where that fails, the
// figure is VmHWM's growth from its old peak, and "exact 0" says so) and
// starts counting the heap; mem_child_finish prints the figures the parent
// reads and ends the process without destructors (nothing left to measure,
// and the build's memory stays in use until the end).
struct mem_child {
    long before = -1;
    bool exact = false;
};

static inline mem_child mem_child_start()
{
    mem_child c;
    FILE *f = std::fopen("/proc/self/clear_refs", "w");
    if (f != nullptr) {
        c.exact = std::fputs("5", f) >= 0;
        c.exact &= std::fclose(f) == 0;
    }
    c.before = c.exact ? status_kb("VmRSS") : status_kb("VmHWM");
    heap_live = heap_peak = 0; // what the build allocates from here on
    heap_counting = true;
    return c;
}

[[noreturn]] static inline void mem_child_finish(const mem_child &c)
{
    long after = status_kb("VmHWM");
    if (c.before < 0 || after < 0) {
        die("no /proc/self/status");
    }
    std::printf("rss %ld\nheap %lld\nexact %d\n", (after - c.before) * 1024, heap_peak,
                c.exact ? 1 : 0);
    std::fflush(stdout);
    std::_Exit(0);
}

// The parent's side: runs `SELF --mem ARGS` and reads its figures (bytes;
// -1 where the child failed).
struct mem_result {
    double rss = -1, heap = -1;
};

static inline mem_result measure_memory(const std::string &self, const std::string &args)
{
    mem_result m;
    std::string cmd = "'" + self + "' --mem " + args;
    FILE *f = popen(cmd.c_str(), "r");
    if (f == nullptr) {
        return m;
    }
    char line[128];
    while (std::fgets(line, sizeof line, f) != nullptr) {
        double v;
        if (std::sscanf(line, "rss %lf", &v) == 1) {
            m.rss = v;
        } else if (std::sscanf(line, "heap %lf", &v) == 1) {
            m.heap = v;
        }
    }
    if (pclose(f) != 0) {
        m.rss = m.heap = -1;
    }
    return m;
}

// Bytes per site with one decimal; "-" for a figure not measured.
static inline std::string per_site(double bytes, uint32_t n)
{
    return bytes < 0 ? "-" : fmt("%.1f", bytes / n);
}

#endif
