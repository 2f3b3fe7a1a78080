#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# tools/misra.sh - `make misra` and make test's suite misra: cppcheck's
# MISRA C:2012 addon over the library (every file of sources.txt and the
# headers of src/ and include/ they include), in the configurations the
# library ships in. Every finding must be covered by a deviation of
# tools/misra-deviations.txt (cppcheck's suppressions format, each one
# justified in docs/misra.md); the closing line is "N passed, N failed".
#
#   tools/misra.sh            the check
#   tools/misra.sh --counts   also print how many findings each deviation
#                             covers (the counts of docs/misra.md)
#
# Configurations (-D: cppcheck then checks exactly that one, as a compiler
# sees it; the macros are those the library's #if lines test):
#   cortex-m0  16-bit ids, 32-bit limbs, GCC for ARMv6-M at -Os
#   cortex-m4  16-bit ids, 32-bit limbs, GCC for ARMv7E-M at -O2, counters
#   host       32-bit ids, 64-bit limbs, GCC for x86-64, counters
#
# Checks, each counted once:
#   - each configuration: cppcheck and its addon run to the end, and every
#     finding (the addon's and cppcheck's own) is deviated;
#   - every header of include/ and src/ is in some file analysed (read
#     from cppcheck's dump files), so none escapes the check;
#   - every deviation of the file covers at least one finding (no stale
#     entry hides a future finding);
#   - self-test: a file with a precedence violation in its header and a
#     modified parameter, checked with no deviation, must give exactly
#     those two findings (so the suite cannot pass with the addon broken).
# Nothing is cached: cppcheck's build directory is emptied on every run.
set -u
cd "$(dirname "$0")/.." || exit 1

counts=0
[ "${1-}" = "--counts" ] && counts=1
out=build/misra
deviations=tools/misra-deviations.txt
rm -rf "$out"
mkdir -p "$out"
passed=0
failed=0
pass() { passed=$((passed + 1)); }
fail() {
    echo "FAIL $*"
    failed=$((failed + 1))
}

jobs=$(nproc 2>/dev/null || echo 2)
[ "$jobs" -gt 2 ] || jobs=2
template='MISRA-FINDING {file}:{line}:{column}:{id}:{message}'

# run NAME FILE... -- DEFINES...: cppcheck with the addon over FILE...;
# its findings into $out/NAME.findings (file:line:column:id), anything
# else it printed into $out/NAME.log. Status 1 if cppcheck failed or
# printed something that is not a finding.
run() {
    local name=$1 dir=$out/$1 files=() status
    shift
    while [ "$1" != "--" ]; do
        files+=("$1")
        shift
    done
    shift
    mkdir -p "$dir"
    nice -n 10 cppcheck -q -j "$jobs" --cppcheck-build-dir="$dir" --addon=misra --std=c99 \
        --language=c -Iinclude -Isrc "$@" --template="$template" "${files[@]}" \
        >"$out/$name.log" 2>"$out/$name.stderr"
    status=$?
    grep '^MISRA-FINDING ' "$out/$name.stderr" | cut -d' ' -f2 | cut -d: -f1-4 | sort -u >"$out/$name.findings"
    grep -v '^MISRA-FINDING ' "$out/$name.stderr" >>"$out/$name.log"
    if [ "$status" != 0 ] || [ -s "$out/$name.log" ]; then
        sed 's/^/    /' "$out/$name.log" | head -n 20
        return 1
    fi
}

mapfile -t sources < <(grep '^src/.*\.c$' sources.txt)
configs="cortex-m0 cortex-m4 host"
for config in $configs; do
    case $config in
        cortex-m0) defines=(-D__GNUC__=12 -D__ARM_ARCH_PROFILE=77 -D__ARM_ARCH_6M__ -D__OPTIMIZE_SIZE__) ;;
        cortex-m4) defines=(-D__GNUC__=12 -D__ARM_ARCH_PROFILE=77 -D__ARM_FEATURE_CLZ -D__ARM_FEATURE_IDIV
            -DVOR_STATS=1) ;;
        host) defines=(-D__GNUC__=12 -D__x86_64__ -D__SIZEOF_INT128__=16 -DVOR_INDEX_BITS=32 -DVOR_STATS=1) ;;
    esac
    if run "$config" "${sources[@]}" -- "${defines[@]}"; then
        pass
    else
        fail "cppcheck did not run cleanly in configuration $config ($out/$config.log)"
    fi
