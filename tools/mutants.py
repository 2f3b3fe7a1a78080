#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""mutants.py - mutation testing of the library's core (make mutants).

Each mutant changes one token of one line of a target file (an operator,
a comparison, a constant, a '!'), is compiled, linked with the host test
suite and run: it is killed when a check fails, the program crashes or
traps, or it runs past the time limit. A mutant whose objects come out
byte for byte the same as the original's in every configuration is not
run: either its line is not compiled on the host (an #if branch of
another target, a function no file calls) or the compiler made the same
code of it (an equivalent mutant by construction). A mutant that does
not compile is discarded. The score is killed / (killed + survived).

Every survivor must be listed in tools/mutants-equivalent.txt with the
reason it is equivalent, or in tools/mutants-open.txt (survivors no test
kills yet, each with what a test must do); the run fails when the score
is below the floor (--floor, 95 % by default), when a survivor is in
neither list, and when a mutant of the open list is killed (the list
only shrinks: its line must go). Before the mutants, a self-test: the
unmutated build must pass, and a mutant that breaks vor_orient2d must be
killed, so the check cannot pass by not running.

    tools/mutants.py [--jobs N] [--every N] [--files src/a.c,...] [--lines TEXT]...

--every N runs about one mutant in N (make test's sample): those whose
key (file, line text, mutation) hashes to 0 modulo N, so that an edit of
other lines leaves the sample as it was. --lines TEXT runs only the
mutants of lines whose text, spaces squeezed, holds TEXT (given again,
any of them): after an edit, the edited lines' mutants, with --floor 0.
The report goes to build/mutants/report.txt and is printed.
See docs/testing.md, "Mutation testing".
"""
import argparse
import concurrent.futures
import hashlib
import os
import re
import shutil
import subprocess
import sys
import time

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), '..'))
OUT = os.path.join(ROOT, 'build', 'mutants')
EQUIVALENT = os.path.join(ROOT, 'tools', 'mutants-equivalent.txt')
OPEN = os.path.join(ROOT, 'tools', 'mutants-open.txt')
FLOOR = 95.0

# The files mutated, each with the test groups that run first (those most
# likely to kill its mutants quickly; a mutant they miss runs the whole
# suite before it counts as a survivor) and the build configurations
# (CONFIGS) its code depends on.
TARGETS = [
    ('src/predicates.c', 'predicates,mesh', ('host', 'limb32')),
    ('src/predicates.h', 'predicates,mesh', ('host', 'limb32')),
    ('src/multiword.h', 'predicates,mesh,raster,geometry', ('host', 'limb32')),
    ('src/perturbation.h', 'predicates,mesh,true_output,dynamic', ('host', 'index16')),
    ('src/mesh.h', 'mesh,api_safety,dynamic', ('host', 'index16')),
    ('src/mesh.c', 'mesh,api_safety,dynamic', ('host', 'index16')),
    ('src/incremental.c', 'mesh,true_output,api_safety', ('host', 'index16')),
    ('src/dynamic.c', 'dynamic,motion', ('host', 'index16')),
    ('src/motion.c', 'motion,dynamic', ('host', 'index16')),
]

# Build configurations, tried in order: a mutant whose objects do not change
# in the first (lines under #if of 32-bit limbs, of 16-bit ids) runs in the
# next of its file's, and a survivor runs in each of them where its code
# changed.
CONFIGS = [
    ('host', ['-DVOR_INDEX_BITS=32']),
    ('limb32', ['-DVOR_INDEX_BITS=32', '-DVOR_LIMB_BITS=32']),
    ('index16', ['-DVOR_INDEX_BITS=16']),
]
# A mutant that survives the test suite then meets the fault injection test
# (tests/faults/): predicates that lie are what the mesh updates' guards
# are for, and nothing else exercises them.
# It runs with 32-bit ids, and with 16-bit ones for the files built so
# (the targets' fault suites run with 16-bit ids: the mark bit moves).
FAULT_CONFIGS = [('faults', ['-DVOR_INDEX_BITS=32', '-DVOR_FAULT_INJECTION']),
                 ('faults16', ['-DVOR_INDEX_BITS=16', '-DVOR_FAULT_INJECTION'])]
FAULT_PROGRAM = 'tests/faults/test_faults.c'
# A survivor of both then meets its file's quick groups built with
# AddressSanitizer, as make test's host-sanitize suite: a read past an
# array that changes no value (a cache hint's address read from beyond
# the arena) is a fault only it sees.
ASAN_DEFS = ['-DVOR_INDEX_BITS=32']
ASAN_FLAGS = ['-fsanitize=address', '-fno-omit-frame-pointer']
COMMON = ['-std=c99', '-O1', '-Iinclude', '-Isrc', '-Iport', '-Itests', '-Itests/vectors',
          '-DVOR_STATS=1']
# The library traps on a failed assertion, as in the test build, on a
# shift by the operand's width or more (x86 masks the count, so such a
# mutant would pass here where ARM and RISC-V give 0) and on an index past
# an array's end: the sanitizer suites of make test reject both.
# A mutant that is not ISO C99 (a zero-size array: gcc's extension, which
# the bounds sanitizer does not check) does not compile, as in the
# -pedantic -Werror builds of make test; other warnings are only printed.
LIB_FLAGS = ['-ffreestanding', '-DVOR_ASSERT(x)=do { if (!(x)) __builtin_trap(); } while (0)',
             '-fsanitize=shift,bounds-strict', '-fsanitize-undefined-trap-on-error', '-pedantic-errors']
TEST_FLAGS = ['-w', '-DTEST_STOP_AT_FAILURE']

# ------------------------------------------------------------ C tokens

TOKEN = re.compile(r'''
    (?P<ws>\s+)
  | (?P<str>"(?:\\.|[^"\\])*"|'(?:\\.|[^'\\])*')
  | (?P<num>0[xX][0-9a-fA-F]+[uUlL]*|[0-9]+[uUlL]*)
  | (?P<id>[A-Za-z_][A-Za-z_0-9]*)
  | (?P<op><<=|>>=|->|\+\+|--|<<|>>|<=|>=|==|!=|&&|\|\||\+=|-=|\*=|/=|%=|&=|\|=|\^=|[-+*/%<>=!&|^~?:;,.(){}\[\]#])
  | (?P<other>.)
''', re.X)

TYPE_WORDS = {'void', 'char', 'short', 'int', 'long', 'unsigned', 'signed', 'bool', 'const',
              'struct', 'vor__limb', 'vor__dlimb', 'vor__sdlimb', 'volatile', 'size_t'}


def tokens(text):
    """(kind, text, start) of each token of a line without comments."""
    out = []
    for m in TOKEN.finditer(text):
        kind = m.lastgroup
        if kind != 'ws':
            out.append((kind, m.group(), m.start()))
    return out


def code_lines(path):
    """The file's lines with comments blanked, and which lines are code a
    mutant may touch (not preprocessor lines, not assertions)."""
    with open(path) as f:
        lines = f.read().split('\n')
    blanked, usable = [], []
    in_comment = False
    in_directive = False
    for line in lines:
        out = []
        i = 0
        while i < len(line):
            if in_comment:
                end = line.find('*/', i)
                if end < 0:
                    out.append(' ' * (len(line) - i))
                    i = len(line)
                else:
                    out.append(' ' * (end + 2 - i))
                    i = end + 2
                    in_comment = False
            elif line.startswith('/*', i):
                in_comment = True
            elif line.startswith('//', i):
                out.append(' ' * (len(line) - i))
                i = len(line)
            elif line[i] in '"\'':
                m = re.compile(r'"(?:\\.|[^"\\])*"|\'(?:\\.|[^\'\\])*\'').match(line, i)
                j = m.end() if m else len(line)
                out.append(line[i:j])
                i = j
            else:
                out.append(line[i])
                i += 1
        text = ''.join(out)
        directive = in_directive or text.lstrip().startswith('#')
        in_directive = directive and text.rstrip().endswith('\\')
        blanked.append(text)
        usable.append(not directive and 'VOR_ASSERT' not in text and 'assert' not in text and
                      text.strip() != '')
    return lines, blanked, usable


def is_operand_end(tok):
    kind, text, _ = tok
    return kind in ('num', 'id', 'str') and text not in ('return', 'case', 'sizeof') \
        or text in (')', ']')


def is_type_before(toks, i):
    """Does the token before toks[i] end a type name (a declaration's '*')?"""
    if i == 0:
        return True
    kind, text, _ = toks[i - 1]
    if text in TYPE_WORDS or text == '*':
        return True
    if kind == 'id' and (text.endswith('_t') or text.endswith('_fn')):
        return True
    if kind == 'id' and i >= 2 and toks[i - 2][1] == 'struct':
        return True
    return False


def constant_mutations(text):
    m = re.match(r'(0[xX][0-9a-fA-F]+|[0-9]+)([uUlL]*)$', text)
    digits, suffix = m.group(1), m.group(2)
    value = int(digits, 0) if digits[:2].lower() == '0x' else int(digits, 10)
    if digits != '0' and digits.startswith('0') and digits[:2].lower() != '0x':
        return []  # octal: none in the library
    hexa = digits[:2].lower() == '0x'

    def spell(v):
        return ('0x%X' % v if hexa else str(v)) + suffix
    out = [spell(value + 1)]
    if value >= 1:
        out.append(spell(value - 1))
    if value >= 2:
        out.append(spell(0))
    return out


SWAPS = {
    '+': ['-'], '-': ['+'], '*': ['/'], '/': ['*'], '%': ['/'],
    '<': ['<='], '<=': ['<'], '>': ['>='], '>=': ['>'], '==': ['!='], '!=': ['=='],
    '&&': ['||'], '||': ['&&'], '<<': ['>>'], '>>': ['<<'], '&': ['|'], '|': ['&'],
    '^': ['|'], '+=': ['-='], '-=': ['+='], '|=': ['&='], '&=': ['|='], '^=': ['|='],
    '<<=': ['>>='], '>>=': ['<<='], '++': ['--'], '--': ['++'],
}
BINARY_ONLY = {'+', '-', '*', '&'}


def line_mutations(text):
    """(start, end, replacement, description) for each mutant of a line."""
    toks = tokens(text)
    out = []
    seen = {}
    declaration = bool(toks) and (toks[0][1] in TYPE_WORDS or toks[0][1] == 'static' or
                                  toks[0][0] == 'id' and toks[0][1].endswith('_t'))
    for i, tok in enumerate(toks):
        kind, t, start = tok
        nth = seen.get(t, 0) + 1
        seen[t] = nth
        end = start + len(t)
        where = '%s#%d' % (t, nth)
        if kind == 'num':
            if declaration and 0 < i < len(toks) - 1 and toks[i - 1][1] == '[' \
                    and toks[i + 1][1] == ']':
                continue  # an array's declared size: a parameter's is ignored
            for r in constant_mutations(t):
                out.append((start, end, r, '%s -> %s' % (where, r)))
        elif kind == 'id' and t in ('true', 'false'):
            r = 'false' if t == 'true' else 'true'
            out.append((start, end, r, '%s -> %s' % (where, r)))
        elif kind == 'op' and t == '!':
            out.append((start, end, '', '%s removed' % where))
        elif kind == 'op' and t in SWAPS:
            binary = i > 0 and is_operand_end(toks[i - 1])
            if t in BINARY_ONLY and not binary:
                if t == '-' and i > 0 and toks[i - 1][1] not in ('(', ','):
                    continue  # a cast's '-' is the only other unary one worth it
                if t == '-':
                    out.append((start, end, '', '%s removed' % where))
                continue
            if t == '*' and is_type_before(toks, i):
                continue
            if t == '&' and is_type_before(toks, i):
                continue
            for r in SWAPS[t]:
                out.append((start, end, r, '%s -> %s' % (where, r)))
    return out


# ------------------------------------------------------ who uses what

IDENT = re.compile(r'[A-Za-z_][A-Za-z_0-9]*')


def header_definitions(blanked):
    """For a header: {name: identifiers of its body} for each function and
    macro, and the name of the function each line belongs to (None: outside
    any function, e.g. a structure)."""
    defs = {}
    owner = [None] * len(blanked)
    depth = 0
    pending = []  # tokens of the declaration being read at depth 0
    pending_start = 0
    current = None
    current_start = 0
    body_ids = set()
    in_directive = False
    macro = None
    for n, text in enumerate(blanked):
        if in_directive or text.lstrip().startswith('#'):
            if not in_directive:
                m = re.match(r'\s*#\s*define\s+([A-Za-z_][A-Za-z_0-9]*)(.*)', text)
                macro = m.group(1) if m else None
                rest = m.group(2) if m else ''
                if macro:
                    defs.setdefault(macro, set())
            else:
                rest = text
            if macro:
                defs[macro] |= set(IDENT.findall(rest))
            in_directive = text.rstrip().endswith('\\')
            continue
        for kind, t, _ in tokens(text):
            if depth == 0:
                if not pending:
                    pending_start = n
                if t == ';':
                    pending = []
                elif t == '{':
                    names = [pending[k - 1][1] for k in range(1, len(pending))
                             if pending[k][1] == '(' and pending[k - 1][0] == 'id']
                    current = names[0] if names else None
                    current_start = pending_start
                    body_ids = set(x[1] for x in pending if x[0] == 'id')
                    depth = 1
                    pending = []
                else:
                    pending.append((kind, t))
            else:
                if kind == 'id':
                    body_ids.add(t)
                if t == '{':
                    depth += 1
                elif t == '}':
                    depth -= 1
                    if depth == 0:
                        if current:
                            defs.setdefault(current, set()).update(body_ids)
                            for k in range(current_start, n + 1):
                                owner[k] = current
                        current = None
    return defs, owner


class Uses:
    """Which translation units a change to a header's function reaches."""

    def __init__(self, units, headers):
        self.defs = {}
        self.owner = {}
        for h in headers:
            _, blanked, _ = code_lines(os.path.join(ROOT, h))
            d, o = header_definitions(blanked)
            for k, v in d.items():
                self.defs.setdefault(k, set()).update(v)
            self.owner[h] = o
        self.reach = {}
        for u in units:
            _, blanked, _ = code_lines(os.path.join(ROOT, u))
            todo = [x for x in set(IDENT.findall('\n'.join(blanked))) if x in self.defs]
            seen = set(todo)
            while todo:
                x = todo.pop()
                for y in self.defs[x]:
                    if y in self.defs and y not in seen:
                        seen.add(y)
                        todo.append(y)
            self.reach[u] = seen

    def units_for(self, header, line_index, units):
        name = self.owner[header][line_index]
        if name is None:
            return list(units)
        return [u for u in units if name in self.reach[u]]


# ------------------------------------------------------------ building

def run(cmd, cwd, timeout=None):
    try:
        p = subprocess.run(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                           timeout=timeout)
        return p.returncode, p.stdout.decode(errors='replace')
    except subprocess.TimeoutExpired:
        return None, 'timeout'


def obj_name(unit):
    return unit.replace('/', '_').replace('.c', '.o')


class Tree:
    """A private copy of the sources a worker patches, with the objects of
    the unmutated build for each configuration."""

    def __init__(self, path, lib_units, test_units, port_units):
        self.path = path
        self.lib_units = lib_units
        self.test_units = test_units
        self.port_units = port_units
        self.preprocessed = {}  # (config, unit): the unmutated unit through gcc -E

    def copy_sources(self):
        shutil.rmtree(self.path, ignore_errors=True)
        for d in ('src', 'include', 'tests', 'port'):
            shutil.copytree(os.path.join(ROOT, d), os.path.join(self.path, d))
        os.makedirs(os.path.join(self.path, 'gen'))
        shutil.copy(os.path.join(ROOT, 'build', 'gen', 'predicate_vectors.c'),
                    os.path.join(self.path, 'gen', 'predicate_vectors.c'))

    def flags(self, config, unit):
        defs = (dict(FAULT_CONFIGS + [('asan', ASAN_DEFS)]).get(config) or
                dict(CONFIGS)[config])
        extra = ASAN_FLAGS if config == 'asan' else []
        if unit.startswith('src/'):
            return COMMON + defs + LIB_FLAGS + extra
        return COMMON + defs + TEST_FLAGS + extra

    def compile(self, config, unit, out):
        return run(['gcc'] + self.flags(config, unit) + ['-c', unit, '-o', out], self.path)

    def base(self, config):
        return os.path.join(self.path, 'obj-' + config)

    def main_obj(self, config, only):
        return os.path.join(self.base(config), 'main-%s.o' % (only.replace(',', '+') or 'all'))

    def compile_main(self, config, only):
        out = self.main_obj(config, only)
        if os.path.exists(out):
            return 0, ''
        cmd = ['gcc'] + self.flags(config, 'tests/main.c') + \
            ['-DTEST_ONLY="%s"' % only, '-c', 'tests/main.c', '-o', out]
        return run(cmd, self.path)

    def link(self, config, replaced, only, exe):
        objs = []
        for u in self.lib_units + self.test_units + self.port_units:
            objs.append(replaced.get(u, os.path.join(self.base(config), obj_name(u))))
        objs.append(self.main_obj(config, only))
        return run(['gcc'] + (ASAN_FLAGS if config == 'asan' else []) + objs + ['-o', exe],
                   self.path)

    def link_faults(self, config, replaced, exe):
        objs = [replaced.get(u, os.path.join(self.base(config), obj_name(u)))
                for u in self.lib_units]
        objs.append(os.path.join(self.base(config), obj_name(FAULT_PROGRAM)))
        for u in ['tests/harness.c'] + self.port_units:
            objs.append(os.path.join(self.base('host'), obj_name(u)))
        return run(['gcc'] + objs + ['-o', exe], self.path)


def build_base(trees, config, onlys, jobs):
    """Compiles the unmutated objects in the first tree, copies them to the
    others: every tree compiles the same relative paths, so an unchanged
    file gives the same bytes in each."""
    first = trees[0]
    os.makedirs(first.base(config), exist_ok=True)
    units = first.lib_units + first.test_units + first.port_units
    if config.startswith('faults'):
        units = first.lib_units + [FAULT_PROGRAM]
    with concurrent.futures.ThreadPoolExecutor(jobs) as pool:
        results = list(pool.map(
            lambda u: (u,) + first.compile(config, u, os.path.join(first.base(config), obj_name(u))),
            units))
    for u, rc, out in results:
        if rc != 0:
            sys.exit('mutants: the unmutated %s does not compile (%s):\n%s' % (u, config, out))
    for only in (onlys if not config.startswith('faults') else []):
        rc, out = first.compile_main(config, only)
        if rc != 0:
            sys.exit('mutants: tests/main.c does not compile:\n' + out)
    for t in trees[1:]:
        shutil.rmtree(t.base(config), ignore_errors=True)
        shutil.copytree(first.base(config), t.base(config))


# ------------------------------------------------------------- mutants

class Mutant:
    def __init__(self, index, path, line, start, end, replacement, description, text):
        self.index = index
        self.path = path
        self.line = line  # 0-based
        self.start, self.end = start, end
        self.replacement = replacement
        self.description = description
        self.text = text
        self.status = None
        self.detail = ''

    def key(self):
        return '%s :: %s :: %s' % (self.path, ' '.join(self.text.split()), self.description)

    def sampled(self, every):
        """In the sample of one in `every`: chosen by the mutant's own
        key, not its place in the list, which every edit above it moves."""
        digest = hashlib.sha256(self.key().encode('utf-8')).digest()
        return int.from_bytes(digest[:8], 'big') % every == 0


def generate(files):
    mutants = []
    for path in files:
        lines, blanked, usable = code_lines(os.path.join(ROOT, path))
        for n, text in enumerate(blanked):
            if not usable[n]:
                continue
            for start, end, r, desc in line_mutations(text):
                mutants.append(Mutant(len(mutants), path, n, start, end, r, desc, lines[n]))
    return mutants


def apply(tree, m, content):
    lines = content.split('\n')
    line = lines[m.line]
    lines[m.line] = line[:m.start] + m.replacement + line[m.end:]
    with open(os.path.join(tree.path, m.path), 'w') as f:
        f.write('\n'.join(lines))


def affected_units(m, tree, uses):
    if m.path.endswith('.c'):
        return [m.path]
    return uses.units_for(m.path, m.line, tree.lib_units + tree.test_units)


def test_run(tree, config, replaced, only, timeout, tag):
    exe = os.path.join(tree.path, 'mutant-%s' % tag)
    rc, out = tree.link(config, replaced, only, exe)
    if rc != 0:
        return 'link', out
    rc, out = run([exe], tree.path, timeout)
    if rc is None:
        return 'timeout', ''
    if rc == 0:
        return 'pass', ''
    if rc < 0:
        return 'signal %d' % -rc, ''
    fails = [x for x in out.split('\n') if x.startswith('FAIL ')]
    return 'fail', fails[0] if fails else 'exit %d' % rc


def try_mutant(tree, m, uses, originals, primary, configs, timeouts):
    """Builds and runs one mutant in tree; sets m.status to killed,
    survived, same-object (no configuration's code changed), not-built
    (its line is compiled in no configuration) or no-compile."""
    units = affected_units(m, tree, uses)
    apply(tree, m, originals[m.path])
    try:
        changed_any = False
        survived_in = []
        for config in configs[m.path]:
            replaced, error = changed_objects(tree, config, units, '')
            if error is not None:
                m.status, m.detail = 'no-compile', error
                return
            if not replaced:
                continue
            verdict = 'pass'
            if not changed_any:  # the first configuration: the quick groups first
                verdict, detail = test_run(tree, config, replaced, primary[m.path], timeouts[0], 'p')
            changed_any = True
            if verdict == 'pass':
                verdict, detail = test_run(tree, config, replaced, '', timeouts[1], 'f')
            if verdict == 'link':
                m.status, m.detail = 'no-compile', 'link: ' + detail.strip().split('\n')[0]
                return
            if verdict != 'pass':
                m.status = 'killed'
                m.detail = '%s: %s %s' % (config, verdict, detail)
                return
            survived_in.append(config)
        if changed_any:
            verdict, detail = faults_run(tree, m, units, configs[m.path])
            if verdict not in ('pass', 'same', 'no-compile', 'link'):
                m.status, m.detail = 'killed', 'faults: %s %s' % (verdict, detail)
                return
            asan, asan_detail = asan_run(tree, m, units, primary[m.path], timeouts[1])
            if asan not in ('pass', 'same', 'no-compile', 'link'):
                m.status, m.detail = 'killed', 'asan: %s %s' % (asan, asan_detail)
                return
            m.status, m.detail = 'survived', 'in ' + ', '.join(survived_in)
            if verdict == 'pass':
                m.detail += ', faults'
            if asan == 'pass':
                m.detail += ', asan'
            return
        m.status = 'same-object' if preprocessed_differs(tree, m, units, originals) else 'not-built'
    finally:
        with open(os.path.join(tree.path, m.path), 'w') as f:
            f.write(originals[m.path])


def changed_objects(tree, config, units, tag):
    """Compiles the mutant's units in a configuration: (those whose objects
    differ from the unmutated build's, None), or (None, the first line of
    the compiler's error)."""
    replaced = {}
    for u in units:
        out = os.path.join(tree.path, 'mut-%s%s' % (tag, obj_name(u)))
        rc, text = tree.compile(config, u, out)
        if rc != 0:
            return None, text.strip().split('\n')[0]
        with open(out, 'rb') as f, open(os.path.join(tree.base(config), obj_name(u)), 'rb') as g:
            if f.read() != g.read():
                replaced[u] = out
    return replaced, None


def faults_run(tree, m, units, configs):
    """The fault injection test on the mutant's library, with 32-bit ids and,
    for a file built with 16-bit ones, with those: 'same' when its objects
    change in neither build, 'pass' when it passes where they change."""
    verdict = 'same'
    for config, _ in FAULT_CONFIGS:
        if config == 'faults16' and 'index16' not in configs:
            continue
        replaced, error = changed_objects(tree, config, [u for u in units if u.startswith('src/')],
                                          config + '-')
        if error is not None:
            return 'no-compile', error
        if not replaced:
            continue
        result, detail = faults_program_run(tree, config, replaced)
        if result != 'pass':
            return result, ('%s: %s' % (config, detail)) if config != 'faults' else detail
        verdict = 'pass'
    return verdict, ''


def asan_run(tree, m, units, only, timeout):
    """The file's quick groups with AddressSanitizer on the mutant's
    library: 'same' when its objects do not change in that build."""
    replaced, error = changed_objects(tree, 'asan', units, 'asan-')
    if error is not None:
        return 'no-compile', error
    if not replaced:
        return 'same', ''
    return test_run(tree, 'asan', replaced, only, timeout, 'asan')


def faults_program_run(tree, config, replaced):
    exe = os.path.join(tree.path, 'mutant-' + config)
    rc, out = tree.link_faults(config, replaced, exe)
    if rc != 0:
        return 'link', out.strip().split('\n')[0]
    rc, out = run([exe], tree.path, 60)
    if rc is None:
        return 'timeout', ''
    if rc == 0:
        return 'pass', ''
    fails = [x for x in out.split('\n') if x.startswith('FAIL ')]
    return ('signal %d' % -rc if rc < 0 else 'fail'), (fails[0] if fails else '')


def preprocessed_differs(tree, m, units, originals):
    """Does the mutated line reach the compiler in some configuration? (If
    not, it lies under an #if no host configuration takes, or in a function
    no unit uses.)"""
    for config, _ in CONFIGS:
        for u in units:
            cmd = ['gcc', '-E', '-P'] + tree.flags(config, u) + [u]
            _, mutated = run(cmd, tree.path)
            key = (config, u)
            if key not in tree.preprocessed:  # the unmutated unit's, once per tree
                with open(os.path.join(tree.path, m.path), 'w') as f:
                    f.write(originals[m.path])
                tree.preprocessed[key] = run(cmd, tree.path)[1]
                apply(tree, m, originals[m.path])
            if mutated != tree.preprocessed[key]:
                return True
    return False


def load_list(path):
    """The mutants of a list file (equivalent or open), key -> reason."""
    known = {}
    if not os.path.exists(path):
        return known
    with open(path) as f:
        for n, line in enumerate(f, 1):
            line = line.rstrip('\n')
            if not line.strip() or line.startswith('#'):
                continue
            parts = [p.strip() for p in line.split(' :: ')]
            if len(parts) != 4 or not parts[3]:
                sys.exit('mutants: %s:%d: want "file :: line :: mutation :: reason"'
                         % (path, n))
            known[' :: '.join(parts[:3])] = parts[3]
    return known


def self_test(tree, uses, originals, primary, configs, timeouts):
    """The unmutated build passes in every configuration, and a mutant
    that makes vor_orient2d answer 0 is killed."""
    problems = []
    for config, _ in CONFIGS:
        for only in (primary['src/predicates.c'], ''):
            verdict, detail = test_run(tree, config, {}, only, timeouts[1], 'self')
            if verdict != 'pass':
                problems.append('the unmutated build fails (%s, ONLY=%s): %s %s'
                                % (config, only, verdict, detail))
    for config, _ in FAULT_CONFIGS:
        verdict, detail = faults_program_run(tree, config, {})
        if verdict != 'pass':
            problems.append('the unmutated fault injection test fails (%s): %s %s'
                            % (config, verdict, detail))
    for only in sorted(set(primary.values())):
        verdict, detail = test_run(tree, 'asan', {}, only, timeouts[1], 'self')
        if verdict != 'pass':
            problems.append('the unmutated AddressSanitizer build fails (ONLY=%s): %s %s'
                            % (only, verdict, detail))
    lines = originals['src/predicates.c'].split('\n')
    at = [n for n, x in enumerate(lines) if x.startswith('int vor_orient2d(')]
    brace = [n for n in range(at[0], len(lines)) if lines[n] == '{'] if at else []
    if not brace:
        problems.append('self-test: no definition of vor_orient2d in src/predicates.c')
    else:
        m = Mutant(-1, 'src/predicates.c', brace[0], 1, 1, ' return 0;', 'self-test', '{')
        try_mutant(tree, m, uses, originals, primary, configs, timeouts)
        if m.status != 'killed':
            problems.append('self-test: vor_orient2d answering 0 was not killed (%s %s)'
                            % (m.status, m.detail))
    return problems


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--jobs', type=int, default=2)
    ap.add_argument('--every', type=int, default=1, help='run about one mutant in N only (by its key)')
    ap.add_argument('--files', default='', help='comma-separated subset of the targets')
    ap.add_argument('--lines', action='append', default=[],
                    help='only the mutants of lines whose text (spaces squeezed) holds this; '
                         'may be given again (after an edit: run the edited lines again)')
    ap.add_argument('--floor', type=float, default=FLOOR,
                    help='the least share killed, in %% (default %(default).0f)')
    args = ap.parse_args()
    began = time.time()

    targets = [t for t in TARGETS if not args.files or t[0] in args.files.split(',')]
    primary = {t[0]: t[1] for t in TARGETS}
    configs = {t[0]: t[2] for t in TARGETS}
    files = [t[0] for t in targets]
    originals = {}
    for path, _, _ in TARGETS:
        with open(os.path.join(ROOT, path)) as f:
            originals[path] = f.read()

    with open(os.path.join(ROOT, 'sources.txt')) as f:
        lib_units = [x.strip() for x in f if x.strip().startswith('src/')]
    test_units = sorted('tests/' + x for x in os.listdir(os.path.join(ROOT, 'tests'))
                        if x.endswith('.c') and x != 'main.c') + ['gen/predicate_vectors.c']
    port_units = ['port/host/port.c']
    headers = sorted('src/' + x for x in os.listdir(os.path.join(ROOT, 'src')) if x.endswith('.h'))
    headers += sorted('include/' + x for x in os.listdir(os.path.join(ROOT, 'include'))
                      if x.endswith('.h'))
    uses = Uses(lib_units + [u for u in test_units if u.startswith('tests/')], headers)
    uses.reach['gen/predicate_vectors.c'] = set()

    trees = [Tree(os.path.join(OUT, 'tree%d' % k), lib_units, test_units, port_units)
             for k in range(args.jobs)]
    for t in trees:
        t.copy_sources()
    onlys = sorted(set(primary.values())) + ['']
    for config in [c for c, _ in CONFIGS + FAULT_CONFIGS]:
        build_base(trees, config, onlys, args.jobs)
    build_base(trees, 'asan', sorted(set(primary.values())), args.jobs)

    # time limits: a generous multiple of the unmutated run
    t0 = time.time()
    verdict, detail = test_run(trees[0], 'host', {}, '', 300, 'time')
    if verdict != 'pass':
        sys.exit('mutants: the unmutated host suite fails: %s %s' % (verdict, detail))
    full = time.time() - t0
    timeouts = (max(10.0, 8 * full), max(20.0, 8 * full))

    problems = self_test(trees[0], uses, originals, primary, configs, timeouts)

    mutants = generate([t[0] for t in TARGETS])
    wanted = [' '.join(x.split()) for x in args.lines]
    chosen = [m for m in mutants if m.sampled(args.every) and m.path in files and
              (not wanted or any(w in ' '.join(m.text.split()) for w in wanted))]
    print('mutants: %d generated, running %d (one in %d) on %d jobs'
          % (len(mutants), len(chosen), args.every, args.jobs), flush=True)
    free = list(trees)
    done = 0
    progress = open(os.path.join(OUT, 'progress.txt'), 'w')

    def work(m):
        tree = free.pop()
        try:
            try_mutant(tree, m, uses, originals, primary, configs, timeouts)
        finally:
            free.append(tree)
        return m

    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        for m in pool.map(work, chosen):
            done += 1
            progress.write('%s:%d: %s: %s %s\n' % (m.path, m.line + 1, m.description, m.status,
                                                  m.detail))
            progress.flush()
            if done % 200 == 0:
                print('  %d of %d, %.0f s' % (done, len(chosen), time.time() - began), flush=True)

    known = load_list(EQUIVALENT)
    still_open = load_list(OPEN)
    for key in sorted(set(known) & set(still_open)):
        problems.append('both equivalent and open: %s' % key)
    for m in chosen:
        if m.status == 'survived' and m.key() in known:
            m.status, m.detail = 'equivalent', known[m.key()]
    # survivors of the open list still count against the score
    listed_open = [m for m in chosen if m.status == 'survived' and m.key() in still_open]
    # an open entry is stale once none of its mutants survives (two lines
    # of the same text share a key: one may be killed, the other not)
    open_survivors = {m.key() for m in listed_open}
    closed = [m for m in chosen if m.status == 'killed' and m.key() in still_open
              and m.key() not in open_survivors]
    report = []
    report.append('Mutation testing of the host suite (tools/mutants.py, %d of %d mutants, one in %d)'
                  % (len(chosen), len(mutants), args.every))
    report.append('killed%: killed / (killed + survived); equivalent: survivors shown')
    report.append('equivalent in tools/mutants-equivalent.txt; same-code: objects unchanged')
    report.append('')
    states = ('killed', 'survived', 'equivalent', 'same-object', 'not-built', 'no-compile')
    report.append('%-19s %7s %6s %8s %10s %9s %9s %10s %7s' % (
        'file', 'mutants', 'killed', 'survived', 'equivalent', 'same-code', 'not-built',
        'no-compile', 'killed%'))
    totals = {}
    for path in files + ['total']:
        ms = [m for m in chosen if m.path == path or path == 'total']
        c = {st: sum(1 for m in ms if m.status == st) for st in states}
        scored = c['killed'] + c['survived']
        c['pct'] = 100.0 * c['killed'] / scored if scored else 100.0
        report.append('%-19s %7d %6d %8d %10d %9d %9d %10d %6.1f%%' % (
            (path, len(ms)) + tuple(c[st] for st in states) + (c['pct'],)))
        totals = c
    report.append('')
    survivors = [m for m in chosen if m.status == 'survived' and m.key() not in still_open]
    report.append('Survivors in no list (%d):' % len(survivors))
    for m in survivors:
        report.append('  %s:%d: %s' % (m.path, m.line + 1, m.description))
        report.append('      %s' % m.text.strip())
    report.append('Open survivors, tools/mutants-open.txt (%d):' % len(listed_open))
    for m in listed_open:
        report.append('  %s:%d: %s: %s' % (m.path, m.line + 1, m.description, still_open[m.key()]))
    equivalent = [m for m in chosen if m.status == 'equivalent']
    report.append('Equivalent survivors (%d), tools/mutants-equivalent.txt:' % len(equivalent))
    for m in equivalent:
        report.append('  %s:%d: %s: %s' % (m.path, m.line + 1, m.description, m.detail))
    elapsed = time.time() - began
    report.append('')
    below = 1 if totals['pct'] < args.floor else 0
    if problems:
        report.extend('FAIL ' + p for p in problems)
    if below:
        report.append('FAIL killed %.1f %% < %.1f %%' % (totals['pct'], args.floor))
    for m in survivors:
        report.append('FAIL a survivor neither killed, nor shown equivalent, nor open: %s:%d: %s'
                      % (m.path, m.line + 1, m.description))
    for m in closed:
        report.append('FAIL killed now, remove it from tools/mutants-open.txt: %s:%d: %s'
                      % (m.path, m.line + 1, m.description))
    failed = bool(problems) or below or bool(survivors) or bool(closed)
    report.append('run time: %.0f s' % elapsed)
    # the checks: each mutant killed or shown equivalent, the self-test's
    # (an unmutated run per configuration and group set, the unmutated
    # fault injection test, one killed mutant), and the floor
    self_checks = 2 * len(CONFIGS) + 2
    report.append('%d passed, %d failed' % (
        totals['killed'] - len(closed) + len(equivalent) + len(listed_open) + self_checks
        - len(problems) + 1 - below,
        len(survivors) + len(closed) + len(problems) + below))
    text = '\n'.join(report) + '\n'
    with open(os.path.join(OUT, 'report.txt'), 'w') as f:
        f.write(text)
    with open(os.path.join(OUT, 'mutants.txt'), 'w') as f:
        for m in mutants:
            if m.status:
                f.write('%s:%d: %s: %s %s\n' % (m.path, m.line + 1, m.description, m.status,
                                                m.detail))
    print(text, end='')
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())
