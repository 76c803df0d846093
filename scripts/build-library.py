#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Builds resources/library/library.json, BenchScope's library of published results, from public files kept under
resources/library/sources/ (never from numbers typed by hand: every value names the file and line it comes from).
The kept files are third-party, so they are not in the project: they lie at that path in the shared folder of
third-party files, BENCHSCOPE_PUBLIC_DATA_DIR (default ../shared/public-data beside the source tree, as in CMake;
--public-data DIR names another). library.json's "kept" fields stay relative to resources/library/ of that folder.

  scripts/build-library.py --fetch MIRROR_ROOT   copy the listed files out of local git mirrors of the public
                                                 repositories (MIRROR_ROOT/<owner>+<name>/repo, as the project's
                                                 fetch tool leaves them) into resources/library/sources/ of the
                                                 shared folder
  scripts/build-library.py                       build library.json from the kept sources
  scripts/build-library.py --check               fail when library.json differs from what the sources give

Sources:
  - MLPerf Inference results (mlcommons/inference_results_v0.5 ... v3.0, Apache-2.0): each result's
    mlperf_log_summary.txt, the system description systems/<system>.json, the measurements JSON (precision) and,
    for power submissions, mlperf_log_detail.txt (power window, query count) and spl.txt (the PTDaemon log). The
    mean power is the mean of spl.txt's Watts samples inside LoadGen's power window, as the importer computes it.
  - clpeak's published result logs (krrishnarraj/clpeak results/old/, Apache-2.0): the peak of each section is the
    highest value over vector widths, as BenchScope's clpeak importer takes it.
  - Result lines pasted in public issue threads (HPL on Raspberry Pi boards, a TensorRT timing report on a TX2),
    kept as their relevant lines with the thread's URL (sources/issues/).
