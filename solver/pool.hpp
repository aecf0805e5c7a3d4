#pragma once
// The solvers' one thread pool: a few persistent workers run every parallel part (the viscous step's
// advection by rings, mode solves by Fourier modes and FFT batches by rings; the per-mode LU and sweeps of
// ModeSolver), so a parallel part pays a wake-up of a spinning worker (~µs), not a thread start (~50 µs).
#include <atomic>
#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace magnus {

/// `threads` threads that split [0, n) ranges: run(f) calls f(t) on each, split() gives part t's range.
class ThreadPool {
 public:
  /// `threads` ≥ 1 threads in all: the caller and threads − 1 workers.
  explicit ThreadPool(int threads);
  ~ThreadPool();
  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;

  int size() const { return int(workers_.size()) + 1; }
  /// f(t) for t = 0…size()−1, t = 0 on the calling thread; returns when all are done. The first exception
  /// thrown by any part is rethrown here. Not reentrant: one run() at a time.
  void run(const std::function<void(int)>& f);

  /// [b, e) of part t when [0, n) is split into size() nearly equal parts.
  void split(int n, int t, int& b, int& e) const {
    const int parts = size();
    b = int(long(n) * t / parts);
    e = int(long(n) * (t + 1) / parts);
  }

 private:
  void work(int t);

  std::vector<std::thread> workers_;
  const std::function<void(int)>* job_ = nullptr;
  std::atomic<unsigned> generation_{0};
  std::atomic<int> pending_{0};
  std::atomic<bool> stop_{false};
  std::atomic<int> sleeping_{0};
  std::mutex mutex_;
  std::condition_variable wake_;
  std::exception_ptr error_;
  std::mutex error_mutex_;
};

}  // namespace magnus
