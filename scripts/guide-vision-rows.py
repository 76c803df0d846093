#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Turns the demosaic part of `benchscope-cli bench vision` output (stdin) into the vision rows of docs/guide.md, "Measured performance" (stdout).

    build/app/cli/benchscope-cli bench vision | tee bench-vision.txt | scripts/guide-vision-rows.py

Copies the figures as the benchmark printed them; computes nothing, so the guide says what the run said."""
import re
import sys

text = sys.stdin.read()
head = re.search(r"BenchScope: Highway (\S+) .*?OpenCV (\S+): .*?its pool = (.*?) with (\d+) threads", text)
before = re.search(r"load average before: (\S+)", text)
after = re.search(r"load average after: (\S+)", text)
row = re.compile(r"^(\d+)\s+(8-bit|16-bit)\s+(bilinear|Malvar-He-Cutler)\s+"
                 r"([\d.]+) \+- ([\d.]+) \(n (\d+)\), median ([\d.]+), min ([\d.]+)\s+"
                 r"([\d.]+) \+- ([\d.]+) \(n (\d+)\), median ([\d.]+), min ([\d.]+)\s+"
                 r"([\d.]+x) \(([\d.]+x)\)\s+(<= \dx): (met|not met)$", re.M)
rows = row.findall(text)
if not head or not rows:
    sys.exit("guide-vision-rows: no demosaic table found in the input (is it `bench vision` output?)")
print(f"| threads | depth | demosaic | BenchScope ms/frame: median (mean ± SD, n; min) | OpenCV cvtColor bilinear "
      f"ms/frame: median (mean ± SD, n; min) | ratio of medians (of means) | target |")
print("|---|---|---|---|---|---|---|")
for t, depth, method, m, sd, n, med, lo, om, osd, on, omed, olo, ratio, ratio_means, limit, verdict in rows:
    print(f"| {t} | {depth} | {method} | {med} ({m} ± {sd}, {n}; {lo}) | {omed} ({om} ± {osd}, {on}; {olo}) | "
          f"{ratio} ({ratio_means}) | {limit}: {verdict} |")
print()
print(f"SIMD: Highway {head.group(1)} (chosen at run time); OpenCV {head.group(2)}, pool {head.group(3)}, "
      f"{head.group(4)} threads; 1-minute load average {before.group(1) if before else '?'} before, "
      f"{after.group(1) if after else '?'} after.")
