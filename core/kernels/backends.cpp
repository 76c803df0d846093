// SPDX-License-Identifier: GPL-3.0-or-later
#include <stdexcept>

#include "kernels/backend.h"
#include "kernels/backend_opencl.h"

namespace bs::kernels {

std::vector<Backend> available_backends(const CpuInfo& cpu) {
  std::vector<Backend> all = cpu_backends(cpu);
  for (Backend& b : opencl_backends(cpu)) all.push_back(std::move(b));
  return all;
}

const Backend& find_backend(const std::vector<Backend>& backends, const std::string& id) {
  const std::string wanted = id == "cpu" ? "cpu-simd" : id == "opencl" ? "opencl:0" : id;
  for (const Backend& b : backends)
    if (b.id == wanted) return b;
  std::string known;
  for (const Backend& b : backends) known += " " + b.id;
  throw std::invalid_argument("no backend '" + id + "' on this machine (available:" + known +
                              "; CUDA is not built into this version)");
}

}  // namespace bs::kernels