done

# The headers analysed: each dump file lists the files its unit read.
cat "$out"/cortex-m0/*.dump "$out"/cortex-m4/*.dump "$out"/host/*.dump 2>/dev/null |
    grep -o '<file index="[0-9]*" name="[^"]*"' | sed 's/.*name="//; s/"$//' | sort -u >"$out/analysed.txt"
missing=0
for header in include/*.h src/*.h; do
    grep -qx "$header" "$out/analysed.txt" || {
        echo "FAIL $header: in no file cppcheck analysed"
        missing=1
    }
done
if [ "$missing" = 0 ]; then pass; else failed=$((failed + 1)); fi

# The findings of every configuration against the deviations.
python3 - "$deviations" "$counts" "$out"/cortex-m0.findings "$out"/cortex-m4.findings "$out"/host.findings \
    >"$out/report.txt" <<'EOF'
import fnmatch, sys
deviations, counts = sys.argv[1], sys.argv[2] == '1'
findings = set()
for name in sys.argv[3:]:
    for line in open(name):
        f, l, c, rule = line.strip().split(':')
        findings.add((f, int(l), int(c), rule))
rules = []  # (entry, rule, file pattern or None, line or None)
for text in open(deviations):
    text = text.split('#', 1)[0].strip()
    if not text:
        continue
    parts = text.split(':')
    rules.append((text, parts[0], parts[1] if len(parts) > 1 else None,
                  int(parts[2]) if len(parts) > 2 else None))
used = {entry: 0 for entry, _, _, _ in rules}
bad = 0
for f, l, c, rule in sorted(findings):
    for entry, r, pattern, line in rules:
        if r == rule and (pattern is None or fnmatch.fnmatch(f, pattern)) and line in (None, l):
            used[entry] += 1
            break
    else:
        print('FAIL %s:%d:%d: %s, not deviated' % (f, l, c, rule))
        bad += 1
for entry, n in used.items():
    if n == 0:
        print('FAIL deviation %s covers no finding (stale: remove it)' % entry)
        bad += 1
    elif counts:
        print('%6d %s' % (n, entry))
print('findings: %d, all deviated' % len(findings) if bad == 0 else 'findings: %d' % len(findings))
sys.exit(1 if bad else 0)
EOF
status=$?
cat "$out/report.txt"
if [ "$status" = 0 ]; then pass; else failed=$((failed + 1)); fi

# Self-test: the addon must find a known violation in a header and in a
# source file, with no deviation applied.
bad=$out/selftest
mkdir -p "$bad"
printf 'static inline int bad_mix(int a, int b, int c)\n{\n    return a + b * c;\n}\n' \
    >"$bad/bad.h"
printf '#include "bad.h"\nint bad(int k);\nint bad(int k)\n{\n    k = k + 1;\n    return bad_mix(k, 2, 3);\n}\n' >"$bad/bad.c"
if run selftest-run "$bad/bad.c" -- -I"$bad" &&
    [ "$(cut -d: -f1,2,4 "$out/selftest-run.findings" | tr '\n' ' ')" = \
        "$bad/bad.c:5:misra-c2012-17.8 $bad/bad.h:3:misra-c2012-12.1 " ]; then
    pass
else
    fail "self-test: cppcheck's MISRA addon did not report exactly the violations of $bad/ (got: $(tr '\n' ' ' <"$out/selftest-run.findings"))"
fi

echo "$passed passed, $failed failed"
[ "$failed" = 0 ]
