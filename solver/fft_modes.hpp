#pragma once
// What the two FFT-in-θ solvers share (solver/potential/fft_solver.cpp, solver/mode_solver.cpp): the one lock on
// FFTW's planner, work split over Fourier modes, and FFTW-aligned buffers.
#include <fftw3.h>

#include <algorithm>
#include <mutex>
#include <new>
#include <thread>
#include <vector>

namespace magnus {

/// FFTW's planner is not thread-safe: every plan is made and destroyed under this one lock.
std::mutex& fftw_planner_mutex();

/// Run body(k_begin, k_end) over the modes [0, m) split across `threads` threads (one thread below 256).
template <class F>
void parallel_over_modes(int m, int threads, const F& body) {
  if (threads <= 1 || m < 256) return body(0, m);
  std::vector<std::thread> pool;
  const int chunk = (m + threads - 1) / threads;
  for (int t = 1; t < threads; ++t) {
    const int b = std::min(m, t * chunk), e = std::min(m, (t + 1) * chunk);
    if (b < e) pool.emplace_back([&body, b, e] { body(b, e); });
  }
  body(0, std::min(m, chunk));
  for (auto& th : pool) th.join();
}

/// n values of T in FFTW-aligned memory (SIMD), freed on destruction.
template <class T>
struct FftwBuffer {
  T* p = nullptr;
  explicit FftwBuffer(size_t n) : p(static_cast<T*>(fftw_malloc(sizeof(T) * std::max<size_t>(n, 1)))) {
    if (!p) throw std::bad_alloc();
  }
  ~FftwBuffer() { fftw_free(p); }
  FftwBuffer(const FftwBuffer&) = delete;
  FftwBuffer& operator=(const FftwBuffer&) = delete;
};

}  // namespace magnus