"""
import argparse
import json
import os
import re
import subprocess
import sys
from datetime import datetime

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
LIB = os.path.join(ROOT, "resources", "library")


def kept_sources(public_data):
    """resources/library/sources/ of a shared folder of third-party files."""
    return os.path.join(public_data, "resources", "library", "sources")


SRC = kept_sources(os.environ.get("BENCHSCOPE_PUBLIC_DATA_DIR") or os.path.join(ROOT, "..", "shared", "public-data"))

# The computers, and how a user may name them (benchscope-cli platforms --library orin,pi5).
COMPUTERS = [
    ("jetson-agx-orin", "NVIDIA Jetson AGX Orin", ["orin", "agx-orin"]),
    ("jetson-orin-nx", "NVIDIA Jetson Orin NX", ["orin-nx"]),
    ("jetson-agx-xavier", "NVIDIA Jetson AGX Xavier", ["xavier", "agx-xavier"]),
    ("jetson-xavier-nx", "NVIDIA Jetson Xavier NX", ["xavier-nx"]),
    ("jetson-tx2", "NVIDIA Jetson TX2", ["tx2"]),
    ("jetson-nano", "NVIDIA Jetson Nano", ["nano"]),
    ("raspberry-pi-4", "Raspberry Pi 4 Model B", ["pi4", "rpi4"]),
    ("raspberry-pi-cm4", "Raspberry Pi Compute Module 4", ["cm4"]),
    ("raspberry-pi-5", "Raspberry Pi 5 Model B", ["pi5", "rpi5"]),
    ("intel-icl-i3-1005g1", "Intel Core i3-1005G1 (Ice Lake U, NUC-class)", ["icl", "i3-1005g1", "nuc-icl"]),
    ("intel-uhd-620", "Intel UHD Graphics 620 (Kaby Lake R U-series iGPU, NUC-class)", ["uhd620"]),
]

COMMITS = {
    "mlcommons/inference_results_v0.5": "f5acb8be3da3ebc13cf6ba783cce371f96d275ac",
    "mlcommons/inference_results_v1.1": "7fc43356c4d71ed6ec97af9d035a34ed146587b8",
    "mlcommons/inference_results_v3.0": "1948f9b5b93c5b4dcafe15de0faa08cdf1439fca",
    "krrishnarraj/clpeak": "18c668f1c940663e62eed5bcc3e460ac541ea4b1",
}
ROUND_DATES = {"v0.5": "2019-11", "v1.1": "2021-09", "v3.0": "2023-04"}  # publication month of each round

# MLPerf results: (round, submitter folder, system folder, network folder, scenario folder, computer, power run).
MLPERF = []
for scen in ("SingleStream", "MultiStream", "Offline"):
    for net in ("resnet50", "retinanet"):
        MLPERF.append(("v3.0", "closed/NVIDIA", "Orin_TRT", net, scen, "jetson-agx-orin", False))
        MLPERF.append(("v3.0", "closed/NVIDIA", "Orin_NX_TRT", net, scen, "jetson-orin-nx", False))
    MLPERF.append(("v3.0", "closed/NVIDIA", "Orin_TRT_MaxQ", "resnet50", scen, "jetson-agx-orin", True))
for scen in ("SingleStream", "Offline"):
    for net in ("resnet50", "ssd-mobilenet"):
        MLPERF.append(("v1.1", "closed/NVIDIA", "AGX_Xavier_TRT", net, scen, "jetson-agx-xavier", False))
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

# clpeak logs: (path in krrishnarraj/clpeak at COMMITS, computer, device note).
CLPEAK = [
    ("results/old/Intel_Graphics_Compute_Runtime/Intel_UHD_Graphics_620.log", "intel-uhd-620", "GPU"),
    # "Device: NVIDIA Tegra X1" at 921 MHz: the Maxwell GPU through PoCL's CUDA driver ("Note via POCL 1.3").
    ("results/old/Portable_Computing_Language/Jetson_Nano_Tegra_X1.txt", "jetson-nano", "GPU (PoCL CUDA)"),
]

# Lines pasted in issue threads: (kept file, URL, date, computer).
HPL = [
    ("issues/geerlingguy+top500-benchmark+18.txt", "https://github.com/geerlingguy/top500-benchmark/issues/18",
     "2023-09-28", "raspberry-pi-5"),
    ("issues/geerlingguy+top500-benchmark+51.txt", "https://github.com/geerlingguy/top500-benchmark/issues/51",
     "2025-01-09", "raspberry-pi-5"),
    ("issues/geerlingguy+top500-benchmark+33.txt", "https://github.com/geerlingguy/top500-benchmark/issues/33",
     "2024-05-21", "raspberry-pi-cm4"),
]
TRT_REPORTS = [
    ("issues/dusty-nv+jetson-inference+388.txt", "https://github.com/dusty-nv/jetson-inference/issues/388",
     "2019-08-15", "jetson-tx2"),
]


def repo_of(rnd):
    return "mlcommons/inference_results_" + rnd


# System descriptions whose file name differs from the results folder's (v0.5 Intel).
SYSTEM_FILES = {"ICL-I3-1005G1_OpenVINO-Windows": "ICL-i31005G1_openvino"}


def system_json(sub, system):
    return f"{sub}/systems/{SYSTEM_FILES.get(system, system)}.json"


def mlperf_paths(entry):
    rnd, sub, system, net, scen, _, power = entry
    run = f"{sub}/results/{system}/{net}/{scen}/performance/run_1"
    paths = [f"{run}/mlperf_log_summary.txt", system_json(sub, system)]
    if power:
        paths += [f"{run}/mlperf_log_detail.txt", f"{run}/spl.txt"]
    return paths


def kept(repo, path):
    return os.path.join(SRC, repo.replace("/", "+"), path)


def git_show(mirror, commit, path):
    return subprocess.run(["git", "-C", mirror, "show", f"{commit}:{path}"], check=True,
                          capture_output=True).stdout


def git_ls(mirror, commit, folder):
    out = subprocess.run(["git", "-C", mirror, "ls-tree", "--name-only", f"{commit}:{folder}"],
                         capture_output=True, text=True)
    return out.stdout.split() if out.returncode == 0 else []


def fetch(mirror_root):
    for entry in MLPERF:
        repo = repo_of(entry[0])
        mirror = os.path.join(mirror_root, repo.replace("/", "+"), "repo")
        rnd, sub, system, net, scen, _, _ = entry
        paths = mlperf_paths(entry)
        mfolder = f"{sub}/measurements/{system}/{net}/{scen}"
        paths += [f"{mfolder}/{n}" for n in git_ls(mirror, COMMITS[repo], mfolder)
                  if n.endswith(".json") and n != "config.json"][:1]
        for p in paths:
            out = kept(repo, p)
            os.makedirs(os.path.dirname(out), exist_ok=True)
            with open(out, "wb") as f:
                f.write(git_show(mirror, COMMITS[repo], p))
    mirror = os.path.join(mirror_root, "krrishnarraj+clpeak", "repo")
    for path, _, _ in CLPEAK:
        out = kept("krrishnarraj/clpeak", path)
        os.makedirs(os.path.dirname(out), exist_ok=True)
        with open(out, "wb") as f:
            f.write(git_show(mirror, COMMITS["krrishnarraj/clpeak"], path))


def lines_of(path):
    with open(path, encoding="utf-8", errors="replace") as f:
        return f.read().splitlines()


def summary_values(path):
    """Key -> (value text, line number) for the 'Key : Value' lines of a LoadGen summary (first occurrence, per-sample
    block for v0.5's MultiStream, whose per-query block comes first)."""
    values, per_query = {}, False
    for no, line in enumerate(lines_of(path), 1):
        s = line.strip()
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


def precision_of(repo, entry):
    rnd, sub, system, net, scen, _, _ = entry
    folder = kept(repo, f"{sub}/measurements/{system}/{net}/{scen}")
    if not os.path.isdir(folder):
        return None, None
    for name in sorted(os.listdir(folder)):
        if name.endswith(".json"):
            with open(os.path.join(folder, name)) as f:
                j = json.load(f)
            w = str(j.get("weight_data_types", "")).strip()
            if w:
                return w, f"{sub}/measurements/{system}/{net}/{scen}/{name}"
    return None, None


def ptd_epoch(text):
    return datetime.strptime(text, "%m-%d-%Y %H:%M:%S.%f").timestamp()


def power_window(repo, entry):
    """Mean Watts of spl.txt inside LoadGen's power window, the window length and the query count."""
    run = os.path.dirname(kept(repo, mlperf_paths(entry)[0]))
    detail = {}
    for line in lines_of(os.path.join(run, "mlperf_log_detail.txt")):
        if not line.startswith(":::MLLOG "):
            continue
        for key in ("power_begin", "power_end", "result_query_count"):
            if line.startswith(':::MLLOG {"key": "%s"' % key):
                detail[key] = json.loads(line[len(":::MLLOG "):])["value"]
    if "power_begin" not in detail:
        return None
    b, e = ptd_epoch(detail["power_begin"]), ptd_epoch(detail["power_end"])
    watts = []
    for line in lines_of(os.path.join(run, "spl.txt")):
        f = line.split(",")
        if len(f) > 3 and f[0] == "Time":
            t = ptd_epoch(f[1])
            if b <= t <= e and float(f[3]) >= 0:
                watts.append(float(f[3]))
    if not watts:
        return None
    return sum(watts) / len(watts), e - b, len(watts), detail.get("result_query_count")


def mlperf_result(entry):
    rnd, sub, system, net, scen, computer, power = entry
    repo = repo_of(rnd)
    commit = COMMITS[repo]
    spath = mlperf_paths(entry)[0]
    v = summary_values(kept(repo, spath))
    with open(kept(repo, system_json(sub, system))) as f:
        sysj = json.load(f)
    scenario = v["Scenario"][0].replace(" ", "")
    if v["Result is"][0] != "VALID":
        raise SystemExit(f"{spath}: not a VALID result")
    lines = {}

    def num(key):
        text, no = v[key]
        lines[key] = no
        return float(text)

    r = {"kind": "mlperf-inference", "computer": computer, "network": NETWORK_NAMES.get(net, net),
         "scenario": scenario, "round": rnd, "date": ROUND_DATES[rnd], "division": sub.split("/")[0],
         "submitter": sysj.get("submitter", ""), "system": sysj.get("system_name", system),
         "validity": "VALID"}
    if scenario == "SingleStream":
        key = "90th percentile latency (ns)" if "90th percentile latency (ns)" in v else "90.00 percentile latency (ns)"
        r["latency_s"] = num(key) * 1e-9
        r["latency_statistic"] = "p90"
        qps = "QPS w/o loadgen overhead" if "QPS w/o loadgen overhead" in v else "QPS w/ loadgen overhead"
        r["throughput_per_s"] = num(qps) if qps in v else 1.0 / r["latency_s"]
        r["throughput_statistic"] = "queries per second" if qps in v else "1 / p90 latency"
    elif scenario == "MultiStream":
        if "99th percentile latency (ns)" in v:
            r["latency_s"] = num("99th percentile latency (ns)") * 1e-9
            r["latency_statistic"] = "p99 per query of %d samples" % int(num("samples_per_query"))
            r["throughput_per_s"] = num("samples_per_query") / r["latency_s"]
            r["throughput_statistic"] = "samples per query / p99 latency"
        else:  # v0.5: the number of streams that meet the latency bound
            r["streams"] = num("Samples per query")
            r["latency_s"] = num("99.00 percentile latency (ns)") * 1e-9
            r["latency_statistic"] = "p99 per sample"
            r["throughput_per_s"] = r["streams"] / (num("target_latency (ns)") * 1e-9)
            r["throughput_statistic"] = "streams / latency bound"
    else:
        r["throughput_per_s"] = num("Samples per second")
        r["throughput_statistic"] = "samples per second"
    conditions = {}
    precision, ppath = precision_of(repo, entry)
    # A data type by name ("int8", "fp16", "fp32"); other text ("No change.") is kept as a condition.
    if precision and re.fullmatch(r"(int|fp|uint|bf)\d+", precision.lower()):
        r["precision"] = precision.lower()
    else:
        r["precision"] = "not stated"
        if precision:
            conditions["stated weight data types"] = precision
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
                   "path": spath, "lines": lines, "kept": os.path.relpath(kept(repo, spath), os.path.dirname(SRC)),
                   "system": system_json(sub, system), "licence": "Apache-2.0"}
    if ppath:
        r["source"]["precision_from"] = ppath
    if power:
        pw = power_window(repo, entry)
        if pw:
            mean_w, window_s, n, queries = pw
            r["mean_power_w"] = mean_w
            r["power_samples"] = n
            spq = float(v["samples_per_query"][0]) if "samples_per_query" in v else 1.0
            if queries:
                r["energy_per_sample_j"] = mean_w * window_s / queries / spq
            elif "Samples per second" in v:
                r["energy_per_sample_j"] = mean_w / float(v["Samples per second"][0])
            elif "QPS w/o loadgen overhead" in v:  # no query count in the detail log (v1.1): mean power / rate
                r["energy_per_sample_j"] = mean_w / float(v["QPS w/o loadgen overhead"][0]) / spq
            r["source"]["power_from"] = spath.replace("mlperf_log_summary.txt", "spl.txt") + \
                " (Watts inside mlperf_log_detail.txt's power_begin .. power_end)"
            r["power_measurement"] = "external meter (SPEC PTDaemon), wall power of the system"
    r["id"] = "-".join(["mlperf", rnd, system.lower(), r["network"], scenario.lower()])
    return r


