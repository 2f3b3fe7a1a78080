# SPDX-License-Identifier: MIT
"""reference_run.py - what the comparisons of a `vor` command with CGAL
share: the command line (VOR, the CGAL tool, the number of cases), the
tally of checks that ends with "N passed, N failed", the scratch files,
the two runs of each case and the exit status.

A comparison gives run() its default number of cases, its random seed and
one function, case(ctx, number), which writes the case's input files with
ctx.write, runs both tools with ctx.vor and ctx.cgal, and calls
ctx.check(ok, what) for each thing it compares. Case k draws from ctx.rng,
one generator seeded once, so every run sees the same cases.
"""
import os
import random
import subprocess
import sys
import tempfile


class Context:
    def __init__(self, vor, cgal, seed, tmp):
        self._vor, self._cgal, self._tmp = vor, cgal, tmp
        self.rng = random.Random(seed)
        self.passed = self.failed = 0

    def check(self, ok, what):
        if ok:
            self.passed += 1
        else:
            self.failed += 1
            if self.failed <= 10:
                print(f"FAIL {what}")

    def write(self, name, rows):
        """A scratch file of one line per row (a tuple of numbers); its path."""
        path = os.path.join(self._tmp, name)
        with open(path, "w") as f:
            f.writelines(" ".join(str(v) for v in row) + "\n" for row in rows)
        return path

    def vor(self, *args):
        return subprocess.run([self._vor, *args], capture_output=True, text=True)

    def cgal(self, *args):
        return subprocess.run([self._cgal, *args], capture_output=True, text=True)


def run(default_cases, seed, case):
    """Usage: SCRIPT VOR CGAL_TOOL [CASES]; exits 1 if a check failed."""
    if len(sys.argv) not in (3, 4):
        sys.exit(f"usage: {os.path.basename(sys.argv[0])} VOR CGAL_TOOL [CASES]")
    cases = int(sys.argv[3]) if len(sys.argv) > 3 else default_cases
    with tempfile.TemporaryDirectory() as tmp:
        ctx = Context(sys.argv[1], sys.argv[2], seed, tmp)
        for number in range(cases):
            case(ctx, number)
    print(f"{ctx.passed} passed, {ctx.failed} failed")
    sys.exit(1 if ctx.failed else 0)
