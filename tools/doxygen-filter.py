#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""doxygen-filter.py FILE - a public header (or README.md, the main page)
as Doxygen should read it.

The headers document themselves in plain C comments, written to be read
in an editor, so Doxygen (docs/Doxyfile, INPUT_FILTER) sees them through
this filter, which writes FILE to stdout with:

- the file's top comment (the first after the SPDX line) as its @file page;
- a comment of its own line(s) before a declaration as that declaration's
  documentation, unless another comment follows it (section banners and
  their rules of '=' stay plain);
- a comment after code on the same line as the member's (`/**<`).

Comments of several lines are laid out for a fixed-width font (aligned
columns, indented examples), so they are shown verbatim (@verbatim),
which also keeps Doxygen from reading their text as markup: a header
edit cannot add a warning. One-line comments (a brief, or a member's
trailing comment) stay text, with the characters Doxygen would read as
commands or HTML escaped.
Comments inside function bodies (the inline entry points) stay plain.
No line is added or removed, so Doxygen's line numbers are the header's.
"""
import re
import sys


def main(path):
    with open(path, encoding="utf-8") as f:
        text = f.read()
    if path.endswith(".md"):
        sys.stdout.write(readme_links(text))
        return
    lines = text.split("\n")
    out = []
    in_comment = False
    verbatim = False
    file_tag = ""
    seen_file_comment = False
    depth_stack = []  # per open brace: True when it opens a function body
    pending = ""  # code since the last ';' or brace, to tell a body from a struct
    for i, line in enumerate(lines):
        if in_comment:
            if verbatim:
                # the " * " margin is decoration, not text
                line = re.sub(r"^\s*\*(?!/) ?", "", line)
            if "*/" in line:
                in_comment = False
                if verbatim:
                    line = line.replace("*/", "@endverbatim" + file_tag + " */", 1)
                    file_tag = ""
            out.append(line)
            continue
        in_body = any(depth_stack)
        stripped = line.lstrip()
        if stripped.startswith("/*") and not stripped.startswith(("/**", "/*!")):
            indent = line[: len(line) - len(stripped)]
            closes = "*/" in stripped[2:]
            verbatim = True
            rule = re.fullmatch(r"/\*[\s=*-]*\*/", stripped) is not None
            if "SPDX-License-Identifier" in stripped or in_body or rule or (
                    seen_file_comment and followed_by_comment(lines, i)):
                new = line
                verbatim = False
            elif not seen_file_comment:
                seen_file_comment = True
                # @file at the end: @verbatim must open the comment's text,
                # or Doxygen's Markdown pass reads inside it (__attribute__
                # in bold). It takes an optional name: the file's own.
                file_tag = " @file " + path.replace("\\", "/").rsplit("/", 1)[-1]
                new = indent + "/** @verbatim" + stripped[2:]
                if closes:
                    new = new.replace("*/", "@endverbatim" + file_tag + " */", 1)
                    verbatim = False
            elif closes:
                # one line: a brief, as text
                new = indent + "/**" + escape(stripped[2:])
                verbatim = False
            else:
                new = indent + "/** @verbatim" + stripped[2:]
            if verbatim and closes:
                new = new[::-1].replace("/*", "/* mitabrevdne@ ", 1)[::-1]
            out.append(new)
            in_comment = not closes
            continue
        # code, possibly with a trailing comment
        m = re.match(r"^(.*?\S.*?)/\*(?![*!])(.*)$", line)
        code = line
        if m and not in_body and '"' not in m.group(1):
            code = m.group(1)
            out.append(m.group(1) + "/**<" + escape(m.group(2)))
            in_comment = "*/" not in m.group(2)
            verbatim = False
        else:
            out.append(line)
            if m:
                code = m.group(1)
                in_comment = "*/" not in m.group(2)
        if code.lstrip().startswith("#"):
            continue
        for ch in code:
            if ch == "{":
                depth_stack.append(pending.rstrip().endswith(")"))
                pending = ""
            elif ch == "}":
                if depth_stack:
                    depth_stack.pop()
                pending = ""
            elif ch == ";":
                pending = ""
            else:
                pending += ch
        pending += " "
    sys.stdout.write("\n".join(out))


def readme_links(text):
    """README.md as the main page: its links to the repository's files
    (docs/api.md, LICENSE) lead from build/docs/html/ back to them, three
    folders up, as HTML links: Doxygen would look for a Markdown link to a
    .md file among its own pages.
    Pictures stay: IMAGE_PATH copies them."""
    return re.sub(r"(?<!!)\[([^\]]*)\]\((?![a-z]+:|#|/)([^)]+)\)",
                  r'<a href="../../../\2">\1</a>', text)


def escape(text):
    """A trailing comment's text with Doxygen's command and HTML characters
    escaped (the closing */ kept)."""
    body, sep, rest = text.partition("*/")
    return re.sub(r"([\\@&<>#%$])", r"\\\1", body) + sep + rest


def followed_by_comment(lines, i):
    """True when the comment that starts at line i is followed (after blank
    lines) by another comment rather than by code."""
    j = i
    while j < len(lines) and "*/" not in lines[j][lines[j].find("/*") + 2 if j == i else 0:]:
        j += 1
    j += 1
    while j < len(lines) and lines[j].strip() == "":
        j += 1
    return j < len(lines) and lines[j].lstrip().startswith("/*")


if __name__ == "__main__":
    main(sys.argv[1])