def clpeak_results(path, computer, device):
    repo = "krrishnarraj/clpeak"
    commit = COMMITS[repo]
    out, section, best = [], None, {}
    units = {"GFLOPS": ("FLOP/s", 1e9), "GBPS": ("B/s", 1e9), "GIOPS": ("OP/s", 1e9)}
    for no, line in enumerate(lines_of(kept(repo, path)), 1):
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
    for no, line in enumerate(lines_of(kept(repo, path)), 1):
        for key in ("Platform", "Device", "Driver version", "Compute units", "Clock frequency"):
            if line.strip().startswith(key) and ":" in line:
                header.setdefault(key, line.split(":", 1)[1].strip())
    wanted = {"Single-precision compute": "fp32", "Half-precision compute": "fp16",
              "Double-precision compute": "fp64", "Global memory bandwidth": None}
    for (name, unit), (val, no, variant) in sorted(best.items()):
        key = next((w for w in wanted if name.lower() == w.lower()), None)
        if key is None:
            continue
        u, scale = units[unit]
        out.append({"kind": "clpeak", "computer": computer, "device": header.get("Device", device),
                    "measure": key, "variant": variant, "precision": wanted[key] or "not applicable",
                    "value": val * scale, "unit": u, "round": "clpeak results/old", "date": "",
                    "conditions": {"backend": device + " via " + header.get("Platform", "OpenCL"),
                                   "driver": header.get("Driver version", ""),
                                   "compute units": header.get("Compute units", ""),
                                   "clock": header.get("Clock frequency", "")},
                    "software": "clpeak 1.x, " + header.get("Platform", ""),
                    "source": {"url": f"https://github.com/{repo}/blob/{commit}/{path}", "repository": repo,
                               "commit": commit, "path": path, "lines": {key: no},
                               "kept": os.path.relpath(kept(repo, path), os.path.dirname(SRC)), "licence": "Apache-2.0"},
                    "id": "clpeak-" + computer + "-" + key.lower().replace(" ", "-")})
    return out


