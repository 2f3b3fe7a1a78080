#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""check-doc-links.py - every relative link of the Markdown docs leads
somewhere: README.md, CHANGELOG.md and docs/**/*.md, each link to a file
that exists and, with a #anchor, to a heading of that file (GitHub's
anchors: lower case, punctuation dropped, spaces to hyphens, -1, -2 for
repeats). Web links are not followed. Prints a FAIL line per broken link
and "N passed, N failed" (links) for tools/run-tests.sh."""
import glob
import os
import re
import sys


def anchors(path):
    found, seen, fence = set(), {}, False
    with open(path, encoding="utf-8") as f:
        for line in f:
            if line.startswith("```"):
                fence = not fence
            m = None if fence else re.match(r"^#{1,6}\s+(.*?)\s*#*\s*$", line)
            if m:
                slug = re.sub(r"[^\w\- ]", "", m.group(1).lower()).replace(" ", "-")
                n = seen.get(slug, 0)
                seen[slug] = n + 1
                found.add(slug if n == 0 else f"{slug}-{n}")
    return found


def main():
    os.chdir(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
    files = ["README.md", "CHANGELOG.md"] + sorted(glob.glob("docs/**/*.md", recursive=True))
    passed = failed = 0
    for name in files:
        with open(name, encoding="utf-8") as f:
            text = f.read()
        # code is not a link: fenced blocks and `spans`
        text = re.sub(r"```.*?```", "", text, flags=re.S)
        text = re.sub(r"`[^`\n]*`", "", text)
        for m in re.finditer(r"\]\(([^)\s]+)\)", text):
            target = m.group(1)
            if re.match(r"[a-z]+:", target):
                continue
            path, _, anchor = target.partition("#")
            dest = os.path.normpath(os.path.join(os.path.dirname(name), path)) if path else name
            if not os.path.exists(dest):
                problem = "no such file"
            elif anchor and dest.endswith(".md") and anchor not in anchors(dest):
                problem = "no such heading"
            else:
                passed += 1
                continue
            print(f"FAIL {name}: ({target}): {problem}")
            failed += 1
    print(f"{passed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
