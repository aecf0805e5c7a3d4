#pragma once
// A small persistent thread pool for the viscous time step: the same few workers run every parallel part
// of every step (advection by rings, the mode solves by Fourier modes, the FFT batches by rings), so a
// step pays a wake-up of a spinning worker (~µs), not a thread start (~50 µs) per parallel part.
#include <atomic>
#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace magnus {

class NsPool {
 public:
  /// `threads` ≥ 1 threads in all: the caller and threads − 1 workers.
  explicit NsPool(int threads);
  ~NsPool();
  NsPool(const NsPool&) = delete;
  NsPool& operator=(const NsPool&) = delete;

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