def hpl_results(kept_path, url, date, computer):
    out = []
    lines = lines_of(os.path.join(SRC, kept_path))
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
                        "mean_power_w": float(m.group(2)),
                        "power_measurement": "wall power as stated in the thread (meter not named)",
                        "round": "top500-benchmark", "date": date,
                        "conditions": {"HPL": "HPLinpack 2.3, N=%s NB=%s P=%s Q=%s" % (
                            params.get("N", "?"), params.get("NB", "?"), params.get("P", "?"),
                            params.get("Q", "?")), "tuning": tweak},
                        "software": "HPL 2.3 (geerlingguy/top500-benchmark)",
                        "source": {"url": url, "lines": {"result": no}, "kept": os.path.join("sources", kept_path),
                                   "licence": "quoted result line"},
                        "id": "hpl-%s-%s-%d" % (computer, url.rsplit("/", 1)[1], len(out) + 1)})
    return out


def trt_results(kept_path, url, date, computer):
    out = []
    lines = lines_of(os.path.join(SRC, kept_path))
    for no, line in enumerate(lines, 1):
        m = re.search(r"Network\s+CPU\s+([0-9.]+)ms\s+CUDA\s+([0-9.]+)ms", line)
        if m:
            lat = float(m.group(2)) * 1e-3
            out.append({"kind": "tensorrt-timing", "computer": computer, "network": "resnet50",
                        "scenario": "SingleStream", "precision": "not stated", "latency_s": lat,
                        "latency_statistic": "one image (single timing report)", "throughput_per_s": 1.0 / lat,
                        "throughput_statistic": "1 / latency", "round": "jetson-inference issue", "date": date,
                        "conditions": {"harness": "jetson-inference imagenet-console, one 1920x1920 image",
                                       "model": "ResNet-50 caffemodel"},
                        "software": "TensorRT (JetPack, version not stated)",
                        "source": {"url": url, "lines": {"network CUDA time": no},
                                   "kept": os.path.join("sources", kept_path), "licence": "quoted result line"},
                        "id": "trt-" + computer + "-resnet50-" + url.rsplit("/", 1)[1]})
    return out


