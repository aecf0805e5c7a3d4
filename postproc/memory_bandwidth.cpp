#include "postproc/memory_bandwidth.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <memory>
#include <thread>
#include <vector>

namespace magnus {

std::size_t last_level_cache_bytes() {
  long bytes = 0;
#ifdef _SC_LEVEL3_CACHE_SIZE
  bytes = std::max(bytes, sysconf(_SC_LEVEL3_CACHE_SIZE));
#endif
#ifdef _SC_LEVEL2_CACHE_SIZE
  bytes = std::max(bytes, sysconf(_SC_LEVEL2_CACHE_SIZE));
#endif
  return bytes > 0 ? std::size_t(bytes) : 0;
}

namespace {

/// Runs f(begin, end) on `threads` threads over [0, n), each its contiguous share.
template <class F>
void split_run(int threads, std::size_t n, F f) {
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(f, n * t / threads, n * (t + 1) / threads);
  f(std::size_t(0), n / threads);
  for (auto& th : pool) th.join();
}

}  // namespace

double triad_bandwidth(int threads, std::size_t bytes_each, int repeats) {
  threads = std::max(1, threads);
  if (bytes_each == 0) bytes_each = std::max<std::size_t>(std::size_t(64) << 20, last_level_cache_bytes());
  const std::size_t n = bytes_each / sizeof(double);
  std::unique_ptr<double[]> a(new double[n]), b(new double[n]), c(new double[n]);
  // First touch on the threads that use them (their pages on those threads' memory).
  split_run(threads, n, [&](std::size_t i0, std::size_t i1) {
    std::fill(a.get() + i0, a.get() + i1, 0.0);
    std::fill(b.get() + i0, b.get() + i1, 1.0);
    std::fill(c.get() + i0, c.get() + i1, 2.0);
  });
  using clock = std::chrono::steady_clock;
  double best = 0.0;
  for (int r = 0; r < std::max(1, repeats); ++r) {
    const double s = 0.5 + r;
    const auto t0 = clock::now();
    split_run(threads, n, [&, s](std::size_t i0, std::size_t i1) {
      double* __restrict pa = a.get();
      const double* __restrict pb = b.get();
      const double* __restrict pc = c.get();
      for (std::size_t i = i0; i < i1; ++i) pa[i] = pb[i] + s * pc[i];
    });
    const double seconds = std::chrono::duration<double>(clock::now() - t0).count();
    if (seconds > 0.0) best = std::max(best, 3.0 * double(n) * sizeof(double) / seconds);
  }
  volatile double sink = a[n / 2];  // the result is used: the loop is not optimised away
  (void)sink;
  return best;
}

}  // namespace magnus
