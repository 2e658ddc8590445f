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

// The memory limit of this process's cgroup (v2 "0::/path", or v1 "N:memory:/path") and of its
// ancestors (a batch job's limit may sit above its task's group), 0 if none.
double cgroup_limit() {
  std::ifstream in("/proc/self/cgroup");
  double limit = 0.0;
  for (std::string line; std::getline(in, line);) {
    const auto first = line.find(':'), second = line.find(':', first + 1);
    if (first == std::string::npos || second == std::string::npos) continue;
    const std::string controllers = line.substr(first + 1, second - first - 1);
    const bool v2 = controllers.empty();
    if (!v2 && controllers.find("memory") == std::string::npos) continue;
    const std::string root = v2 ? "/sys/fs/cgroup" : "/sys/fs/cgroup/memory";
    const std::string file = v2 ? "/memory.max" : "/memory.limit_in_bytes";
    for (std::string path = line.substr(second + 1);; path = path.substr(0, path.rfind('/'))) {
      const double bytes = cgroup_file_limit(root + path + file);
      if (bytes > 0.0 && (limit == 0.0 || bytes < limit)) limit = bytes;
      if (path.empty() || path == "/") break;
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

std::string out_of_memory_message(const std::string& what, const std::string& advice) {
  return fmt::format("out of memory{}: the run needs more than {}; {}", what.empty() ? "" : " " + what,
                     memory_limit().describe(), advice);
}

void reserve_library_buffers() {
  // libgomp keeps the threads of a parallel region for later regions of at most that many threads.
  // CHOLMOD's regions ask for 4 (CHOLMOD_OMP_NUM_THREADS of Debian's build), others for the default.
  using Parallel = void (*)(void (*)(void*), void*, unsigned, unsigned);
  using MaxThreads = int (*)();
  const auto parallel = reinterpret_cast<Parallel>(dlsym(RTLD_DEFAULT, "GOMP_parallel"));
  const auto max_threads = reinterpret_cast<MaxThreads>(dlsym(RTLD_DEFAULT, "omp_get_max_threads"));
  const int threads = parallel && max_threads ? std::max(4, max_threads()) : 0;
  // Either reservation would hang or end the process without a word if the address space left
  // could not hold it: OpenBLAS's buffer (128 MiB, its BUFFER_SIZE on x86-64), and per thread its
  // stack (RLIMIT_STACK, 32 MiB when unlimited, as glibc) and the malloc arena it may open (64
  // MiB of address space), with 64 MiB to spare.
  constexpr double kMiB = 1024.0 * 1024.0;
  rlimit stack{};
  const double stack_bytes = getrlimit(RLIMIT_STACK, &stack) == 0 && stack.rlim_cur != RLIM_INFINITY
                                 ? static_cast<double>(stack.rlim_cur)
                                 : 32 * kMiB;
  const double reserved = 128 * kMiB + threads * (stack_bytes + 64 * kMiB) + 64 * kMiB;
  rlimit address_space{};
  if (getrlimit(RLIMIT_AS, &address_space) == 0 && address_space.rlim_cur != RLIM_INFINITY &&
      mapped_bytes() + reserved > static_cast<double>(address_space.rlim_cur))
    throw OutOfMemory(out_of_memory_message(
        fmt::format("while starting (OpenBLAS's buffer and {} OpenMP threads need {:.3g} GB of address space "
                    "beside the {:.3g} GB mapped)",
                    threads, reserved / 1e9, mapped_bytes() / 1e9),
        "raise the limit, or lower OMP_NUM_THREADS (at least 4 threads are started)"));
  if (threads > 0) parallel([](void*) {}, nullptr, static_cast<unsigned>(threads), 0);
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
