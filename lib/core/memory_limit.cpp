// The memory limit from sysconf, getrlimit and the cgroup files; OpenBLAS's buffer reserved by one
// product, OpenMP's threads by one empty parallel region.
#include "core/memory_limit.hpp"

#include <dlfcn.h>
#include <fmt/format.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <string>
#include <vector>

#include "core/error.hpp"

namespace hpcontact {
namespace {

// A cgroup limit file holds a number of bytes, or "max" (none).
double cgroup_file_limit(const std::string& path) {
  std::ifstream in(path);
  std::string text;
  if (!(in >> text) || text == "max") return 0.0;
  try {
    const double bytes = std::stod(text);
    // cgroup v1 writes about 2^63 for "no limit".
    return bytes > 0.0 && bytes < 1e18 ? bytes : 0.0;
  } catch (const std::exception&) {
    return 0.0;
  }
}

// The memory limit of this process's cgroup (v2 "0::/path", or v1 "N:memory:/path"), 0 if none.
double cgroup_limit() {
  std::ifstream in("/proc/self/cgroup");
  double limit = 0.0;
  for (std::string line; std::getline(in, line);) {
    const auto first = line.find(':'), second = line.find(':', first + 1);
    if (first == std::string::npos || second == std::string::npos) continue;
    const std::string controllers = line.substr(first + 1, second - first - 1), path = line.substr(second + 1);
    std::vector<std::string> files;
    if (controllers.empty()) {  // v2: the limit of the group and of its ancestors as far as mounted
      files = {"/sys/fs/cgroup" + path + "/memory.max", "/sys/fs/cgroup/memory.max"};
    } else if (controllers.find("memory") != std::string::npos) {
      files = {"/sys/fs/cgroup/memory" + path + "/memory.limit_in_bytes",
               "/sys/fs/cgroup/memory/memory.limit_in_bytes"};
    }
    for (const auto& file : files) {
      const double bytes = cgroup_file_limit(file);
      if (bytes > 0.0 && (limit == 0.0 || bytes < limit)) limit = bytes;
    }
  }
  return limit;
}

// The address space this process has mapped (its virtual size), from /proc/self/statm.
double mapped_bytes() {
  std::ifstream in("/proc/self/statm");
  double pages = 0.0;
  in >> pages;
  return pages * static_cast<double>(sysconf(_SC_PAGE_SIZE));
}

}  // namespace

std::string MemoryLimit::describe() const { return fmt::format("{} of {:.3g} GB", source, bytes / 1e9); }

MemoryLimit memory_limit() {
  MemoryLimit limit{static_cast<double>(sysconf(_SC_PHYS_PAGES)) * static_cast<double>(sysconf(_SC_PAGE_SIZE)),
                    "this machine's memory"};
  rlimit address_space{};
  if (getrlimit(RLIMIT_AS, &address_space) == 0 && address_space.rlim_cur != RLIM_INFINITY &&
      static_cast<double>(address_space.rlim_cur) < limit.bytes)
    limit = {static_cast<double>(address_space.rlim_cur), "the address-space limit (ulimit -v)"};
  const double cgroup = cgroup_limit();
  if (cgroup > 0.0 && cgroup < limit.bytes) limit = {cgroup, "the cgroup's memory limit (a container or batch job)"};
  return limit;
}

std::string out_of_memory_message(const std::string& what) {
  return fmt::format(
      "out of memory{}: the run needs more than {}; use fewer cells, a lower p or fewer ranks per "
      "machine, or raise the limit",
      what.empty() ? "" : " while " + what, memory_limit().describe());
}

void reserve_library_buffers() {
  // Either reservation below would hang or end the process without a word if the address space
  // left cannot hold it: OpenBLAS's buffer (128 MiB, its BUFFER_SIZE on x86-64) and the OpenMP
  // threads' stacks, with room to spare.
  constexpr double kReserved = 320.0 * 1024 * 1024;
  rlimit address_space{};
  if (getrlimit(RLIMIT_AS, &address_space) == 0 && address_space.rlim_cur != RLIM_INFINITY &&
      mapped_bytes() + kReserved > static_cast<double>(address_space.rlim_cur))
    throw OutOfMemory(out_of_memory_message(
        fmt::format("starting (the libraries' buffers and threads need {:.3g} GB more than the {:.3g} GB mapped)",
                    kReserved / 1e9, mapped_bytes() / 1e9)));
  // libgomp keeps the threads of a parallel region for later regions of at most that many threads.
  // CHOLMOD's regions ask for 4 (CHOLMOD_OMP_NUM_THREADS of Debian's build), others for the default.
  using Parallel = void (*)(void (*)(void*), void*, unsigned, unsigned);
  using MaxThreads = int (*)();
  const auto parallel = reinterpret_cast<Parallel>(dlsym(RTLD_DEFAULT, "GOMP_parallel"));
  const auto max_threads = reinterpret_cast<MaxThreads>(dlsym(RTLD_DEFAULT, "omp_get_max_threads"));
  if (parallel && max_threads) parallel([](void*) {}, nullptr, static_cast<unsigned>(std::max(4, max_threads())), 0);
  using Gemm = void (*)(const char*, const char*, const int*, const int*, const int*, const double*, const double*,
                        const int*, const double*, const int*, const double*, double*, const int*);
  // Resolved at run time: the BLAS the process loaded (CHOLMOD's, through PETSc or SuiteSparse).
  const auto gemm = reinterpret_cast<Gemm>(dlsym(RTLD_DEFAULT, "dgemm_"));
  if (!gemm) return;
  // Larger than OpenBLAS's small-matrix path (m n k <= 1e6), which takes no buffer.
  const int n = 128;
  const double one = 1.0, zero = 0.0;
  std::vector<double> a(static_cast<std::size_t>(n) * n, 1.0), c(a.size());
  gemm("N", "N", &n, &n, &n, &one, a.data(), &n, a.data(), &n, &zero, c.data(), &n);
}

}  // namespace hpcontact
