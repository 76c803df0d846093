#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Writes sample_data/paper-2018/power/*.csv: supply-current logs reconstructed from Biddulph et al. 2018.

The paper reports, at a 16 V supply, NUC 2.53 A (SD 0.35) = 40.52 W and Jetson 0.59 A (SD 0.09) = 9.48 W, GFLOPS/W
104.64 and 41.26 (peak GPU FLOPS / (16 V x maximum current)) and battery lives of 84.36 and 360.48 min (14.8 V,
3.85 Ah). Those roundings pin the exact statistics: mean power 40.524 W and 9.484 W (40.52 W and 84.36 min are both
only true for P in [40.5238, 40.525) W), maximum currents 3.13576 A and 0.742244 A. Each log is a two-level load
(idle/processing) with noise, scaled so its sample mean and SD are exactly those targets, with one spike at the
maximum. Deterministic; stdlib only.
"""
import math
import os
import random

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "sample_data", "paper-2018", "power")
SUPPLY_V = 16.0
RATE_HZ = 10
SECONDS = 120


def log(mean, sd, peak, low, high, seed):
    rng = random.Random(seed)
    n = SECONDS * RATE_HZ
    # Alternating processing (high) and waiting (low) phases of 2-6 s, with measurement noise.
    raw, level, left = [], high, 0
    for _ in range(n - 1):
        if left == 0:
            level = high if level == low else low
            left = rng.randint(20, 60)
        left -= 1
        raw.append(level + rng.uniform(-0.05, 0.05) * (high - low))
    spike = n // 3
    # Rest of the samples: mean and spread such that, with the spike, the whole log has exactly (mean, sd).
    rest_mean = (n * mean - peak) / (n - 1)
    rest_ss = (n - 1) * sd * sd - (peak - mean) ** 2 - (n - 1) * (rest_mean - mean) ** 2
    m = sum(raw) / len(raw)
    ss = sum((x - m) ** 2 for x in raw)
    k = math.sqrt(rest_ss / ss)
    rest = [rest_mean + (x - m) * k for x in raw]
    assert max(rest) < peak and min(rest) > 0, (max(rest), peak)
    values = rest[:spike] + [peak] + rest[spike:]
    mu = sum(values) / n
    s = math.sqrt(sum((x - mu) ** 2 for x in values) / (n - 1))
    assert abs(mu - mean) < 1e-12 and abs(s - sd) < 1e-12 and max(values) == peak
    return values


def write(name, platform, values, note):
    with open(os.path.join(OUT, name), "w") as f:
        f.write(f"# {platform} supply current at {SUPPLY_V:g} V, {RATE_HZ} Hz. Reconstructed from the paper's reported\n")
        f.write(f"# figures (Biddulph et al. 2018): {note}. Not a measurement.\n")
        f.write(f"# platform: {platform}\n# supply_voltage_V: {SUPPLY_V:g}\n")
        f.write("time_s,current_A\n")
        for i, v in enumerate(values):
            f.write(f"{i / RATE_HZ:.1f},{v!r}\n")


def verify(name, peak_flops, mean_a, sd_a, watts, gflops_w, minutes, power_window):
    """Reads the written file back (as text, like the importer) and checks every figure the paper reports."""
    with open(os.path.join(OUT, name)) as f:
        rows = [line.split(",") for line in f if line[0].isdigit()]
    v = [float(r[1]) for r in rows]
    n = len(v)
    mean = sum(v) / n
    sd = math.sqrt(sum((x - mean) ** 2 for x in v) / (n - 1))
    p = SUPPLY_V * mean
    got = (round(mean, 2), round(sd, 2), round(p, 2), round(peak_flops / (SUPPLY_V * max(v)) / 1e9, 2),
           round(14.8 * 3.85 / p * 60, 2))
    assert got == (mean_a, sd_a, watts, gflops_w, minutes), (name, got)
    # Both roundings of the paper at once only hold in a narrow window of mean power.
    assert power_window[0] <= p < power_window[1], (name, p)
    print(f"{name}: n = {n}, {mean:.5f} A (SD {sd:.4f}), {p:.4f} W, max {max(v):.6f} A, "
          f"{got[3]:.2f} GFLOPS/W, {got[4]:.2f} min")


def main():
    os.makedirs(OUT, exist_ok=True)
    nuc = log(40.524 / SUPPLY_V, 0.35, 5.25e12 / (SUPPLY_V * 104.64e9), 2.15, 2.95, 1)
    jetson = log(9.484 / SUPPLY_V, 0.09, 0.49e12 / (SUPPLY_V * 41.26e9), 0.48, 0.70, 2)
    write("nuc-current.csv", "NUC", nuc, "mean 2.53 A, SD 0.35, 40.52 W, max current from 104.64 GFLOPS/W")
    write("jetson-current.csv", "Jetson TX2", jetson, "mean 0.59 A, SD 0.09, 9.48 W, max current from 41.26 GFLOPS/W")
    # What the tool must show from these files, checked on the files as written.
    verify("nuc-current.csv", 5.25e12, 2.53, 0.35, 40.52, 104.64, 84.36, (40.5238, 40.525))
    verify("jetson-current.csv", 0.49e12, 0.59, 0.09, 9.48, 41.26, 360.48, (9.48389, 9.48415))


if __name__ == "__main__":
    main()
