#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""stack-depth.py - worst-case stack depth of vor's public functions.

    tools/stack-depth.py [--worst] [--without FILE.c,...] FILE.ci|DIR...

Reads the call graphs GCC writes with -fcallgraph-info=su (one VCG file,
NAME.ci, per object; a DIR stands for every *.ci in it), merges them, and
for every public function (a global whose name starts with vor_ but not
vor__) computes the deepest call chain: the sum of the -fstack-usage frames
along the chain whose sum is largest. The caller's own frame and interrupt
stacking are not included.

Default output: one line per public function, deepest first, with its chain.
--worst prints only the deepest public function: "BYTES NAME" (BYTES is
">=N" when the depth is not fully known).
--without leaves out the functions of the named source files (base names)
as a firmware that never calls into them has them: their public functions
are not listed, and an indirect call through one of the library's tables
(below) whose every function is left out is no call (the pointer is never
set: the constraints' upkeep without vor_cdt_attach).

The library promises a static stack, so these are flagged, on stderr, and
make the depth of every function that reaches them unknown (reported as a
lower bound, ">=N"):
  - a frame GCC marks "dynamic" or "dynamic,bounded" (alloca, VLA);
  - a call to a function outside the graph (memset/memcpy emitted by GCC,
    a libgcc helper such as __aeabi_ldivmod, anything else undefined);
  - an indirect call (function pointer), except through one of the
    library's own tables of functions (TABLE_CALLS below: counted as a
    call to every function of the table, the deepest deciding), and where
    a public function calls back into its caller's code (CALLER_CALLBACKS
    below): that stack is the caller's, like the caller's own frame, and
    is left out with a note.
A cycle in the call graph (recursion) has no bound at all: it is reported
and nothing else is printed.

