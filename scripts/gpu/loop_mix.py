#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Instruction mix of each kernel's innermost loop, from PTX (nvcc -ptx) or SASS (cuobjdump -sass).

Usage: loop_mix.py FILE [NAME_SUBSTRING ...]
For every kernel (PTX .entry / SASS "Function :") whose name contains one of the substrings, finds the loops
(a label and a branch back to it) and prints, for the innermost loop with the most floating-point work, how many
multiplies, FMAs, additions/subtractions, moves and other instructions one pass runs, and the share of issue slots
that are FP32 arithmetic. An SM sub-partition issues one warp instruction per cycle, so a loop whose share is S
reaches at most S of the FP32 rate; every mov or integer instruction in the loop is a slot lost. In PTX a mul
followed by a sub may still become one FFMA in ptxas, and a neg.f32 is an operand modifier (not counted): read
SASS where cuobjdump exists. Exits 1 when no kernel matched."""
import re
import sys


def kernels_ptx(text):
    for m in re.finditer(r"\.entry\s+(\S+)\((.*?)^\}", text, re.S | re.M):
        name = m.group(1)
        body = m.group(2)
        lines = [l.strip() for l in body.splitlines()]
        yield name, lines


def kernels_sass(text):
    # cuobjdump -sass gives each instruction its address ("/*0090*/ FFMA ...") and branches to addresses
    # ("@P0 BRA 0x90"), with no labels (nvdisasm's "BRA `(.L_x_1)" has them): every address becomes a label line
    # "A_90:" and every branch names it, so loops are found as in PTX. Without this every kernel read "no loop".
    parts = re.split(r"^\s*Function : (\S+)\s*$", text, flags=re.M)
    for i in range(1, len(parts), 2):
        name = parts[i]
        lines = []
        for l in parts[i + 1].splitlines():
            at = re.match(r"^\s*/\*([0-9a-f]{4,})\*/", l)
            l = re.sub(r"/\*[0-9a-fx]*\*/", "", l)  # addresses and encodings
            l = re.sub(r"/\*.*?\*/", "", l).strip()
            l = re.sub(r"\b(BRA(?:\.[A-Z]+)*)\s+0x([0-9a-f]+)", lambda m: f"{m.group(1)} A_{int(m.group(2), 16):x}", l)
            if at and l:
                lines.append(f"A_{int(at.group(1), 16):x}:")
            if l:
                lines.append(l.rstrip(" ;"))
        yield name, lines


def opcode(line, sass):
    line = re.sub(r"^@!?U?P[T0-9]+\s+", "", line)  # predicate
    if sass and line.startswith("{"):
        line = line[1:].strip()
    op = line.split()[0] if line.split() else ""
    return op


def classify(op, sass):
    base = op.split(".")[0].upper()
    if sass:
        return {"FFMA": "fma", "FMUL": "mul", "FADD": "add", "MOV": "mov", "IMAD.MOV": "mov"}.get(
            op.split(".")[0] if not op.startswith("IMAD.MOV") else "IMAD.MOV", "other")
    if op.startswith("fma.") and ".f32" in op:
        return "fma"
    if op.startswith("mul.") and ".f32" in op:
        return "mul"
    if (op.startswith("sub.") or op.startswith("add.")) and ".f32" in op:
        return "add"
    if op.startswith("mov.") and ".f32" in op:
        return "mov"
    if op.startswith("neg.") and ".f32" in op:
        return "neg"  # folded into the FFMA's operand by ptxas: no instruction of its own
    return "other"


def loops(lines, sass):
    labels = {}
    for i, l in enumerate(lines):
        m = re.match(r"^(\$?\.?[A-Za-z_][\w$.]*):", l)
        if m:
            labels[m.group(1)] = i
    out = []
    for i, l in enumerate(lines):
        m = re.search(r"\bbra(?:\.uni)?\s+(\$?[\w$.]+)" if not sass else r"\bBRA(?:\.[A-Z]+)*\s+`?\(?([\w$.]+)\)?", l)
        if m and m.group(1) in labels and labels[m.group(1)] < i:
            out.append((labels[m.group(1)], i))
    return out


def mix(lines, start, end, sass):
    counts = {"fma": 0, "mul": 0, "add": 0, "mov": 0, "neg": 0, "other": 0}
    for l in lines[start + 1:end + 1]:
        if l.endswith(":") or l.startswith("//") or l.startswith("."):
            continue
        op = opcode(l, sass)
        if not op or op in ("{", "}"):
            continue
        counts[classify(op, sass)] += 1
    return counts


def main():
    if len(sys.argv) < 2:
        print(__doc__)
        return 2
    text = open(sys.argv[1], encoding="utf-8", errors="replace").read()
    wanted = sys.argv[2:]
    sass = "Function :" in text
    found = 0
    for name, lines in (kernels_sass(text) if sass else kernels_ptx(text)):
        if wanted and not any(w in name for w in wanted):
            continue
        found += 1
        best = None
        for start, end in loops(lines, sass):
            inner = not any(s > start and e < end for s, e in loops(lines, sass))
            c = mix(lines, start, end, sass)
            if inner and (best is None or c["fma"] + c["mul"] > best[2]["fma"] + best[2]["mul"]):
                best = (start, end, c)
        if best is None:
            print(f"{name}: no loop")
            continue
        c = best[2]
        total = sum(c.values()) - c["neg"]
        fp = c["fma"] + c["mul"] + c["add"]
        share = fp / total if total else 0
        neg = f", {c['neg']} neg (operand modifiers)" if c["neg"] else ""
        print(f"{name}: loop of {total} instructions: {c['mul']} mul, {c['fma']} fma, {c['add']} f32 add/sub, "
              f"{c['mov']} mov, {c['other']} other{neg}; FP32 arithmetic share of issue slots {100 * share:.1f} %")
    if not found:
        print(f"loop_mix: no kernel named {' or '.join(wanted) or '(any)'} in {sys.argv[1]}", file=sys.stderr)
    return 0 if found else 1


if __name__ == "__main__":
    sys.exit(main())
