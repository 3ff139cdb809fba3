#include "core/linalg/machine_resources.h"

#include <sys/resource.h>

#include <cstdio>
#include <fstream>
#include <limits>
#include <string>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace drape {

double AvailableMemoryBytes() {
  std::ifstream meminfo("/proc/meminfo");
  std::string line;
  double kib = 0;
  while (std::getline(meminfo, line))
    if (std::sscanf(line.c_str(), "MemAvailable: %lf kB", &kib) == 1) return kib * 1024;
  return std::numeric_limits<double>::infinity();
}

double PeakMemoryBytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return 1024.0 * static_cast<double>(usage.ru_maxrss);  // Linux reports KiB
}

int UseAssemblyThreads(int requested) {
#ifdef _OPENMP
  if (requested > 0) omp_set_num_threads(requested);
  return omp_get_max_threads();
#else
  (void)requested;
  return 1;
#endif
}

}  // namespace drape
