/* SPDX-License-Identifier: GPL-3.0-or-later */
/* A stand-in for libnvidia-ml.so.1 with the entry points BenchScope loads: one GPU, named as a Jetson Orin's
   NVML names it, whose power answers NVML_ERROR_NOT_SUPPORTED (3), as on every Jetson. */
#include <string.h>

typedef struct nvmlDevice_st* nvmlDevice_t;
static int the_gpu;

int nvmlInit_v2(void) { return 0; }
int nvmlShutdown(void) { return 0; }
int nvmlDeviceGetCount_v2(unsigned* n) { *n = 1; return 0; }
int nvmlDeviceGetHandleByIndex_v2(unsigned i, nvmlDevice_t* d) {
  if (i != 0) return 2;
  *d = (nvmlDevice_t)&the_gpu;
  return 0;
}
int nvmlDeviceGetName(nvmlDevice_t d, char* name, unsigned len) {
  (void)d;
  if (len < 13) return 7;
  strcpy(name, "Orin (nvgpu)");
  return 0;
}
int nvmlDeviceGetPowerUsage(nvmlDevice_t d, unsigned* mw) { (void)d; (void)mw; return 3; }
const char* nvmlErrorString(int r) { return r == 3 ? "Not Supported" : "Unknown Error"; }
