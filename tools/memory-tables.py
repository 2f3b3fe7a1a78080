#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""memory-tables.py - the three memory tables of docs/benchmarks.md, measured.

    tools/memory-tables.py            print the tables (Markdown)
    tools/memory-tables.py --check F  exit 1 unless file F holds each verbatim

1. Stack per public call and target: the deepest chain of -fstack-usage
   frames below each public vor_ function (tools/size-report.sh -v builds
   the objects, tools/stack-depth.py reads them), for a firmware that
   never attaches constraint memory (--without the constraints' files:
   the upkeep's pointer is never set).
2. The calls whose stack grows when constraint memory is attached (the
   upkeep's and the constrained mesh's functions counted), and the
   constraints' own calls.
3. Sites per RAM budget and target: the most sites n whose arena
   VOR_ARENA_BYTES(n) (tools/ram_budget.c, per VOR_INDEX_BITS), the vor_t
   (sizeof from the target compiler) and the worst stack of table 1 fit in
   8, 16, 32, 64 and 256 KB.
"""

import os
import re
import subprocess
import sys
import tempfile

TARGETS = ["cortex-m0", "cortex-m3", "cortex-m4f", "riscv32"]
BUDGETS_KB = [8, 16, 32, 64, 256]
ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))


def run(args, **kwargs):
    return subprocess.run(args, cwd=ROOT, check=True, capture_output=True, text=True, **kwargs).stdout


CONSTRAINTS = "cdt.c,crossing.c"


def stack_depths():
    """({target: {public function: bytes}} without constraints, the same
    with them) from the objects tools/size-report.sh builds."""
    run(["tools/size-report.sh", "-v"] + TARGETS)
    tables = []
    for options in (["--without", CONSTRAINTS], []):
        depths = {}
        for target in TARGETS:
            chains = subprocess.run(["python3", "tools/stack-depth.py"] + options +
                                    [f"build/size/{target}"], cwd=ROOT, capture_output=True,
                                    text=True).stdout
            depths[target] = {line.split()[0]: int(line.split()[1]) for line in chains.splitlines()
                              if re.match(r"vor_\w+\s+\d+\s", line)}
        missing = [t for t in TARGETS if not depths[t]]
        if missing:
            sys.exit(f"memory-tables: no stack depths for {' '.join(missing)}")
        tables.append(depths)
    return tables


def vor_t_bytes(target, tmp):
    """sizeof(vor_t) as the target compiler lays it out: the size nm gives
    a vor_t object compiled with the library's own flags."""
    # the Makefile's final $(CC), $(LIB_CFLAGS) and $(NM), as tools/size-report.sh reads them
    rules = "vor-probe-cc:\n\t@echo $(CC) $(LIB_CFLAGS)\nvor-probe-nm:\n\t@echo $(NM)"
    cc = run(["make", "-s", f"PORT={target}", "--eval", rules, "vor-probe-cc"]).split()
    nm = run(["make", "-s", f"PORT={target}", "--eval", rules, "vor-probe-nm"]).strip()
    source, obj = os.path.join(tmp, "probe.c"), os.path.join(tmp, f"probe-{target}.o")
    with open(source, "w") as f:
        f.write('#include "vor.h"\nvor_t vor_size_probe;\n')
    run(cc + ["-fno-common", "-c", source, "-o", obj])
    for line in run([nm, "-S", obj]).splitlines():
        fields = line.split()
        if fields[-1] == "vor_size_probe":
            return int(fields[1], 16)
    sys.exit(f"memory-tables: no vor_size_probe in {obj}")


def most_sites(tmp, index_bits, overhead):
    """{budget KB: sites} for one index width."""
    exe = os.path.join(tmp, f"ram_budget{index_bits}")
    run(["gcc", "-std=c99", "-O2", "-Iinclude", f"-DVOR_INDEX_BITS={index_bits}",
         "tools/ram_budget.c", "-o", exe])
    lines = run([exe, str(overhead)] + [str(kb * 1024) for kb in BUDGETS_KB]).splitlines()
    return {int(b) // 1024: int(n) for b, n in (line.split() for line in lines)}


def stack_rows(depths, calls):
    return [f"| `{call}` | " + " | ".join(f"{depths[t].get(call, '-'):,}" for t in TARGETS) + " |"
            for call in sorted(calls, key=lambda c: (-depths[TARGETS[0]][c], c))]


def tables():
    """The three tables, each a Markdown string."""
    depths, attached = stack_depths()
    header = ["| {} | " + " | ".join(TARGETS) + " |", "|---|" + "---:|" * len(TARGETS)]
    stack = [header[0].format("public call"), header[1]] + stack_rows(depths, depths[TARGETS[0]])
    grown = [c for c in attached[TARGETS[0]]
             if any(attached[t][c] != depths[t].get(c) for t in TARGETS)]
    with_constraints = [header[0].format("with constraint memory"), header[1]] + \
        stack_rows(attached, grown)
    with tempfile.TemporaryDirectory() as tmp:
        fixed = {t: (vor_t_bytes(t, tmp), max(depths[t].values())) for t in TARGETS}
        sites = {(t, bits): most_sites(tmp, bits, sum(fixed[t]))
                 for t in TARGETS for bits in (16, 32)}
    ram = [header[0].format("RAM"), header[1],
           "| vor_t + worst stack (B) | " +
           " | ".join(f"{fixed[t][0]} + {fixed[t][1]:,}" for t in TARGETS) + " |"]
    for kb in BUDGETS_KB:
        ram.append(f"| {kb} KB | " +
                   " | ".join(f"{sites[t, 16][kb]:,} / {sites[t, 32][kb]:,}" for t in TARGETS) + " |")
    return ["\n".join(stack) + "\n", "\n".join(with_constraints) + "\n", "\n".join(ram) + "\n"]


def main():
    measured = tables()
    if len(sys.argv) == 3 and sys.argv[1] == "--check":
        with open(sys.argv[2]) as f:
            doc = f.read()
        stale = [table for table in measured if table not in doc]
        for table in stale:
            print(f"FAIL {sys.argv[2]} does not hold this measured table:\n{table}")
        print(f"{len(measured) - len(stale)} passed, {len(stale)} failed")
        return 1 if stale else 0
    if len(sys.argv) != 1:
        sys.exit("usage: tools/memory-tables.py [--check FILE]")
    sys.stdout.write("\n".join(measured))
    return 0


if __name__ == "__main__":
    sys.exit(main())
