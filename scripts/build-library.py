#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Builds resources/library/library.json, BenchScope's library of published results, from public files kept outside
the project (third-party files are never committed): by default ../shared/public-data/resources/library/sources/
beside the checkout. Every value names the file and line it comes from; no number is typed by hand.

  scripts/build-library.py [--sources DIR]...    build library.json from the kept files (the first DIR holding a
                                                 file wins; default ../shared/public-data/resources/library/sources)
  scripts/build-library.py --check               fail when library.json differs from what the sources give
  scripts/build-library.py --fetch MIRROR_ROOT --sources DIR
                                                 copy the files the library needs and DIR lacks out of local git
                                                 mirrors of the public repositories (MIRROR_ROOT/<owner>+<name>/repo,
                                                 as the project's fetch tool leaves them) into DIR

Rules (issue #46: what a lab can defend), applied to every source alike, never by editing a row:
  - MLPerf Inference: the official metric of each round and scenario first, as that round's submission checker
    (mlcommons/inference tools/submission/) takes it: from v2.0 on SingleStream and MultiStream report LoadGen's
    early-stopping estimate (90th percentile per query, 99th percentile per query of 8 samples); v0.5 and v1.1
    the plain 90th percentile (SingleStream) and the streams (v0.5 MultiStream); Offline samples per second. The
    plain percentile is kept beside it where the two differ.
  - Power (MaxQ submissions): the mean of spl.txt's Watts strictly inside LoadGen's power window, and the power
    metric as the round's checker defines it, unit named: Offline W; SingleStream/MultiStream v1.1 J per query
    (mean power x window / (QPS with LoadGen overhead x window)), v2.0 on mJ per query (mean power x window x 1000
    / result_query_count). The in-window samples are kept so a budget can say which share of them lies above it;
    the power's kind (AC wall power of the whole system: PTDaemon logs Volts and a power factor) is said.
  - Precision from the measurements JSON of the result's own benchmark: v0.5 results folders named the benchmark
    differently from the measurements folders (resnet/ against resnet50/), so the benchmark's other folder names
    are tried; a data type stated in words ("We transform the original fp32 weight to int8 weight", "No change."
    beside "from int8 ... to int8") is read as the type the weights end up in.
  - A timing made of one run of one image is not a result: it is kept as a note with its words, never ranked.
  - A computer that stands in for another (the paper's NUC) says so in its name and its stand_in field.
  - A clpeak half-precision peak at the single-precision rate through PoCL is flagged: not the chip's FP16 peak.
  - Every file in the kept folder is either read by a result or listed in "kept_not_used" with the reason (an
    empty file is never read).
"""
import argparse
import json
import os
import re
import subprocess
import sys
from datetime import datetime, timezone

import yaml  # Debian's python3-yaml: the builder's reading; the importer reads RobotPerf with its own strict reader

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
LIB = os.path.join(ROOT, "resources", "library")
# The shared folder of third-party files: BENCHSCOPE_PUBLIC_DATA_DIR as CMake and scripts/fuzz take it, else
# ../shared/public-data beside the checkout (docs/third-party-data.md).
PUBLIC_DATA = os.path.normpath(os.environ.get("BENCHSCOPE_PUBLIC_DATA_DIR") or
                               os.path.join(ROOT, "..", "shared", "public-data"))
DEFAULT_SOURCES = os.path.join(PUBLIC_DATA, "resources", "library", "sources")
SOURCES = [DEFAULT_SOURCES]  # set by main(); the first root that holds a file wins
# ROS 2 graph benchmark results, kept beside the library's sources in the shared public data (new/ros2/).
DEFAULT_ROS2 = os.path.join(PUBLIC_DATA, "new", "ros2")
ROS2 = [DEFAULT_ROS2]

PAPER_NUC = "the paper's Intel NUC7i7BNH (Core i7-7567U, Iris Plus 650)"

# The computers, and how a user may name them (benchscope-cli platforms --library orin,pi5). A fourth field says
# which computer a row stands in for when it is not that computer.
COMPUTERS = [
    ("jetson-agx-orin", "NVIDIA Jetson AGX Orin", ["orin", "agx-orin"], ""),
    ("jetson-orin-nx", "NVIDIA Jetson Orin NX", ["orin-nx"], ""),
    ("jetson-agx-xavier", "NVIDIA Jetson AGX Xavier", ["xavier", "agx-xavier"], ""),
    ("jetson-xavier-nx", "NVIDIA Jetson Xavier NX", ["xavier-nx"], ""),
    ("jetson-tx2", "NVIDIA Jetson TX2", ["tx2"], ""),
    ("jetson-nano", "NVIDIA Jetson Nano", ["nano"], ""),
    ("jetson-orin-nano", "NVIDIA Jetson Orin Nano", ["orin-nano"], ""),
    ("jetson-agx-thor", "NVIDIA Jetson AGX Thor", ["thor", "agx-thor"], ""),
    ("jetson-thor-t4000", "NVIDIA Jetson Thor T4000", ["t4000", "thor-t4000"], ""),
    ("nvidia-dgx-spark", "NVIDIA DGX Spark", ["dgx-spark", "spark"], ""),
    ("x86-rtx4090", "x86_64 PC with NVIDIA GeForce RTX 4090 (CPU not named)", ["rtx4090", "x86-4090"], ""),
    ("x86-rtx5090", "x86_64 PC with NVIDIA GeForce RTX 5090 (CPU not named)", ["rtx5090", "x86-5090"], ""),
    ("amd-kria-kv260", "AMD Kria KV260 (named 'Kria KV260' in RobotPerf's results)", ["kv260", "kria-kv260"], ""),
    ("amd-kria-kr260", "AMD Kria KR260 (named 'Kria KR260' in RobotPerf's results)", ["kr260", "kria-kr260"], ""),
    ("raspberry-pi-4", "Raspberry Pi 4 Model B", ["pi4", "rpi4"], ""),
    ("raspberry-pi-cm4", "Raspberry Pi Compute Module 4", ["cm4"], ""),
    ("raspberry-pi-5", "Raspberry Pi 5 Model B", ["pi5", "rpi5"], ""),
    ("intel-icl-i3-1005g1", "Intel Core i3-1005G1 (Ice Lake U, 2 cores, Windows 10) [stand-in for the paper's NUC]",
     ["icl", "i3-1005g1", "nuc-icl"],
     "stands in for " + PAPER_NUC + ": a different computer (2-core Ice Lake U laptop part, Windows 10 Home, "
     "OpenVINO on its UHD Graphics iGPU), not the NUC"),
    ("intel-uhd-620", "Intel UHD Graphics 620 (host computer not named in the log) [stand-in for the paper's NUC GPU]",
     ["uhd620"],
     "stands in for the GPU of " + PAPER_NUC + ": a Kaby Lake R U-series iGPU in a host the clpeak log does not "
     "name, not the NUC's Iris Plus 650"),
]

COMMITS = {
    "mlcommons/inference_results_v0.5": "f5acb8be3da3ebc13cf6ba783cce371f96d275ac",
    "mlcommons/inference_results_v1.1": "7fc43356c4d71ed6ec97af9d035a34ed146587b8",
    "mlcommons/inference_results_v3.0": "1948f9b5b93c5b4dcafe15de0faa08cdf1439fca",
    "krrishnarraj/clpeak": "18c668f1c940663e62eed5bcc3e460ac541ea4b1",
}
ROUND_DATES = {"v0.5": "2019-11", "v1.1": "2021-09", "v3.0": "2023-04"}  # publication month of each round

# The submission checker of each round, where its result and power metric are defined (mlcommons/inference).
CHECKER = {
    "v0.5": None,  # no power results in v0.5
    "v1.1": ("https://github.com/mlcommons/inference/blob/c5b89189389253dcd298a3a5ca8b3668ac1bbd69/"
             "tools/submission/submission-checker.py", "r1.1 @ c5b8918, check_power_dir() lines 819-902"),
    "v3.0": ("https://github.com/mlcommons/inference/blob/fd6486a0483de3175c67bdd84576eb5f4f406be7/"
             "tools/submission/submission_checker.py", "v3.0 @ fd6486a, RESULT_FIELD_NEW and check_power_dir() "
             "lines 1188-1240, 1770-1895"),
}


def uses_early_stopping(rnd):  # submission_checker.py v3.0 Config.uses_early_stopping
    return rnd not in ("v0.5", "v0.7", "v1.0", "v1.1")


def has_query_count_in_log(rnd):  # Config.has_query_count_in_log
    return rnd not in ("v0.5", "v0.7", "v1.0", "v1.1")


# MLPerf results: (round, submitter folder, system folder, network folder, scenario folder, computer, power run).
MLPERF = []
for scen in ("SingleStream", "MultiStream", "Offline"):
    for net in ("resnet50", "retinanet"):
        MLPERF.append(("v3.0", "closed/NVIDIA", "Orin_TRT", net, scen, "jetson-agx-orin", False))
        MLPERF.append(("v3.0", "closed/NVIDIA", "Orin_NX_TRT", net, scen, "jetson-orin-nx", False))
        MLPERF.append(("v3.0", "closed/NVIDIA", "Orin_TRT_MaxQ", net, scen, "jetson-agx-orin", True))
for scen in ("SingleStream", "Offline"):
    for net in ("resnet50", "ssd-mobilenet"):
        MLPERF.append(("v1.1", "closed/NVIDIA", "AGX_Xavier_TRT", net, scen, "jetson-agx-xavier", False))
        MLPERF.append(("v1.1", "closed/NVIDIA", "AGX_Xavier_TRT_MaxQ", net, scen, "jetson-agx-xavier", True))
        MLPERF.append(("v1.1", "closed/NVIDIA", "Xavier_NX_TRT", net, scen, "jetson-xavier-nx", False))
        MLPERF.append(("v1.1", "closed/NVIDIA", "Xavier_NX_TRT_MaxQ", net, scen, "jetson-xavier-nx", True))
    for net in ("resnet", "ssd-small"):
        MLPERF.append(("v0.5", "closed/Intel", "ICL-I3-1005G1_OpenVINO-Windows", net, scen, "intel-icl-i3-1005g1",
                       False))
# Krai's offline/ and multistream/ folders of these systems hold copies of the SingleStream log ("Scenario :
# SingleStream"): only the SingleStream result is taken.
for scen in ("singlestream",):
    MLPERF.append(("v3.0", "closed/Krai", "rpi4-tflite-v2.11.0-ruy", "resnet50", scen, "raspberry-pi-4", False))
    MLPERF.append(("v3.0", "closed/Krai", "rpi4-armnn-v22.11-neon", "resnet50", scen, "raspberry-pi-4", False))
MLPERF.append(("v0.5", "closed/NVIDIA", "Xavier", "ssd-small", "MultiStream", "jetson-agx-xavier", False))

NETWORK_NAMES = {"resnet": "resnet50", "ssd-small": "ssd-mobilenet"}  # v0.5's folder names
# The folder names one MLPerf benchmark has had in results/ and measurements/ (v0.5 Intel: results/.../resnet/,
# measurements/.../resnet50/).
BENCHMARK_FOLDERS = [("resnet", "resnet50"), ("ssd-small", "ssd-mobilenet")]

# clpeak logs: (path in krrishnarraj/clpeak at COMMITS, computer, device note).
CLPEAK = [
    ("results/old/Intel_Graphics_Compute_Runtime/Intel_UHD_Graphics_620.log", "intel-uhd-620", "GPU"),
    # "Device: NVIDIA Tegra X1" at 921 MHz: the Maxwell GPU through PoCL's CUDA driver ("Note via POCL 1.3").
    ("results/old/Portable_Computing_Language/Jetson_Nano_Tegra_X1.txt", "jetson-nano", "GPU (PoCL CUDA)"),
]
# GPUs whose FP16 rate is twice their FP32 rate (packed half2), by the device name clpeak prints.
DOUBLE_RATE_FP16 = {"NVIDIA Tegra X1": "Maxwell GM20B: FP16 at twice the FP32 rate (packed half2)"}

# Lines pasted in issue threads: (kept file, URL, date, computer).
HPL = [
    ("issues/geerlingguy+top500-benchmark+18.txt", "https://github.com/geerlingguy/top500-benchmark/issues/18",
     "2023-09-28", "raspberry-pi-5"),
    ("issues/geerlingguy+top500-benchmark+51.txt", "https://github.com/geerlingguy/top500-benchmark/issues/51",
     "2025-01-09", "raspberry-pi-5"),
    ("issues/geerlingguy+top500-benchmark+33.txt", "https://github.com/geerlingguy/top500-benchmark/issues/33",
     "2024-05-21", "raspberry-pi-cm4"),
]
# TensorRT timing reports: jetson-inference prints one "Timing Report" per image, so a pasted report is one run of
# one image. The maintainer's words in the same thread say why that is not a benchmark result.
TRT_REPORTS = [
    ("issues/dusty-nv+jetson-inference+388.txt", "https://github.com/dusty-nv/jetson-inference/issues/388",
     "2019-08-15", "jetson-tx2",
     "dusty-nv (maintainer), comment of 2019-08-23 in the same thread: \"The first run will be slow, and don't "
     "measure benchmark results from just one run (see the python examples which do multiple runs with the "
     "--profile flag).\""),
]


def repo_of(rnd):
    return "mlcommons/inference_results_" + rnd


# System descriptions whose file name differs from the results folder's (v0.5 Intel: the commit has no
# systems/ICL-I3-1005G1_OpenVINO-Windows.json; its system is described in systems/ICL-i31005G1_openvino.json).
SYSTEM_FILES = {"ICL-I3-1005G1_OpenVINO-Windows": "ICL-i31005G1_openvino"}
# Files found in the kept folder that no result reads, and why.
NOT_AT_COMMIT = {
    "mlcommons+inference_results_v0.5/closed/Intel/systems/ICL-I3-1005G1_OpenVINO-Windows.json":
        "empty, and no such file exists at f5acb8b (the system is described in systems/ICL-i31005G1_openvino.json): "
        "never read; remove it from the kept folder",
}


def system_json(sub, system):
    return f"{sub}/systems/{SYSTEM_FILES.get(system, system)}.json"


def run_folder(entry):
    rnd, sub, system, net, scen, _, _ = entry
    return f"{sub}/results/{system}/{net}/{scen}/performance/run_1"


def mlperf_paths(entry):
    run = run_folder(entry)
    paths = [f"{run}/mlperf_log_summary.txt", system_json(entry[1], entry[2])]
    if entry[6]:
        paths += [f"{run}/mlperf_log_detail.txt", f"{run}/spl.txt"]
    return paths


def rel(repo, path):
    return repo.replace("/", "+") + "/" + path


def kept(repo, path):
    """The kept copy of repo:path: the first source root that holds it (else where the first would)."""
    for root in SOURCES:
        p = os.path.join(root, rel(repo, path))
        if os.path.exists(p):
            return p
    return os.path.join(SOURCES[0], rel(repo, path))


def kept_name(repo, path):  # as library.json names it: relative to resources/library/ of the kept tree
    return "sources/" + rel(repo, path)


USED = set()  # kept files read by some result (relative to a source root)


def use(repo, path):
    p = kept(repo, path)
    if not os.path.isfile(p):
        raise SystemExit(f"{p}: kept file missing (scripts/build-library.py --fetch MIRROR_ROOT --sources DIR)")
    if os.path.getsize(p) == 0:
        raise SystemExit(f"{p}: kept file is empty: not a source")
    USED.add(rel(repo, path))
    return p


def git_show(mirror, commit, path):
    return subprocess.run(["git", "-C", mirror, "show", f"{commit}:{path}"], check=True,
                          capture_output=True).stdout


def git_ls(mirror, commit, folder):
    out = subprocess.run(["git", "-C", mirror, "ls-tree", "--name-only", f"{commit}:{folder}"],
                         capture_output=True, text=True)
    return out.stdout.split() if out.returncode == 0 else []


def measurement_folders(entry):
    rnd, sub, system, net, scen, _, _ = entry
    names = [net] + [n for pair in BENCHMARK_FOLDERS if net in pair for n in pair if n != net]
    return [f"{sub}/measurements/{system}/{n}/{scen}" for n in names]


def fetch(mirror_root):
    """Copies what the kept folder (the first --sources) lacks out of the mirrors; never rewrites a kept file."""
    def put(repo, path):
        if os.path.exists(kept(repo, path)):
            return
        out = os.path.join(SOURCES[0], rel(repo, path))
        mirror = os.path.join(mirror_root, repo.replace("/", "+"), "repo")
        os.makedirs(os.path.dirname(out), exist_ok=True)
        with open(out, "wb") as f:
            f.write(git_show(mirror, COMMITS[repo], path))
        print("fetched", out)

    for entry in MLPERF:
        repo = repo_of(entry[0])
        mirror = os.path.join(mirror_root, repo.replace("/", "+"), "repo")
        if not os.path.isdir(mirror):
            continue
        for p in mlperf_paths(entry):
            put(repo, p)
        for folder in measurement_folders(entry):
            names = [n for n in git_ls(mirror, COMMITS[repo], folder) if n.endswith(".json") and n != "config.json"]
            if names:
                put(repo, f"{folder}/{names[0]}")
                break
    if os.path.isdir(os.path.join(mirror_root, "krrishnarraj+clpeak", "repo")):
        for path, _, _ in CLPEAK:
            put("krrishnarraj/clpeak", path)


def lines_of(path):
    with open(path, encoding="utf-8", errors="replace") as f:
        return f.read().splitlines()


def summary_values(path):
    """Key -> (value text, line number) for the 'Key : Value' lines of a LoadGen summary (first occurrence, per-sample
    block for v0.5's MultiStream, whose per-query block comes first), and the early-stopping estimates
    (" * Early stopping 90th percentile estimate: 1637696") as "Early stopping 90th percentile estimate"."""
    values, per_query = {}, False
    for no, line in enumerate(lines_of(path), 1):
        s = line.strip()
        m = re.match(r"^\*\s*(Early stopping \d+th percentile estimate)\s*:\s*(\d+)\s*$", s)
        if m:
            values.setdefault(m.group(1), (m.group(2), no))
            continue
        if s.startswith("Per-query latency"):
            per_query = True
        if s.startswith("Per-sample latency"):
            per_query = False
        if ":" not in s or s.startswith("*"):
            continue
        k, v = (x.strip() for x in s.split(":", 1))
        if per_query and "percentile latency" in k:
            k = "per-query " + k
        values.setdefault(k, (v, no))
    return values


def detail_values(path):
    """Key -> (value, line number) of the :::MLLOG lines of a detail log (the keys the checker reads)."""
    want = ("power_begin", "power_end", "result_query_count", "result_qps_with_loadgen_overhead",
            "early_stopping_latency_ss", "early_stopping_latency_ms", "loadgen_version")
    out = {}
    for no, line in enumerate(lines_of(path), 1):
        if not line.startswith(":::MLLOG "):
            continue
        for key in want:
            if line.startswith(':::MLLOG {"key": "%s"' % key):
                out.setdefault(key, (json.loads(line[len(":::MLLOG "):])["value"], no))
    return out


DTYPE = r"(u?int\d+|fp\d+|bf16|float\d+)"


def data_type_of(fields):
    """The data type the weights end up in, from a measurements JSON's words, and the field and text it comes from.
    A type named alone ("int8"); a change in words ("transform ... fp32 weight to int8 weight": the type after
    "to"); "No change." reads the starting type from weight_transformations ("from int8 ... to int8")."""
    def final_type(text):
        t = text.lower()
        if re.fullmatch(DTYPE, t.strip().rstrip(".")):
            return t.strip().rstrip(".")
        m = re.search(r"\bto\s+(?:\w+\s+)?" + DTYPE, t)
        if m:
            return m.group(1)
        found = set(re.findall(r"\b" + DTYPE + r"\b", t))
        return found.pop() if len(found) == 1 else None

    weights = str(fields.get("weight_data_types", "")).strip()
    t = final_type(weights) if weights else None
    if t:
        return t, "weight_data_types", weights
    if weights.lower().rstrip(".") in ("no change", "none", ""):
        trans = str(fields.get("weight_transformations", "")).strip()
        t = final_type(trans) if trans else None
        if t:
            return t, "weight_transformations", trans
    return None, "weight_data_types", weights


def precision_of(repo, entry):
    for folder in measurement_folders(entry):
        path = kept(repo, folder)
        if not os.path.isdir(path):
            continue
        for name in sorted(os.listdir(path)):
            if name.endswith(".json") and name != "config.json":
                use(repo, f"{folder}/{name}")
                with open(os.path.join(path, name), encoding="utf-8") as f:
                    fields = json.load(f)
                t, field, text = data_type_of(fields)
                return t, field, text, f"{folder}/{name}"
    print("warning: no measurements JSON kept for %s (looked in %s): precision \"not stated\"; "
          "--fetch MIRROR_ROOT --sources DIR copies it" % (run_folder(entry), ", ".join(measurement_folders(entry))),
          file=sys.stderr)
    return None, None, None, None


def ptd_epoch(text):  # PTDaemon's and LoadGen's "MM-DD-YYYY hh:mm:ss.fff", UTC from v1.1 on (the checker's rule)
    return datetime.strptime(text, "%m-%d-%Y %H:%M:%S.%f").replace(tzinfo=timezone.utc).timestamp()


def power_window(repo, entry, detail):
    """Watts of spl.txt strictly inside LoadGen's power window (the checker's `power_begin < t < power_end`), the
    window length, and the mean Volts and power factor of those samples (what kind of power it is)."""
    spl = use(repo, run_folder(entry) + "/spl.txt")
    b, e = ptd_epoch(detail["power_begin"][0]), ptd_epoch(detail["power_end"][0])
    watts, volts, pf = [], [], []
    for line in lines_of(spl):
        f = line.split(",")
        if len(f) > 3 and f[0] == "Time":
            t = ptd_epoch(f[1])
            if b < t < e:
                watts.append(float(f[3]))
                if len(f) > 5 and f[4] == "Volts":
                    volts.append(float(f[5]))
                if len(f) > 9 and f[8] == "PF":
                    pf.append(float(f[9]))
    return watts, e - b, volts, pf


def official_metric(rnd, scenario, v, detail):
    """The round's result for the scenario, as its submission checker takes it: (field, value, unit, statistic,
    definition, line), and the plain percentile where it differs."""
    if scenario == "SingleStream":
        plain_key = "90th percentile latency (ns)" if "90th percentile latency (ns)" in v else \
            "90.00 percentile latency (ns)"
        plain = (plain_key, float(v[plain_key][0]) * 1e-9, "s", "p90", v[plain_key][1])
        if uses_early_stopping(rnd):
            key = "Early stopping 90th percentile estimate"
            if key not in v:
                raise SystemExit(f"{rnd} SingleStream summary without its early-stopping estimate")
            return ((key, float(v[key][0]) * 1e-9, "s", "p90 early-stopping estimate",
                     f"MLPerf Inference {rnd} SingleStream result: LoadGen's early-stopping estimate of the 90th "
                     "percentile latency (checker field early_stopping_latency_ss), not the plain percentile",
                     v[key][1]), plain)
        return ((plain_key, plain[1], "s", "p90",
                 f"MLPerf Inference {rnd} SingleStream result: the 90th percentile latency (before v2.0 there was "
                 "no early stopping)", plain[4]), None)
    if scenario == "MultiStream":
        if "99th percentile latency (ns)" in v:  # v1.0 on: per query of samples_per_query samples
            plain = ("99th percentile latency (ns)", float(v["99th percentile latency (ns)"][0]) * 1e-9, "s",
                     "p99 per query", v["99th percentile latency (ns)"][1])
            key = "Early stopping 99th percentile estimate"
            if uses_early_stopping(rnd) and key in v:
                return ((key, float(v[key][0]) * 1e-9, "s", "p99 per query early-stopping estimate",
                         f"MLPerf Inference {rnd} MultiStream result: LoadGen's early-stopping estimate of the 99th "
                         "percentile latency per query of 8 samples (checker field early_stopping_latency_ms)",
                         v[key][1]), plain)
            return ((plain[0], plain[1], "s", "p99 per query", f"MLPerf Inference {rnd} MultiStream result: the "
                     "99th percentile latency per query", plain[4]), None)
        key = "Samples per query"  # v0.5 .. v1.1 legacy MultiStream: streams within the latency bound
        return ((key, float(v[key][0]), "streams", "streams",
                 f"MLPerf Inference {rnd} MultiStream result: the number of streams (samples per query) whose "
                 "99th percentile latency meets the benchmark's bound", v[key][1]), None)
    if scenario == "Offline":
        key = "Samples per second"
        return ((key, float(v[key][0]), "1/s", "samples per second",
                 f"MLPerf Inference {rnd} Offline result: samples per second", v[key][1]), None)
    raise SystemExit("scenario " + scenario + " is not taken")


def power_metric(rnd, scenario, mean_w, window_s, detail, spq):
    """The round's power metric (value, unit, definition, detail-log lines used), as its checker computes it."""
    lines = {"power_begin": detail["power_begin"][1], "power_end": detail["power_end"][1]}
    if scenario in ("Offline", "Server"):
        return mean_w, "W", (f"MLPerf Inference {rnd} {scenario} power metric: the mean of spl.txt's Watts strictly "
                             "inside LoadGen's power window (power_begin .. power_end)"), lines
    if has_query_count_in_log(rnd):
        queries, no = detail["result_query_count"]
        lines["result_query_count"] = no
        return mean_w * window_s * 1000 / queries, "mJ/query", (
            f"MLPerf Inference {rnd} {scenario} power metric: mean power x power window x 1000 / result_query_count "
            f"(millijoules per query{' of %d samples' % spq if spq > 1 else ''})"), lines
    if scenario == "SingleStream":
        qps, no = detail["result_qps_with_loadgen_overhead"]
        lines["result_qps_with_loadgen_overhead"] = no
        return mean_w * window_s / (qps * window_s), "J/query", (
            f"MLPerf Inference {rnd} SingleStream power metric: mean power x power window / (QPS with LoadGen "
            "overhead x power window): joules per query (LoadGen logged no query count before v2.0)"), lines
    raise SystemExit(f"{rnd} {scenario}: no power metric rule")


def mlperf_result(entry):
    rnd, sub, system, net, scen, computer, power = entry
    repo = repo_of(rnd)
    commit = COMMITS[repo]
    spath = mlperf_paths(entry)[0]
    v = summary_values(use(repo, spath))
    with open(use(repo, system_json(sub, system)), encoding="utf-8") as f:
        sysj = json.load(f)
    scenario = v["Scenario"][0].replace(" ", "")
    if v["Result is"][0] != "VALID":
        raise SystemExit(f"{spath}: not a VALID result")
    detail = detail_values(use(repo, run_folder(entry) + "/mlperf_log_detail.txt")) if power else {}
    lines = {}

    def num(key):
        text, no = v[key]
        lines[key] = no
        return float(text)

    r = {"kind": "mlperf-inference", "computer": computer, "network": NETWORK_NAMES.get(net, net),
         "scenario": scenario, "round": rnd, "date": ROUND_DATES[rnd], "division": sub.split("/")[0],
         "submitter": sysj.get("submitter", ""), "system": sysj.get("system_name", system),
         "validity": "VALID"}
    official, plain = official_metric(rnd, scenario, v, detail)
    key, value, unit, statistic, definition, line = official
    lines[key] = line
    r["official"] = {"metric": key, "value": value, "unit": unit, "statistic": statistic,
                     "definition": definition}
    if plain and abs(plain[1] - value) > 0:
        lines[plain[0]] = plain[4]
        r["plain_percentile"] = {"metric": plain[0], "value": plain[1], "unit": plain[2], "statistic": plain[3],
                                 "differs_by": (value - plain[1]) / plain[1]}
    if scenario == "SingleStream":
        r["latency_s"] = value
        r["latency_statistic"] = statistic
        qps = "QPS w/o loadgen overhead" if "QPS w/o loadgen overhead" in v else "QPS w/ loadgen overhead"
        r["throughput_per_s"] = num(qps)
        r["throughput_statistic"] = "queries per second (" + qps[4:] + ")"
    elif scenario == "MultiStream":
        if unit == "s":
            spq = num("samples_per_query")
            r["latency_s"] = value
            r["latency_statistic"] = statistic + " of %d samples" % int(spq)
            r["throughput_per_s"] = spq / value
            r["throughput_statistic"] = "samples per query / %s latency" % statistic
        else:  # v0.5: the number of streams that meet the latency bound
            r["streams"] = value
            r["latency_s"] = num("99.00 percentile latency (ns)") * 1e-9
            r["latency_statistic"] = "p99 per sample"
            r["throughput_per_s"] = value / (num("target_latency (ns)") * 1e-9)
            r["throughput_statistic"] = "streams / latency bound"
    else:
        r["throughput_per_s"] = value
        r["throughput_statistic"] = "samples per second"
    conditions = {}
    precision, field, text, ppath = precision_of(repo, entry)
    r["precision"] = precision or "not stated"
    if text:
        conditions["stated " + field.replace("_", " ")] = text
    if system.endswith("_MaxQ"):
        conditions["power setting"] = "MaxQ (energy-efficient configuration, system " + system + ")"
    for k in ("hw_notes", "cooling", "power_management", "host_processor_frequency", "accelerator_frequency"):
        val = str(sysj.get(k, "")).strip()
        if val and val != "-":
            conditions[k.replace("_", " ")] = val
    conditions["accelerator"] = str(sysj.get("accelerator_model_name", "")).strip() or "-"
    conditions["host processor"] = str(sysj.get("host_processor_model_name", "")).strip()
    r["conditions"] = conditions
    r["software"] = ", ".join(x for x in (str(sysj.get("framework", "")).strip(),
                                          str(sysj.get("operating_system", "")).strip()) if x)
    r["source"] = {"url": f"https://github.com/{repo}/blob/{commit}/{spath}", "repository": repo, "commit": commit,
                   "path": spath, "lines": lines, "kept": kept_name(repo, spath),
                   "system": system_json(sub, system), "licence": "Apache-2.0"}
    if ppath:
        r["source"]["precision_from"] = ppath
        r["source"]["precision_rule"] = field
    if power:
        watts, window_s, volts, pf = power_window(repo, entry, detail)
        if not watts:
            raise SystemExit(f"{spath}: no spl.txt sample inside LoadGen's power window")
        mean_w = sum(watts) / len(watts)
        spq = int(float(v["samples_per_query"][0])) if "samples_per_query" in v else 1
        pvalue, punit, pdef, plines = power_metric(rnd, scenario, mean_w, window_s, detail, spq)
        r["mean_power_w"] = mean_w
        r["power_samples"] = len(watts)
        r["power_samples_w"] = watts
        r["power_window_s"] = round(window_s, 3)
        r["power_metric"] = {"value": pvalue, "unit": punit, "definition": pdef, "checker": CHECKER[rnd][0],
                             "checker_where": CHECKER[rnd][1]}
        if punit == "W":  # Offline: an energy per sample is derived, not MLPerf's metric
            r["energy_per_sample_j"] = mean_w / r["throughput_per_s"]
            r["energy_statistic"] = "derived: mean power / samples per second (MLPerf's Offline metric is W)"
        else:
            per_query_j = pvalue / 1000 if punit == "mJ/query" else pvalue
            r["energy_per_sample_j"] = per_query_j / spq
            r["energy_statistic"] = "MLPerf's power metric" + (" / %d samples per query" % spq if spq > 1 else "")
        r["source"]["power_from"] = run_folder(entry) + "/spl.txt"
        r["source"]["detail"] = run_folder(entry) + "/mlperf_log_detail.txt"
        r["source"]["detail_lines"] = plines
        mean_v = sum(volts) / len(volts) if volts else None
        mean_pf = sum(pf) / len(pf) if pf else None
        r["power_kind"] = "AC wall"
        r["power_measurement"] = ("AC wall power of the whole system (SPEC PTDaemon meter at the mains plug%s%s), "
                                  "not a DC supply or module rail" % (
                                      ", %.0f V AC" % mean_v if mean_v else "",
                                      ", power factor %.2f" % mean_pf if mean_pf else ""))
    r["id"] = "-".join(["mlperf", rnd, system.lower(), r["network"], scenario.lower()])
    return r


def clpeak_results(path, computer, device):
    repo = "krrishnarraj/clpeak"
    commit = COMMITS[repo]
    out, section, best = [], None, {}
    units = {"GFLOPS": ("FLOP/s", 1e9), "GBPS": ("B/s", 1e9), "GIOPS": ("OP/s", 1e9)}
    log = use(repo, path)
    for no, line in enumerate(lines_of(log), 1):
        s = line.strip()
        m = re.match(r"^(.*\S)\s*\((GFLOPS|GBPS|GIOPS)\)\s*$", s)
        if m:
            section = (m.group(1), m.group(2))
            continue
        m = re.match(r"^(\w+)\s*:\s*([0-9.]+)\s*$", s)
        if m and section:
            val = float(m.group(2))
            if section not in best or val > best[section][0]:
                best[section] = (val, no, m.group(1))
        elif s and not m:
            section = section if s.startswith(("float", "double", "half", "int")) else None
    header = {}
    for no, line in enumerate(lines_of(log), 1):
        for key in ("Platform", "Device", "Driver version", "Compute units", "Clock frequency"):
            if line.strip().startswith(key) and ":" in line:
                header.setdefault(key, line.split(":", 1)[1].strip())
    wanted = {"Single-precision compute": "fp32", "Half-precision compute": "fp16",
              "Double-precision compute": "fp64", "Global memory bandwidth": None}
    peak = {name: val for (name, unit), (val, no, variant) in best.items()}
    for (name, unit), (val, no, variant) in sorted(best.items()):
        key = next((w for w in wanted if name.lower() == w.lower()), None)
        if key is None:
            continue
        u, scale = units[unit]
        r = {"kind": "clpeak", "computer": computer, "device": header.get("Device", device),
             "measure": key, "variant": variant, "precision": wanted[key] or "not applicable",
             "value": val * scale, "unit": u, "round": "clpeak results/old", "date": "",
             "conditions": {"backend": device + " via " + header.get("Platform", "OpenCL"),
                            "driver": header.get("Driver version", ""),
                            "compute units": header.get("Compute units", ""),
                            "clock": header.get("Clock frequency", "")},
             "software": "clpeak 1.x, " + header.get("Platform", ""),
             "source": {"url": f"https://github.com/{repo}/blob/{commit}/{path}", "repository": repo,
                        "commit": commit, "path": path, "lines": {key: no},
                        "kept": kept_name(repo, path), "licence": "Apache-2.0"},
             "id": "clpeak-" + computer + "-" + key.lower().replace(" ", "-")}
        # A half-precision peak at the single-precision rate on a GPU that runs FP16 twice as fast: the OpenCL
        # implementation (PoCL here) did not use the packed half path, so the figure is not the chip's FP16 peak.
        fp32 = peak.get("Single-precision compute")
        dev = header.get("Device", "")
        if key == "Half-precision compute" and fp32 and dev in DOUBLE_RATE_FP16 and val < 1.5 * fp32:
            r["flags"] = [{"code": "fp16_at_fp32_rate",
                           "reason": "half-precision %.2f GFLOPS is %.2fx the single-precision %.2f GFLOPS, but the "
                                     "%s runs FP16 at twice its FP32 rate (%s): the run through %s did not use "
                                     "packed half, so this is not the chip's FP16 peak" % (
                                         val, val / fp32, fp32, dev, DOUBLE_RATE_FP16[dev],
                                         header.get("Platform", "OpenCL"))}]
        out.append(r)
    return out


def hpl_results(kept_path, url, date, computer):
    out = []
    lines = lines_of(kept_issue(kept_path))
    params = {}
    for no, line in enumerate(lines, 1):
        m = re.match(r"^(N|NB|P|Q)\s*:\s*(\d+)", line)
        if m:
            params[m.group(1)] = m.group(2)
    for no, line in enumerate(lines, 1):
        for m in re.finditer(r"([0-9]+\.[0-9]+) Gflops at ([0-9.]+) ?W", line):
            tweak = "without NUMA/SDRAM tweaks" if "without" in line[:m.start()] else "as tuned in the thread"
            out.append({"kind": "hpl", "computer": computer, "device": "CPU (all cores)", "measure": "HPL (LINPACK)",
                        "precision": "fp64", "value": float(m.group(1)) * 1e9, "unit": "FLOP/s",
                        "mean_power_w": float(m.group(2)), "power_kind": "wall (not stated whether AC or DC)",
                        "power_measurement": "wall power as stated in the thread (meter not named)",
                        "round": "top500-benchmark", "date": date,
                        "conditions": {"HPL": "HPLinpack 2.3, N=%s NB=%s P=%s Q=%s" % (
                            params.get("N", "?"), params.get("NB", "?"), params.get("P", "?"),
                            params.get("Q", "?")), "tuning": tweak},
                        "software": "HPL 2.3 (geerlingguy/top500-benchmark)",
                        "source": {"url": url, "lines": {"result": no}, "kept": "sources/" + kept_path,
                                   "licence": "quoted result line"},
                        "id": "hpl-%s-%s-%d" % (computer, url.rsplit("/", 1)[1], len(out) + 1)})
    return out


def kept_issue(kept_path):
    for root in SOURCES:
        p = os.path.join(root, kept_path)
        if os.path.isfile(p) and os.path.getsize(p) > 0:
            USED.add(kept_path)
            return p
    raise SystemExit(f"{kept_path}: kept file missing or empty in {SOURCES}")


def trt_results(kept_path, url, date, computer, why):
    """A TensorRT timing report pasted in a thread: one run of one image. Kept as a note with its words, never a
    ranked result."""
    out = []
    lines = lines_of(kept_issue(kept_path))
    for no, line in enumerate(lines, 1):
        m = re.search(r"Network\s+CPU\s+([0-9.]+)ms\s+CUDA\s+([0-9.]+)ms", line)
        if m:
            lat = float(m.group(2)) * 1e-3
            out.append({"kind": "tensorrt-timing", "computer": computer, "network": "resnet50",
                        "scenario": "SingleStream", "precision": "not stated", "latency_s": lat,
                        "latency_statistic": "one timing of one image (first run)",
                        "throughput_per_s": 1.0 / lat, "throughput_statistic": "1 / one timing",
                        "runs": 1, "images": 1,
                        "not_ranked": "one run of one image is not a benchmark result: " + why,
                        "note": "the thread's words, line %d: \"%s\"" % (no, line.strip()),
                        "round": "jetson-inference issue", "date": date,
                        "conditions": {"harness": "jetson-inference imagenet-console, one 1920x1920 image",
                                       "model": "ResNet-50 caffemodel"},
                        "software": "TensorRT (JetPack, version not stated)",
                        "source": {"url": url, "lines": {"network CUDA time": no},
                                   "kept": "sources/" + kept_path, "licence": "quoted result line"},
                        "id": "trt-" + computer + "-resnet50-" + url.rsplit("/", 1)[1]})
    return out


# ROS 2 graph benchmarks: (file in new/ros2/, repository, commit, path there, computer the path or file names).
_R2B = "NVIDIA-ISAAC-ROS/ros2_benchmark"
_IRB = "NVIDIA-ISAAC-ROS/isaac_ros_benchmark"
_IRB_AT = "9741686b4c5390e2523e879c234f994077985547"
ROS2_BENCHMARK = [
    ("ros2bench_rectify_agx_orin_2023-05.json", _R2B,
     "18690995911e4da57e6f601b985189b03979040d", "results/image_proc_rectify_node-agx_orin.json", "jetson-agx-orin"),
    # Added for issue #51 (new/ros2/SOURCES.md): each file's own date and ROS 2 distribution say its release.
    ("ros2bench_rectify_agx_xavier_2023-05.json", _R2B, "7f77426830559e6070a51c324ec6264fbe2efb9a",
     "results/image_proc_rectify_node-agx_xavier.json", "jetson-agx-xavier"),
    ("ros2bench_rectify_orin_nx_2023-05.json", _R2B, "54d3000dbf919555c9e097256f697c20b7ad55b6",
     "results/image_proc_rectify_node-orin_nx.json", "jetson-orin-nx"),
    ("ros2bench_rectify_x86_rtx4090_2023-05.json", _R2B, "54d3000dbf919555c9e097256f697c20b7ad55b6",
     "results/image_proc_rectify_node-x86_4090.json", "x86-rtx4090"),
    ("ros2bench_stereo_disparity_orin_nano_2023-05.json", _R2B, "54d3000dbf919555c9e097256f697c20b7ad55b6",
     "results/stereo_image_proc_node-orin_nano.json", "jetson-orin-nano"),
    ("ros2bench_stereo_disparity_agx_orin_2023-05.json", _R2B, "54d3000dbf919555c9e097256f697c20b7ad55b6",
     "results/stereo_image_proc_node-agx_orin.json", "jetson-agx-orin"),
    ("ros2bench_stereo_disparity_orin_nx_2023-05.json", _R2B, "54d3000dbf919555c9e097256f697c20b7ad55b6",
     "results/stereo_image_proc_node-orin_nx.json", "jetson-orin-nx"),
    ("ros2bench_rectify_agx_thor_2025-10.json", _R2B, "999ed5e8c7da3f4f550829396d58d589f490e681",
     "results/image_proc_rectify_node-agx_thor.json", "jetson-agx-thor"),
    ("ros2bench_rectify_x86_rtx5090_2025-10.json", _R2B, "999ed5e8c7da3f4f550829396d58d589f490e681",
     "results/image_proc_rectify_node-x86-5090.json", "x86-rtx5090"),
    ("isaacbench_rectify_agx_thor_2026-02.json", _IRB, _IRB_AT, "results/image_proc_rectify_node-agx_thor.json",
     "jetson-agx-thor"),
    ("isaacbench_gpu_rectify_agx_thor_2026-02.json", _IRB, _IRB_AT, "results/isaac_ros_rectify_node-agx_thor.json",
     "jetson-agx-thor"),
    ("isaacbench_rectify_dgx_spark_2026-02.json", _IRB, _IRB_AT, "results/image_proc_rectify_node-dgx_spark.json",
     "nvidia-dgx-spark"),
    ("isaacbench_gpu_rectify_dgx_spark_2026-02.json", _IRB, _IRB_AT, "results/isaac_ros_rectify_node-dgx_spark.json",
     "nvidia-dgx-spark"),
    ("isaacbench_rectify_thor_t4000_2026-02.json", _IRB, _IRB_AT, "results/image_proc_rectify_node-thor-t4000.json",
     "jetson-thor-t4000"),
    ("isaacbench_gpu_rectify_thor_t4000_2026-02.json", _IRB, _IRB_AT,
     "results/isaac_ros_rectify_node-thor-t4000.json", "jetson-thor-t4000"),
    ("isaacbench_rectify_x86_rtx5090_2026-02.json", _IRB, _IRB_AT, "results/image_proc_rectify_node-x86-5090.json",
     "x86-rtx5090"),
    ("isaacbench_gpu_rectify_x86_rtx5090_2026-02.json", _IRB, _IRB_AT,
     "results/isaac_ros_rectify_node-x86-5090.json", "x86-rtx5090"),
]
# RobotPerf: (file in new/ros2/, repository, commit, path there, the boards its free-text "hardware" names). Only
# boards are taken; workstation CPUs ("Intel i7-8700K", "AMD Ryzen 5 PRO 4650G") name no one computer.
_RP_BOARDS = {"NVIDIA AGX Orin Dev. Kit": "jetson-agx-orin", "NVIDIA Jetson Nano": "jetson-nano",
              "Kria KV260": "amd-kria-kv260", "Kria KR260": "amd-kria-kr260"}
ROBOTPERF = [
    ("robotperf_c1_rrbot_joint_trajectory_controller_benchmark.yaml", "robotperf/benchmarks",
     "e603946568ac126c9b051865978ab58d05763e30",
     "benchmarks/control/c1_rrbot_joint_trajectory_controller/benchmark.yaml", _RP_BOARDS),
    # Added for issue #51 (new/ros2/SOURCES.md).
    ("robotperf_a2_rectify_benchmark.yaml", "robotperf/benchmarks", "6bcaa370f84afb7b3de20382a3e58ddc33b6df48",
     "benchmarks/perception/a2_rectify/benchmark.yaml", _RP_BOARDS),
    ("robotperf_a5_resize_benchmark.yaml", "robotperf/benchmarks", "6125a574a9e34cefc8fb3d4ba70f2512a1f07078",
     "benchmarks/perception/a5_resize/benchmark.yaml", _RP_BOARDS),
]
# What each value is (ros2_benchmark basic_performance_calculator.py; RobotPerf's notes).
ROS2_FIELDS = [
    ("BasicPerformanceMetrics.MEAN_FRAME_RATE", "frame rate", "1/s", 1,
     "received frames / received duration, mean of the kept runs"),
    ("BasicPerformanceMetrics.FIRST_SENT_RECEIVED_LATENCY", "first-message latency", "s", 1e-3,
     "the latency of the FIRST message only (mean of runs): not a latency distribution"),
    ("BasicPerformanceMetrics.MEAN_JITTER", "jitter ('mean')", "s", 1e-3,
     "the LARGEST of the runs' mean frame-to-frame jitters: a maximum, despite its name"),
    ("CPUProfilingMetrics.MEAN_CPU_UTIL", "CPU use", "%", 1, "mean CPU use, % of all cores"),
    # The 2024+ schema names the same CPU use ResourceMetrics.MEAN_OVERALL_CPU_UTILIZATION.
    ("ResourceMetrics.MEAN_OVERALL_CPU_UTILIZATION", "CPU use", "%", 1, "mean CPU use, % of all cores"),
]


def ros2_release(meta):
    """The release a ros2_benchmark result ran with, from the file's own facts: the month of TEST_DATETIME and the
    ROS 2 distribution of TEST_FILE_PATH (/opt/ros/<distro>/...). default_config_version is 0.30.0 in every release
    from 2023 to 2026, so it tells none apart (the same as importers/ros2/ros2_benchmark_json.cpp)."""
    parts = []
    date = meta.get("BenchmarkMetadata.TEST_DATETIME", "")
    if len(date) >= 7:
        parts.append("run " + date[:7])
    m = re.search(r"/opt/ros/([^/]+)/", meta.get("BenchmarkMetadata.TEST_FILE_PATH", ""))
    if m:
        parts.append("ROS 2 " + m.group(1))
    return ", ".join(parts)


def ros2_file(name):
    for root in ROS2:
        p = os.path.join(root, name)
        if os.path.isfile(p) and os.path.getsize(p) > 0:
            return p
    raise SystemExit(f"{name}: not in {ROS2} (give --ros2 DIR)")


def ros2_benchmark_results(name, repo, commit, path, computer):
    f = ros2_file(name)
    with open(f, encoding="utf-8") as fh:
        doc = json.load(fh)
    lines = lines_of(f)
    meta = doc["metadata"]
    bench = meta["BenchmarkMetadata.NAME"]
    config = meta.get("BenchmarkMetadata.CONFIG", "")
    m = re.search(r"default_config_version: (\S+)", config)
    tool = "isaac_ros_benchmark" if repo == _IRB else "ros2_benchmark"
    facts = ros2_release(meta)
    release = tool + " " + facts if facts else "not stated"
    inp = doc.get("custom", {}).get("data_resolution", "not stated")
    out = []
    runs = [("peak", doc, 0)] + [(k, v, None) for k, v in doc.items() if k.endswith("fps") and isinstance(v, dict)]
    for run, obj, _ in runs:
        # The line of each key: the first after the run's own key line ("10.0fps": {).
        # Some results are one line of JSON (the 2023 files at 54d3000): the line then holds every key.
        start = 0 if run == "peak" else next(i for i, l in enumerate(lines) if '"%s":' % run in l)
        for key, measure, unit, scale, meaning in ROS2_FIELDS:
            if key not in obj or (run != "peak" and measure != "CPU use"):
                continue
            no = next(i for i in range(start, len(lines)) if '"%s"' % key in lines[i]) + 1
            rate = "at peak throughput" if run == "peak" else "at " + run + " (one run at a fixed rate)"
            out.append({"kind": "ros2-benchmark", "computer": computer, "device": meta.get(
                "BenchmarkMetadata.DEVICE_ARCH", ""), "measure": "%s, %s" % (measure, rate),
                "benchmark": bench, "input": inp, "release": release, "statistic": meaning,
                "precision": "not applicable", "value": obj[key] * scale, "unit": unit,
                "round": "ros2_benchmark results", "date": meta.get("BenchmarkMetadata.TEST_DATETIME", "")[:10],
                "conditions": dict({"kernel": meta.get("BenchmarkMetadata.DEVICE_OS", ""),
                                    "computer named by": "the repository path " + path},
                                   **({"config version": m.group(1)} if m else {})),
                "software": "NVIDIA " + tool + " (" + release + ")",
                "source": {"url": f"https://github.com/{repo}/blob/{commit}/{path}", "repository": repo,
                           "commit": commit, "path": path, "lines": {key: no},
                           "kept": "../../new/ros2/" + name, "licence": "Apache-2.0"},
                "id": "%s-%s-%s-%s-%s" % ("isaacbench" if repo == _IRB else "ros2bench", computer, bench.split("::")[-1].split()[0].lower(),
                                                  measure.split()[0].strip("'(").lower(), run.replace(".0", ""))})
    return out


_RP_STAT = {"max": "the maximum of the run", "mean": "the mean of the run", "min": "the minimum of the run",
            "rms": "the root mean square of the run"}


def robotperf_statistic(value_text, note):
    """Which statistic of the run RobotPerf's value is: the one of its note ("mean_benchmark 30.2, ... max_benchmark
    36.46", "mean 5.41 ms, ... max 9.23 ms", "max_latency ...") whose number is the value to the digits both
    print. a2's and a5's throughputs are the maximum, c1's the mean; a note without numbers leaves it not stated.
    The same rule as importers/ros2/robotperf_yaml.cpp."""
    def decimals(t):
        return len(t.split(".", 1)[1]) if "." in t else 0
    v = float(value_text)
    for m in re.finditer(r"\b(mean|max|min|rms)(?:_benchmark|_latency)?\s+([0-9]+(?:\.[0-9]+)?)", note):
        x = m.group(2)
        if abs(float(x) - v) <= 0.5 * 10 ** -min(decimals(x), decimals(value_text)) + 1e-12:
            return "%s (RobotPerf's value; its note's %s)" % (_RP_STAT[m.group(1)], m.group(0).split()[0])
    return "not stated (RobotPerf's value; its note gives no statistic equal to it)"


def robotperf_results(name, repo, commit, path, computers):
    f = ros2_file(name)
    with open(f, encoding="utf-8") as fh:
        doc = yaml.safe_load(fh)
    lines = lines_of(f)
    out = []
    units = {"latency": ("s", 1e-3), "throughput": ("1/s", 1), "power": ("W", 1)}
    value_lines = [i + 1 for i, l in enumerate(lines) if l.strip().startswith("value:")]
    # The raw value text (the YAML reader drops "10.00"'s digits), for the statistic's comparison.
    value_texts = [lines[n - 1].split("value:", 1)[1].strip() for n in value_lines]
    # A "throughput" that is the same whole number on every machine of the file (c1's joint trajectory controller:
    # 10/s everywhere) is the rate the loop was configured to run at, not a throughput (the importer's rule).
    rates = {float(i["result"]["value"]) for i in doc["results"] if i["result"]["metric"] == "throughput"}
    configured = len(rates) == 1 and next(iter(rates)) > 0 and next(iter(rates)).is_integer() and len(
        {i["result"]["hardware"] for i in doc["results"]}) > 1
    seen = {}
    for k, item in enumerate(doc["results"]):
        r = item["result"]
        computer = computers.get(r["hardware"])
        if not computer:
            continue
        unit, scale = units[r["metric"]]
        value = float(r["value"])
        note = str(r.get("note", "")).strip()
        what = ("as RobotPerf reports it (the statistic is not stated)" if r["metric"] == "power"
                else robotperf_statistic(value_texts[k], note))
        box = {"grey": "grey-box", "black": "black-box"}.get(r.get("type", ""), "box type not stated")
        measure = r["metric"]
        if r["metric"] == "throughput" and configured:
            measure = "update rate as configured (not a throughput)"
        measure += ", " + box
        key = "robotperf-%s-%s-%s" % (computer, doc["id"], r["metric"])
        seen[key] = seen.get(key, 0) + 1
        conditions = {"hardware as written": r["hardware"] + " (free text)", "category": r.get("category", ""),
                      "box type": box + " (RobotPerf's type: %s)" % r.get("type", "not stated")}
        if note:
            conditions["RobotPerf's note"] = note
        entry = {"kind": "robotperf", "computer": computer, "device": r["hardware"], "measure": measure,
                 "benchmark": "%s %s" % (doc["id"], doc["name"]), "input": r.get("datasource", "not stated"),
                 "release": "not stated in the file", "statistic": what, "precision": "not applicable",
                 "value": value * scale, "unit": unit, "round": "RobotPerf benchmarks",
                 "date": str(r.get("timestampt", ""))[:10],
                 "conditions": conditions,
                 "software": "RobotPerf (ROS 2 release not stated in the file)",
                 "source": {"url": f"https://github.com/{repo}/blob/{commit}/{path}", "repository": repo,
                            "commit": commit, "path": path, "lines": {"value": value_lines[k]},
                            "kept": "../../new/ros2/" + name, "licence": "Apache-2.0"},
                 # The first result of a computer and metric keeps the short id; later ones say their line.
                 "id": key if seen[key] == 1 else "%s-line%d" % (key, value_lines[k])}
        flags = []
        if value <= 0 or (r["metric"] == "power" and value < 0.01):
            flags.append({"code": "impossible_value", "reason": "%s %s of %s is impossible%s" % (
                r["value"], r["metric_unit"], r["metric"],
                " (below 0.01 W, which no computer draws)" if value > 0 else "")})
        if measure.startswith("update rate as configured"):
            flags.append({"code": "configured_rate", "reason": "%s %s on every machine of the file: the rate the "
                          "loop was configured to run at, not a throughput" % (r["value"], r["metric_unit"])})
        if flags:
            entry["flags"] = flags
        if r["metric"] == "power":
            entry["power_kind"] = "not stated"
        out.append(entry)
    return out


def kept_not_used():
    """Every file under the kept folders that no result reads, with the reason."""
    out = []
    for root, dirpath, files in ((r, d, f) for r in SOURCES for d, _, f in os.walk(r)):
        for name in sorted(files):
            relp = os.path.relpath(os.path.join(dirpath, name), root).replace(os.sep, "/")
            if relp in USED or name in ("SOURCES.md", "README.md"):
                continue
            if relp in NOT_AT_COMMIT:
                out.append({"kept": "sources/" + relp, "why": NOT_AT_COMMIT[relp]})
            elif os.path.getsize(os.path.join(dirpath, name)) == 0:
                out.append({"kept": "sources/" + relp, "why": "empty: never read"})
            else:
                out.append({"kept": "sources/" + relp, "why": "not read by any result"})
    return sorted(out, key=lambda x: x["kept"])


def build():
    USED.clear()
    results = [mlperf_result(e) for e in MLPERF]
    for path, computer, device in CLPEAK:
        results += clpeak_results(path, computer, device)
    for args in HPL:
        results += hpl_results(*args)
    for args in TRT_REPORTS:
        results += trt_results(*args)
    for args in ROS2_BENCHMARK:
        results += ros2_benchmark_results(*args)
    for args in ROBOTPERF:
        results += robotperf_results(*args)
    ids = [r["id"] for r in results]
    dup = {i for i in ids if ids.count(i) > 1}
    if dup:
        raise SystemExit("duplicate ids: " + ", ".join(sorted(dup)))
    for r in results:
        r["origin"] = "published"
    used = {r["computer"] for r in results}
    return {
        "format": "benchscope-library", "version": 1,
        "about": "Published results of candidate robot computers, built by scripts/build-library.py from public "
                 "files kept outside the project (../shared/public-data/resources/library/sources/; each result "
                 "names its URL, commit, file and line). Origin: published. SI units: latency_s in s, "
                 "throughput_per_s in 1/s, value in FLOP/s or B/s, mean_power_w in W, energy_per_sample_j in J; "
                 "official and power_metric carry the unit MLPerf's checker gives them.",
        "computers": [dict({"id": c, "name": n, "aliases": a}, **({"stand_in": s} if s else {}))
                      for c, n, a, s in COMPUTERS if c in used],
        "results": results,
        "kept_not_used": kept_not_used(),
    }


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--fetch", metavar="MIRROR_ROOT")
    ap.add_argument("--sources", metavar="DIR", action="append",
                    help="a folder of kept files (repeatable; default %s)" % DEFAULT_SOURCES)
    ap.add_argument("--ros2", metavar="DIR", action="append",
                    help="a folder of ROS 2 benchmark results (default %s)" % DEFAULT_ROS2)
    ap.add_argument("--check", action="store_true")
    a = ap.parse_args()
    SOURCES[:] = [os.path.abspath(s) for s in a.sources] if a.sources else [DEFAULT_SOURCES]
    ROS2[:] = [os.path.abspath(s) for s in a.ros2] if a.ros2 else [DEFAULT_ROS2]
    if not os.path.isdir(SOURCES[0]) and not a.fetch:
        sys.exit(SOURCES[0] + ": no kept sources here (give --sources DIR)")
    if a.fetch:
        fetch(a.fetch)
    lib = build()
    text = json.dumps(lib, indent=1, ensure_ascii=False, sort_keys=False) + "\n"
    out = os.path.join(LIB, "library.json")
    if a.check:
        with open(out, encoding="utf-8") as f:
            if f.read() != text:
                sys.exit(out + " differs from what scripts/build-library.py builds from the sources")
        return
    with open(out, "w", encoding="utf-8") as f:
        f.write(text)
    print("%s: %d results for %d computers" % (out, len(lib["results"]), len(lib["computers"])))
    for k in lib["kept_not_used"]:
        print("kept but not read: %s (%s)" % (k["kept"], k["why"]))


if __name__ == "__main__":
    main()
