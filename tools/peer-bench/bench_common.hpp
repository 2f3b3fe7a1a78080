/* SPDX-License-Identifier: MIT */
// tools/peer-bench/bench_common.hpp - what the host benchmarks share: the
// random generator that makes their inputs, and the number formats of
// their Markdown tables.
#ifndef VOR_BENCH_COMMON_HPP
#define VOR_BENCH_COMMON_HPP

#include <cstdint>
#include <cstdio>
#include <string>

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