Exit status: 0 every public depth is known; 1 some depth is unknown
(warnings above); 2 recursion, unreadable or malformed input, or no public
function found.
"""

import os
import re
import sys

PUBLIC = re.compile(r"vor_(?!_)\w*\Z")
# One attribute inside a node or an edge: name: "string" or name: word.
ATTR = re.compile(r'(\w+)\s*:\s*("(?:[^"\\]|\\.)*"|[^\s}]+)')
ITEM = re.compile(r"^\s*(node|edge)\s*:\s*\{(.*)\}\s*$")
FRAME = re.compile(r"^(\d+) bytes \(([^)]*)\)$")
INDIRECT = "__indirect_call"
# Functions whose only indirect calls are to a callback the caller passes
# in (its stack is the caller's): name -> what is called. Public ones, or
# the static helper of one public function that makes the call (matched
# without GCC's clone suffixes such as ".constprop.0"): build_forked calls
# vor_build_dc_forked's fork and join hooks.
# The library's own function pointers: every indirect call made in a
# source file (its base name) goes to one of the functions these names
# match (without clone suffixes), and to nothing else of the library.
# A key "file.c:function" is more specific than the file's.
TABLE_CALLS = {"raster.c": (r"write_(label8|label16|label32|rgb565|rgb888)",
                            "a row writer of write_row's table"),
               "raster_metrics.c": (r"(key|compare|bounds)_[A-Z0-9]+",
                                    "a metric's key, comparison or bounds (metric_ops)"),
               "dynamic.c": (r"motion_update|mesh_predicate|removal_predicate",
                             "the motion cache's upkeep or the constrained or power mesh's predicates"),
               "dynamic.c:vor_remove": (r"vor__cdt_update|mesh_predicate",
                                        "the constraints' upkeep or the constrained mesh's predicates"),
               "dynamic.c:move_constrained": (r"vor__cdt_update|motion_update|mesh_predicate",
                                              "the constraints' or the motion cache's upkeep"),
               "incremental.c": (r"vor__cdt_update", "the constraints' upkeep (vor_cdt_attach)"),
               "mesh.c": (r"vor__cdt_update", "the constraints' upkeep (vor_cdt_attach)"),
               "divide_conquer.c": (r"vor__cdt_update", "the constraints' upkeep (vor_cdt_attach)"),
               "geometry.c": (r"pair_line", "an order-K cell's pair lines (vor_order_cell_begin)")}
CALLER_CALLBACKS = {"vor_raster": "the caller's flush callback",
                    "vor_raster_euclid": "the caller's flush callback",
                    "vor_field_raster": "the caller's flush callback",
                    "build_forked": "the caller's fork and join hooks"}


class Input(Exception):
    pass


def unquote(value):
    if value.startswith('"'):
        return re.sub(r"\\(.)", lambda m: "\n" if m.group(1) == "n" else m.group(1),
                      value[1:-1])
    return value


def read_graph(paths):
    """Returns (frames, kinds, where, edges, externals).

    frames[title] = bytes, kinds[title] = "static" / "dynamic" / ...,
    where[title] = "file:line:col", edges[title] = set of callee titles,
    for every function defined in one of the files; externals[title] =
    label of every callee seen only as a declaration.
    """
    frames, kinds, where, edges, externals = {}, {}, {}, {}, {}
    for path in paths:
        try:
            with open(path, encoding="utf-8") as f:
                lines = f.read().splitlines()
        except OSError as e:
            raise Input(f"{path}: {e.strerror}")
        for number, line in enumerate(lines, 1):
            m = ITEM.match(line)
            if not m:
                continue
            attrs = {k: unquote(v) for k, v in ATTR.findall(m.group(2))}
            if m.group(1) == "edge":
                if "sourcename" not in attrs or "targetname" not in attrs:
                    raise Input(f"{path}:{number}: edge without source or target")
                edges.setdefault(attrs["sourcename"], set()).add(attrs["targetname"])
                continue
            title = attrs.get("title")
            label = attrs.get("label", "").split("\n")
            if not title:
                raise Input(f"{path}:{number}: node without a title")
            frame = FRAME.match(label[-1])
            if frame:
                if title in frames:
                    print(f"stack-depth: warning: {title} defined twice "
                          f"({where[title]}, {label[1]})", file=sys.stderr)
                frames[title] = int(frame.group(1))
                kinds[title] = frame.group(2)
                where[title] = label[1] if len(label) > 2 else path
            elif attrs.get("shape") == "ellipse":
                externals.setdefault(title, label[0] if label else title)
            else:
                raise Input(f"{path}:{number}: {title} has no stack usage "
                            "(compile with -fcallgraph-info=su, not =da or nothing)")
    for title in frames:
        externals.pop(title, None)
    for callees in edges.values():
        for callee in callees:
            if callee not in frames and callee not in externals:
                externals[callee] = callee
    return frames, kinds, where, edges, externals


def find_cycle(frames, edges):
    """A list of titles forming a cycle reachable in the graph, or None."""
    WHITE, GREY, BLACK = 0, 1, 2
    colour = dict.fromkeys(frames, WHITE)
    for root in sorted(frames):
        if colour[root] != WHITE:
            continue
        colour[root] = GREY
        stack = [(root, iter(sorted(edges.get(root, ()))))]
        while stack:
            node, callees = stack[-1]
            for callee in callees:
                if callee not in frames:
                    continue
                if colour[callee] == GREY:
                    chain = [n for n, _ in stack]
                    return chain[chain.index(callee):] + [callee]
                if colour[callee] == WHITE:
                    colour[callee] = GREY
                    stack.append((callee, iter(sorted(edges.get(callee, ())))))
                    break
            else:
                colour[node] = BLACK
                stack.pop()
    return None


def depths(frames, kinds, edges):
    """depth[title] = (bytes, known, chain): the deepest chain from title.

    An unknown part (dynamic frame, external or indirect callee) counts as
    0 bytes and makes the result unknown (a lower bound). Needs an acyclic
    graph.
    """
    memo = {}

    def visit(title):
        if title in memo:
            return memo[title]
        if title not in frames:
            memo[title] = (0, False, [title])
            return memo[title]
        best = (0, True, [])
        known = True
        for callee in sorted(edges.get(title, ())):
            sub = visit(callee)
            known = known and sub[1]
            if sub[0] > best[0] or not best[2]:
                best = sub
        known = known and kinds[title] == "static"
        memo[title] = (frames[title] + best[0], known, [title] + best[2])
        return memo[title]

    # Iterative depth-first order keeps deep graphs off Python's own stack.
    order, seen = [], set()
    for root in sorted(frames):
        todo = [(root, False)]
        while todo:
            node, done = todo.pop()
            if done:
                order.append(node)
                continue
            if node in seen:
                continue
            seen.add(node)
            todo.append((node, True))
            for callee in sorted(edges.get(node, ()), reverse=True):
                if callee not in seen:
                    todo.append((callee, False))
    for node in order:
        visit(node)
    return memo


def short(title):
    """src/x.c:helper -> helper (static functions are titled file:name)."""
    return title.rsplit(":", 1)[-1]


def reaches(title, edges, frames, bad):
    """The members of bad that title reaches (itself included)."""
    found, todo, seen = set(), [title], set()
    while todo:
        node = todo.pop()
        if node in seen:
            continue
        seen.add(node)
        if node in bad:
            found.add(node)
        if node in frames:
            todo.extend(edges.get(node, ()))
    return found


def main(argv):
    worst_only = False
    without = set()
    args = []
    argv = list(argv)
    while argv:
        arg = argv.pop(0)
        if arg == "--worst":
            worst_only = True
        elif arg == "--without" and argv:
            without = set(argv.pop(0).split(","))
        elif arg in ("-h", "--help"):
            print(__doc__.strip())
            return 0
        else:
            args.append(arg)
    paths = []
    for arg in args:
        if os.path.isdir(arg):
            paths += sorted(os.path.join(arg, n) for n in os.listdir(arg) if n.endswith(".ci"))
        else:
            paths.append(arg)
    if not paths:
        print("stack-depth: no .ci files (compile with -fcallgraph-info=su)", file=sys.stderr)
        return 2
    try:
        frames, kinds, where, edges, externals = read_graph(paths)
    except Input as e:
        print(f"stack-depth: {e}", file=sys.stderr)
        return 2

    for title in sorted(frames):
        source = os.path.basename(where[title].split(":", 1)[0])
        key = source + ":" + short(title).split(".", 1)[0]
        key = key if key in TABLE_CALLS else source
        if key not in TABLE_CALLS or INDIRECT not in edges.get(title, ()):
            continue
        pattern, what = TABLE_CALLS[key]
        table = {t for t in frames if re.fullmatch(pattern, short(t).split(".", 1)[0])}
        if not table:
            continue  # stays unknown: the warning below names the caller
        # a public function's callbacks to its caller (CALLER_CALLBACKS)
        # stay marked, to be left out below
        caller = {INDIRECT} if short(title).split(".", 1)[0] in CALLER_CALLBACKS else set()
        edges[title] = (edges[title] - {INDIRECT}) | table | caller
        print(f"stack-depth: note: {short(title)} calls {what}: the deepest of "
              f"{len(table)} counted", file=sys.stderr)

    # --without: the left-out files' functions, and every call to them, go
    left_out = {t for t in frames
                if os.path.basename(where[t].split(":", 1)[0]) in without}
    for title in left_out:
        for table in (frames, kinds, where, edges):
            table.pop(title, None)
    for title in edges:
        edges[title] = edges[title] - left_out

    for title in frames:
        name = short(title).split(".", 1)[0]
        if name in CALLER_CALLBACKS and INDIRECT in edges.get(title, ()):
            edges[title] = edges[title] - {INDIRECT}
            print(f"stack-depth: note: {name} calls "
                  f"{CALLER_CALLBACKS[name]}; its stack is not counted",
                  file=sys.stderr)

    cycle = find_cycle(frames, edges)
    if cycle:
        print("stack-depth: error: recursion, no stack bound: "
              + " -> ".join(short(t) for t in cycle), file=sys.stderr)
        return 2

    public = sorted(t for t in frames if ":" not in t and PUBLIC.match(t))
    if not public:
        print("stack-depth: no public vor_ function in " + " ".join(paths), file=sys.stderr)
        return 2

    # Flag everything that makes a public depth unknown, once each.
    dynamic = {t for t in frames if kinds[t] != "static"}
    bad = dynamic | set(externals)
    flagged = set()
    for title in public:
        for b in sorted(reaches(title, edges, frames, bad) - flagged):
            flagged.add(b)
            if b in dynamic:
                print(f"stack-depth: warning: {short(b)} ({where[b]}): "
                      f"{kinds[b]} stack of {frames[b]}+ bytes; depth unknown",
                      file=sys.stderr)
            else:
                callers = sorted(short(t) for t in frames if b in edges.get(t, ()))
                what = ("indirect call" if b == INDIRECT
                        else f"call to {b} (not in the library)" if externals[b] in ("", b)
                        else f"call to {b} ({externals[b]}, not in the library)")
                print(f"stack-depth: warning: {what} from {', '.join(callers)}; "
                      "its stack is unknown", file=sys.stderr)

    depth = depths(frames, kinds, edges)

    def shown(d):
        return f"{d[0]}" if d[1] else f">={d[0]}"

    ranked = sorted(public, key=lambda t: (-depth[t][0], t))
    if worst_only:
        top = ranked[0]
        print(shown(depth[top]), top)
    else:
        width = max(len(t) for t in public)
        for t in ranked:
            chain = " -> ".join(
                f"{short(n)}({frames[n]})" if n in frames else f"{short(n)}(?)"
                for n in depth[t][2])
            print(f"{t:<{width}}  {shown(depth[t]):>6}  {chain}")
    return 0 if all(depth[t][1] for t in public) else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
