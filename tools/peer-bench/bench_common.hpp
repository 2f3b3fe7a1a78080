/* SPDX-License-Identifier: MIT */
// tools/peer-bench/bench_common.hpp - what the host benchmarks share: the
// random generator that makes their inputs, the clock, the command line's
// size lists and errors, and the number formats of their Markdown tables.
#ifndef VOR_BENCH_COMMON_HPP
#define VOR_BENCH_COMMON_HPP

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <time.h>

// The program's name in its error messages; each main sets it first.
static const char *bench_program = "bench";

// An error message and exit status 2, as for a bad command line.
[[noreturn]] static inline void die(const char *what)
{
    std::fprintf(stderr, "%s: %s\n", bench_program, what);
    std::exit(2);
}

// A steady clock in seconds.
static inline double now_s()
{
    using namespace std::chrono;
    return duration<double>(steady_clock::now().time_since_epoch()).count();
}

// The calling thread's CPU time in seconds (user and system, page faults
// included): on a shared machine the time the thread waits for a core is
// not the library's. The libraries timed with it run on the calling thread.
static inline double cpu_s()
{
    timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

// The median of repeated timings; -1 when there are none or the first is
// -1 (a run that did not happen).
static inline double median(std::vector<double> v)
{
    if (v.empty() || v[0] < 0) {
        return -1;
    }
    std::sort(v.begin(), v.end());
    size_t m = v.size() / 2;
    return (v.size() % 2 != 0) ? v[m] : (v[m - 1] + v[m]) / 2;
}

// A bad command line: the program's options and exit status 2.
[[noreturn]] static inline void usage(const char *options)
{
    std::fprintf(stderr, "usage: %s %s\n", bench_program, options);
    std::exit(2);
}

// The result: text on stdout, and into the --out file when one is named.
static inline void publish(const std::string &text, const char *path)
{
    std::fputs(text.c_str(), stdout);
    if (path != nullptr) {
        FILE *f = std::fopen(path, "w");
        if (f == nullptr || std::fputs(text.c_str(), f) < 0 || std::fclose(f) != 0) {
            die("cannot write --out file");
        }
    }
}

// "N,N,..": a comma-separated list of sizes, each in [least, most].
static inline std::vector<uint32_t> parse_sizes(const char *s, unsigned long least,
                                                unsigned long most)
{
    std::vector<uint32_t> sizes;
    while (*s != '\0') {
        char *end;
        unsigned long v = std::strtoul(s, &end, 10);
        if (end == s || v < least || v > most) {
            die("bad --sizes");
        }
        sizes.push_back((uint32_t)v);
        s = (*end == ',') ? end + 1 : end;
    }
    return sizes;
}

// splitmix64: a fixed, portable sequence, so every library and every run
// sees the same inputs.
struct splitmix64 {
    uint64_t s;
    uint64_t next()
    {
        uint64_t z = (s += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
};

// printf-formatted v; "-" for a negative value (a figure not measured).
static inline std::string fmt(const char *format, double v)
{
    if (v < 0) {
        return "-";
    }
    char buf[64];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}

// A Markdown table row of cells, "| a | b |", and a header: its titles'
// row and the separator under it, newlines included.
static inline std::string md_row(const std::vector<std::string> &cells)
{
    std::string row = "|";
    for (const std::string &c : cells) {
        row += " " + c + " |";
    }
    return row;
}

static inline std::string md_head(const std::vector<std::string> &titles)
{
    std::string rule = "|";
    for (size_t i = 0; i < titles.size(); i++) {
        rule += "---|";
    }
    return md_row(titles) + "\n" + rule + "\n";
}

// 1234567 -> "1,234,567"
static inline std::string with_commas(uint64_t n)
{
    std::string s = std::to_string(n), out;
    for (size_t i = 0; i < s.size(); i++) {
        if (i != 0 && (s.size() - i) % 3 == 0) {
            out += ',';
        }
        out += s[i];
    }
    return out;
}

#endif
