#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""check-layers.py - the #include lines of src/ are its real dependencies.

docs/design.md ("Who depends on whom in src/") states the rule this
checks, file by file:

- every private header a file includes (#include "x.h" of src/) belongs
  to a lower layer than the file, or is the file's own header (mesh.c
  with mesh.h); so includes point one way and cannot form a circle;
- every vor__ function a src/*.c calls and does not define, or a
  src/*.h calls in its inline functions and macros and does not declare,
  is declared in a private header it includes directly (a declaration or an inline
  definition at file scope, or a function-like macro), not one that
  comes in through another header;
- no src/*.c declares a function itself: no `extern`, no prototype of a
  vor__ function it does not define (both bypass the headers).

A file missing from LAYERS fails, so a new part is placed deliberately.
The comments and string literals are stripped first; the parse is
lexical (braces and parentheses), which is enough for this code's style.

    tools/check-layers.py [SRC]     check SRC (default: src/)
    tools/check-layers.py --self-test
                                    also break copies of src/ in a temp
                                    dir, one way at a time, and check that
                                    each break is caught

Closing line "N passed, N failed" (one check per file, one per break)
for tools/run-tests.sh.
"""
import os
import re
import shutil
import sys
import tempfile

# The layers of docs/design.md, lowest first. A file may include the
# private headers of the layers below its own, and its own header.
LAYERS = [
    # the leaves: multi-word integers; the motion cache's epoch and box test
    ("arithmetic", ["multiword.h", "motion.h"]),
    # the topology, the exact predicates, and the raster core beside them,
    # which uses only the arithmetic (nothing of the mesh)
    ("mesh, predicates, raster", [
        "mesh.h", "mesh.c", "predicates.h", "predicates.c", "crossing.h", "crossing.c",
        "raster.h", "raster.c", "raster_euclid.c", "raster_metrics.c", "field.c"]),
    ("perturbation", ["perturbation.h"]),
    ("services", [
        "insertion_order.h", "insertion_order.c", "incremental.h", "dynamic.h",
        "bucket_grid.h", "bucket_grid.c", "walk.h", "cdt.h"]),
    ("parts", [
        "incremental.c", "divide_conquer.c", "dynamic.c", "motion.c",
        "queries.c", "geometry.c", "interpolate.c", "cdt.c", "power.c"]),
]
# A file's own header, where it is not the file's name with .h.
OWN_HEADER = {"raster_euclid.c": "raster.h", "raster_metrics.c": "raster.h",
              "field.c": "raster.h"}

LAYER_OF = {name: level for level, (_, names) in enumerate(LAYERS) for name in names}

CALL = re.compile(r"\bvor__\w+(?=\s*\()")
INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"', re.M)
DEFINE_MACRO = re.compile(r"^\s*#\s*define\s+(vor__\w+)\(", re.M)


def strip(text):
    """The text without comments, string and character literals (each
    replaced by a space or an empty literal, line breaks kept), and with
    continued lines joined (the line breaks moved after them)."""
    out = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("/*", i):
            end = text.find("*/", i + 2)
            end = n if end < 0 else end + 2
            out.append(" " + "\n" * text.count("\n", i, end))
            i = end
        elif text.startswith("//", i):
            end = text.find("\n", i)
            i = n if end < 0 else end
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            out.append(c + c)
            i = j + 1
        else:
            out.append(c)
            i += 1
    return re.sub(r"\\\n", " ", "".join(out))


def split_directives(text):
    """(code, directives): the stripped text with preprocessor lines
    blanked, and those lines."""
    code, directives = [], []
    for line in text.split("\n"):
        if line.lstrip().startswith("#"):
            directives.append(line)
            code.append("")
        else:
            code.append(line)
    return "\n".join(code), "\n".join(directives)


def file_scope(code):
    """For each vor__ name followed by "(" at file scope (brace depth 0):
    (name, what follows its parameter list: "{", ";" or other)."""
    found = []
    depth = 0
    i = 0
    for m in re.finditer(r"[{}]|\bvor__\w+\s*\(", code):
        token = m.group(0)
        if m.start() < i:
            continue
        if token == "{":
            depth += 1
        elif token == "}":
            depth -= 1
        elif depth == 0:
            j, parens = m.end(), 1
            while j < len(code) and parens:
                parens += {"(": 1, ")": -1}.get(code[j], 0)
                j += 1
            rest = code[j:].lstrip()
            found.append((token.rstrip("( \t\n"), rest[:1]))
            i = j
    return found


class Source:
    def __init__(self, root, name):
        with open(os.path.join(root, name), encoding="utf-8") as f:
            raw = f.read()
        self.name = name
        self.includes = INCLUDE.findall(raw)
        text = strip(raw)
        code, directives = split_directives(text)
        self.code = code
        self.calls = set(CALL.findall(code)) | set(
            CALL.findall("\n".join(l for l in directives.split("\n")
                                   if not re.match(r"\s*#\s*include", l))))
        scope = file_scope(code)
        self.defined = {name for name, after in scope if after == "{"}
        self.prototypes = {name for name, after in scope if after == ";"}
        self.declared = self.defined | self.prototypes | set(DEFINE_MACRO.findall(directives))
        self.has_extern = re.search(r"\bextern\b", code) is not None


