// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A per-host cache of measured empirical ceilings, so `devices` and the GUI's Kernel Runner show them without
// measuring on every start (`bench kernels` always measures afresh and updates the cache). One JSON file,
// $BENCHSCOPE_CACHE_DIR/ceilings.json, else $XDG_CACHE_HOME/benchscope/ceilings.json, else
// ~/.cache/benchscope/ceilings.json; one entry per (host, CPU model, ISA, threads), each with its date and how it
// was measured; a GPU's or OpenCL device's entry is keyed by (host, device name, "cuda"/"opencl", 0). A ceiling
// measured on other hardware or another thread count is never shown for this one.
#include <optional>
#include <string>
#include <vector>

#include "kernels/backends/backend.h"
#include "kernels/ceilings/ceilings.h"

namespace bs::kernels {

std::string ceiling_cache_path();

// Every entry of the file; empty when it does not exist. std::runtime_error naming the file, the entry and the
// field when it is unreadable.
std::vector<CeilingSet> load_ceiling_cache(const std::string& path);

// The entry for this host, CPU model, ISA and thread count, if any. A damaged file counts as no entry.
std::optional<CeilingSet> cached_ceilings(const CpuInfo& cpu, const std::string& path = ceiling_cache_path());

// The entry for this host and a device backend's device (OpenCL, CUDA: keyed by device name and "cuda"/"opencl",
// threads 0), if any; none for a backend without ceiling kernels.
std::optional<CeilingSet> cached_device_ceilings(const Backend& backend,
                                                 const std::string& path = ceiling_cache_path());

// Replaces (or adds) the entry of `set`'s host, CPU model, ISA and threads; creates the folder. Throws
// std::runtime_error naming the file when it cannot be written.
void store_ceilings(const CeilingSet& set, const std::string& path = ceiling_cache_path());

}  // namespace bs::kernels
