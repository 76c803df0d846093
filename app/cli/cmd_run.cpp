// SPDX-License-Identifier: GPL-3.0-or-later
// benchscope-cli run flops: measure the paper's kernel on this machine and write run JSON v1.
#include <iomanip>
#include <iostream>

#include "analysis/flops.h"
#include "analysis/units.h"
#include "args.h"
#include "command.h"
#include "kernels/sweep.h"
#include "kernels/worker_spec.h"
#include "run_json.h"
#include "signals.h"
#include "store/workspace.h"

namespace bs::cli {

int run_bandwidth(const std::vector<std::string>& raw, std::ostream& out, std::ostream& err);  // cmd_run_bandwidth.cpp

namespace {

int run_flops(const std::vector<std::string>& raw, std::ostream& out, std::ostream& err) {
  if (!raw.empty() && raw[0] == "bandwidth") return run_bandwidth(raw, out, err);
  const ParsedArgs args = parse_args(raw, {"--json", "--no-warmup", "--quiet"},
                                     {"--backend", "--points", "--iterations", "--workers", "--repeats", "--out",
                                      "--workspace", "--variant", "--device"});
  if (args.positional.size() != 1 || args.positional[0] != "flops")
    throw UsageError("expected 'run flops'");
  kernels::SweepSpec spec;
  try {
    spec.workers = kernels::parse_worker_spec(args.value("--workers").value_or("1,2,4,8,16,32,64,128,256"));
    spec.dims = kernels::parse_dims_list(args.value("--points").value_or("4"));
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--workers/--points: ") + e.what());
  }
  const double n = args.number("--iterations", 40000);
  const double repeats = args.number("--repeats", 3);
  if (n < 1 || n > 1e12 || n != static_cast<double>(static_cast<std::int64_t>(n)))
    throw UsageError("--iterations must be a whole number >= 1");
  if (repeats < 1 || repeats > 1000) throw UsageError("--repeats must be between 1 and 1000");
  spec.iterations = static_cast<std::int64_t>(n);
  spec.repeats = static_cast<int>(repeats);
  spec.warmup = !args.has("--no-warmup");
  const std::string variant = args.value("--variant").value_or("throughput");
  // The throughput variant's per-backend labels (float16x4, float4x4) are accepted as its names too.
  if (variant != "paper" && variant != "throughput" && variant != "float16x4" && variant != "float4x4")
    throw UsageError("--variant must be paper or throughput");
  spec.variant = variant == "paper" ? kernels::Variant::Paper : kernels::Variant::Throughput;

  const kernels::CpuInfo cpu = kernels::detect_cpu();
  const auto backends = kernels::available_backends(cpu);
  std::string backend_id = args.value("--backend").value_or("cpu");
  if (const auto device = args.value("--device")) backend_id += ":" + *device;  // --backend opencl --device 1
  const kernels::Backend* found = nullptr;
  try {
    found = &kernels::find_backend(backends, backend_id);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  const kernels::Backend& backend = *found;
  if (!args.has("--quiet"))
    err << "benchscope-cli: " << backend.label << " on " << backend.device_name << " (" << backend.details
        << "), theoretical peak " << format_si(backend.theoretical_peak_flops, "FLOPS") << '\n';
  const bool quiet = args.has("--quiet");
  kernels::SweepResult result;
  try {
    result = kernels::run_sweep(
        backend, cpu, spec, interrupt_token(),
        [&](double f, std::string_view step) {
          if (!quiet) err << "\r" << std::setw(5) << std::fixed << std::setprecision(1) << f * 100 << " % " << step
                          << "          " << std::flush;
        });
  } catch (const std::invalid_argument& e) {  // sizes or D the backend refuses before running anything
    throw UsageError(e.what());
  }
  if (!quiet) err << '\n';
  if (result.cancelled) err << "benchscope-cli: cancelled; keeping the " << result.runs.size() << " partial run(s)\n";

  if (result.runs.empty()) {
    err << "benchscope-cli: error: no point completed; nothing written\n";
    return 1;
  }
  if (const auto path = args.value("--out")) {
    save_run_json(*path, result.runs);
    if (!quiet) err << "benchscope-cli: wrote " << *path << '\n';
  }
  if (const auto ws_path = args.value("--workspace")) {
    ImportBatch batch;
    batch.source_path = "benchscope-cli run flops";
    batch.format = "benchscope-run-v1";
    batch.runs = result.runs;
    Workspace ws(*ws_path);
    ws.add_import(batch, content_hash(write_run_json(result.runs)));
    if (!quiet) err << "benchscope-cli: stored " << result.runs.size() << " run(s) in " << *ws_path << '\n';
  }
  if (args.has("--json")) {
    out << write_run_json(result.runs);
  } else {
    for (const PeakRow& row : peak_table(result.runs)) {
      out << row.backend << ", D = " << row.dims << ": peak " << format_si(row.peak.flops, "FLOPS") << " \xC2\xB1 "
          << format_si(row.peak.at_peak.sd, "FLOPS") << " (n = " << row.peak.at_peak.n << ") at W = "
          << row.peak.workers;
      if (row.fraction_of_theoretical)
        out << ", " << std::setprecision(1) << std::fixed << *row.fraction_of_theoretical * 100 << " % of "
            << format_si(*row.theoretical_flops, "FLOPS") << " theoretical";
      out << " [variant " << row.variant << "]\n";
    }
  }
  return result.cancelled ? 1 : 0;
}

const CommandRegistrar registrar({
    "run",
    "measure the paper's rotation kernel (FLOPS sweep) or memory bandwidth on this machine",
    "usage: benchscope-cli run flops [--backend cpu|cpu-simd|cpu-scalar|opencl|cuda [--device N]]\n"
    "         [--variant throughput|paper]\n"
    "         [--points 1,2,4] [--iterations N] [--workers SPEC] [--repeats R] [--no-warmup]\n"
    "         [--out run.json] [--workspace W.bsw] [--json] [--quiet]\n"
    "  SPEC: 256:1024000:256 (start:stop:step), 1,2,4,8, or mixes such as 1,2,4:64:4.\n"
    "  paper: the paper's kernel (OpenMP task / work-item / thread per worker; OpenCL and CUDA: float, float2,\n"
    "  float4 for D = 1, 2, 4). throughput: enough independent vector chains per thread to reach the FMA pipes'\n"
    "  peak (CPU: all W*D points packed into vectors; OpenCL: float16x4; CUDA: float4x4).\n"
    "  Every output is checked against the closed form D*(cos 2N + sin 2N). Ctrl+C keeps the completed points.\n"
    "usage: benchscope-cli run bandwidth [--backend cpu|cpu-scalar|opencl [--device N]] [--mib 128]\n"
    "         [--repeats 10] [--workspace W.bsw] [--json] [--quiet]\n"
    "  STREAM triad a = b + q c over three float arrays of --mib MiB (12 bytes per element), mean ± SD of the\n"
    "  repetitions in GB/s: the memory ceiling of the roofline. --workspace stores it as a result set.",
    [](const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
      return run_flops(args, out, err);
    },
});

}  // namespace
}  // namespace bs::cli