def build():
    results = [mlperf_result(e) for e in MLPERF]
    for path, computer, device in CLPEAK:
        results += clpeak_results(path, computer, device)
    for args in HPL:
        results += hpl_results(*args)
    for args in TRT_REPORTS:
        results += trt_results(*args)
    ids = [r["id"] for r in results]
    dup = {i for i in ids if ids.count(i) > 1}
    if dup:
        raise SystemExit("duplicate ids: " + ", ".join(sorted(dup)))
    for r in results:
        r["origin"] = "published"
    used = {r["computer"] for r in results}
    return {
        "format": "benchscope-library", "version": 1,
        "about": "Published results of candidate robot computers, built by scripts/build-library.py from the public "
                 "files kept under resources/library/sources/ (each result names its URL, commit, file and line). "
                 "Origin: published. SI units: latency_s in s, throughput_per_s in 1/s, value in FLOP/s or B/s, "
                 "mean_power_w in W, energy_per_sample_j in J.",
        "computers": [{"id": c, "name": n, "aliases": a} for c, n, a in COMPUTERS if c in used],
        "results": results,
    }


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--fetch", metavar="MIRROR_ROOT")
    ap.add_argument("--check", action="store_true")
    ap.add_argument("--public-data", metavar="DIR",
                    help="the shared folder of third-party files (default: $BENCHSCOPE_PUBLIC_DATA_DIR, else "
                         "../shared/public-data beside the source tree)")
    a = ap.parse_args()
    global SRC
    if a.public_data:
        SRC = kept_sources(a.public_data)
    if a.fetch:
        fetch(a.fetch)
    if not os.path.isdir(SRC):
        sys.exit("scripts/build-library.py: no kept sources at " + SRC + ": they are third-party files of the shared "
                 "folder (docs/third-party-data.md); set BENCHSCOPE_PUBLIC_DATA_DIR or pass --public-data DIR")
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


if __name__ == "__main__":
    main()
