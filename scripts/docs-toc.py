#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Writes the table of contents of a Markdown file between its <!-- toc --> and <!-- /toc --> lines.

Usage: scripts/docs-toc.py [--check] FILE...   (default: docs/cli.md)
Headings inside fenced code blocks are skipped; anchors follow GitHub's rule (lower case, punctuation dropped,
spaces to hyphens, repeats numbered). --check exits 1 when a file's contents list is out of date.
"""
import re
import sys

BEGIN, END = "<!-- toc -->", "<!-- /toc -->"


def anchor(title, seen):
    a = re.sub(r"[^\w\- ]", "", title.lower()).replace(" ", "-")
    n = seen.get(a, 0)
    seen[a] = n + 1
    return a if n == 0 else f"{a}-{n}"


def toc(text):
    lines, seen, fenced = [], {}, False
    for line in text.split("\n"):
        if line.startswith("```"):
            fenced = not fenced
            continue
        m = re.match(r"(#{2,3}) (.+)$", line)
        if fenced or not m or m.group(2).strip() == "Contents":
            continue
        title = m.group(2).strip()
        indent = "  " * (len(m.group(1)) - 2)
        lines.append(f"{indent}- [{title.replace('`', '')}](#{anchor(title, seen)})")
    return "\n".join(lines)


def main(argv):
    check = "--check" in argv
    files = [a for a in argv if a != "--check"] or ["docs/cli.md"]
    stale = False
    for path in files:
        text = open(path, encoding="utf-8").read()
        if BEGIN not in text or END not in text:
            sys.exit(f"{path}: no '{BEGIN}' ... '{END}' lines to fill")
        head, rest = text.split(BEGIN, 1)
        _, tail = rest.split(END, 1)
        new = f"{head}{BEGIN}\n{toc(head + tail)}\n{END}{tail}"
        if new != text:
            stale = True
            if not check:
                open(path, "w", encoding="utf-8").write(new)
    if check and stale:
        sys.exit("contents out of date: run scripts/docs-toc.py")


main(sys.argv[1:])
