#!/usr/bin/env python3
"""Tests of the host command-line tool build/host/vor.

Expected answers come from Python's big integers, independently of the C
code. Prints failures and ends with "N passed, N failed"; exit status 1 if
anything failed. Usage: tests/cli/test_cli.py path/to/vor
"""
import random
import subprocess
import sys

VOR = sys.argv[1] if len(sys.argv) > 1 else "build/host/vor"
MIN, MAX = -2**31, 2**31 - 1
passed = failed = 0


def check(ok, what):
    global passed, failed
    if ok:
        passed += 1
    else:
        failed += 1
        print(f"FAIL {what}")


def sign(v):
    return (v > 0) - (v < 0)


def orient(a, b, c):
    return sign((a[0] - c[0]) * (b[1] - c[1]) - (a[1] - c[1]) * (b[0] - c[0]))


def incircle(a, b, c, d):
    rows = [(p[0] - d[0], p[1] - d[1]) for p in (a, b, c)]
    (ax, ay), (bx, by), (cx, cy) = rows
    la, lb, lc = ax * ax + ay * ay, bx * bx + by * by, cx * cx + cy * cy
    return sign(la * (bx * cy - by * cx) + lb * (cx * ay - cy * ax) + lc * (ax * by - ay * bx))


def run(args, text):
    return subprocess.run([VOR] + args, input=text, capture_output=True, text=True)


def predicates_cases(rng):
    lines, expected = [], []
    for n in range(600):
        small = n % 3 == 0
        coord = (lambda: rng.randint(-3, 3)) if small else (lambda: rng.choice([MIN, MAX, rng.randint(MIN, MAX)]))
        if n % 2:
            pts = [(coord(), coord()) for _ in range(3)]
            lines.append("o " + " ".join(f"{x} {y}" for x, y in pts))
            expected.append(orient(*pts))
        else:
            pts = [(coord(), coord()) for _ in range(4)]
            lines.append("c " + " ".join(f"{x} {y}" for x, y in pts))
            expected.append(incircle(*pts))
        if n % 50 == 0:
            lines.append("")
            lines.append("# a comment line")
    return lines, expected


def main():
    rng = random.Random(5)
    lines, expected = predicates_cases(rng)
    r = run(["predicates"], "\n".join(lines) + "\n")
    got = r.stdout.split()
    check(r.returncode == 0, f"predicates exit status {r.returncode}: {r.stderr.strip()}")
    check(len(got) == len(expected), f"predicates printed {len(got)} lines for {len(expected)} cases")
    zeros = 0
    for k, (g, e) in enumerate(zip(got, expected)):
        check(g == str(e), f"predicates case {k}: printed {g}, expected {e}")
        zeros += e == 0
    check(zeros > 20, f"only {zeros} degenerate cases were generated")

    # malformed input: status 2, the right line number, nothing on stdout
    bad = [
        ("o 0 0 1 0 0 1\no 1 2 3\n", 2, "missing coordinate"),
        ("# c\n\nc 0 0 1 0 0 1 1 1 9\n", 3, "too many fields"),
        ("o 0 0 1 0 0 2147483648\n", 1, "out of int32 range"),
        ("o 0 0 1 0 0 -2147483649\n", 1, "out of int32 range"),
        ("o 0 0 1 0 0 1x\n", 1, "not a decimal integer"),
        ("x 1 2\n", 1, "expected 'o' or 'c'"),
    ]
    for text, line, reason in bad:
        r = run(["predicates"], text)
        check(r.returncode == 2, f"bad input {text!r}: exit {r.returncode}, expected 2")
        check(r.stdout == "", f"bad input {text!r}: stdout {r.stdout!r}, expected nothing")
        check(r.stderr.startswith(f"error: line {line}: ") and reason in r.stderr,
              f"bad input {text!r}: stderr {r.stderr!r}")
    r = run(["predicates"], "o -2147483648 -2147483648 0 0 2147483647 2147483647\n")
    check(r.stdout == "0\n", f"full-range collinear: {r.stdout!r}")
    r = run(["no-such-command"], "")
    check(r.returncode == 2 and "usage" in r.stderr, "unknown command: usage and status 2")

    print(f"{passed} passed, {failed} failed")
    return 0 if failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