def check_tree(root, quiet=False):
    """Checks root (a src/ folder); returns (passed, failed, messages)."""
    names = sorted(n for n in os.listdir(root) if n.endswith((".c", ".h")))
    sources = {n: Source(root, n) for n in names}
    headers = {n for n in names if n.endswith(".h")}
    passed = failed = 0
    messages = []
    for name in names:
        src = sources[name]
        problems = []
        level = LAYER_OF.get(name)
        if level is None:
            problems.append("not in check-layers.py's LAYERS: place it in a layer")
        private = [h for h in src.includes if h in headers]
        for h in src.includes:
            if h not in headers and not os.path.exists(os.path.join(root, "..", "include", h)):
                problems.append(f'includes "{h}", which is neither in src/ nor in include/')
        own = OWN_HEADER.get(name, name[:-2] + ".h") if name.endswith(".c") else None
        for h in private:
            if h == own or level is None or h not in LAYER_OF:
                continue
            if LAYER_OF[h] >= level:
                where = "the same layer" if LAYER_OF[h] == level else "a higher layer"
                problems.append(
                    f"includes {h} of {where} ({LAYERS[LAYER_OF[h]][0]}; {name} is in "
                    f"{LAYERS[level][0]})")
        if name.endswith(".c"):
            if src.has_extern:
                problems.append("declares something extern: declare it in the private "
                                "header of the part that defines it")
            for fn in sorted(src.prototypes - src.defined):
                problems.append(f"declares {fn} itself: include the header that declares it")
            own_names = src.defined
        else:
            own_names = src.declared  # a header's inline functions call its own
        visible = set()
        for h in private:
            visible |= sources[h].declared
        for fn in sorted(src.calls - own_names - visible):
            holders = sorted(h for h in headers if fn in sources[h].declared)
            hint = (f" (declared in {', '.join(holders)})" if holders
                    else " (declared in no private header)")
            problems.append(f"calls {fn}, declared in no header it includes{hint}")
        if problems:
            failed += 1
            messages += [f"FAIL {name}: {p}" for p in problems]
        else:
            passed += 1
    return passed, failed, messages


# Each break: (what it shows, file, text replaced (None: append to the
# file, which may be new), the text put there, a phrase the failure must
# contain).
BREAKS = [
    ("an upward include", "mesh.h", None, '#include "perturbation.h"\n', "a higher layer"),
    ("a circle of two headers", "predicates.h", None, '#include "mesh.h"\n',
     "the same layer"),
    ("a call through a header that another one includes", "queries.c",
     '#include "perturbation.h"\n', "", "declared in no header it includes (declared in "
     "perturbation.h)"),
    ("an extern declaration", "geometry.c", None, "extern int vor__x_secret(void);\n",
     "declares something extern"),
    ("a prototype of another part's function", "motion.c", None,
     "int vor__x_elsewhere(int);\nint vor__x_use(void) { return vor__x_elsewhere(1); }\n",
     "declares vor__x_elsewhere itself"),
    ("a file in no layer", "newpart.c", None, "", "not in check-layers.py's LAYERS"),
]


def self_test(src):
    """Breaks copies of src one way at a time; each must be caught."""
    passed = failed = 0
    with tempfile.TemporaryDirectory() as tmp:
        for what, name, old, new, phrase in BREAKS:
            tree = os.path.join(tmp, "src")
            shutil.rmtree(tree, ignore_errors=True)
            shutil.copytree(src, tree)
            include = os.path.join(src, "..", "include")
            if not os.path.exists(os.path.join(tmp, "include")):
                shutil.copytree(include, os.path.join(tmp, "include"))
            path = os.path.join(tree, name)
            if old is None:
                with open(path, "a", encoding="utf-8") as f:
                    f.write(new)
            else:
                with open(path, encoding="utf-8") as f:
                    text = f.read()
                assert old in text, f"self-test: {name} no longer holds {old!r}"
                with open(path, "w", encoding="utf-8") as f:
                    f.write(text.replace(old, new))
            _, bad, messages = check_tree(tree)
            if bad and any(phrase in m for m in messages):
                passed += 1
            else:
                failed += 1
                print(f"FAIL self-test: {what} ({name}) was not caught")
    return passed, failed


def main(argv):
    args = [a for a in argv if a != "--self-test"]
    root = args[0] if args else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "src")
    passed, failed, messages = check_tree(root)
    for m in messages:
        print(m)
    if "--self-test" in argv:
        p, f = self_test(root)
        print(f"self-test: {p} of {p + f} broken trees caught")
        passed, failed = passed + p, failed + f
    print(f"{passed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
