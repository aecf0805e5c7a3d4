#pragma once
// What every FFT in θ shares (solver/mode_solver.cpp, the potential and Navier–Stokes drivers): the one lock
// on FFTW's planner and FFTW-aligned buffers. Work over Fourier modes is split by a ThreadPool (solver/pool.hpp).
#include <fftw3.h>

#include <algorithm>
#include <mutex>
#include <new>

namespace magnus {

/// FFTW's planner is not thread-safe: every plan is made and destroyed under this one lock.
std::mutex& fftw_planner_mutex();

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
