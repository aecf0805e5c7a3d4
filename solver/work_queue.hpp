#pragma once
// Independent tasks on the cores: each thread takes the next index as it comes free.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace magnus {

/// task(i) for i = 0 … n − 1, each once, on min(threads, n) threads at once (the caller's among them),
/// the indices taken in increasing order as threads come free; returns when every task is done. A task
/// that throws ends its thread's share; once all threads are done the first exception is rethrown (callers
/// that report each failed task their own way catch inside the task).
inline void for_each_index(size_t n, size_t threads, const std::function<void(size_t)>& task) {
  std::atomic<size_t> next{0};
  std::exception_ptr failed;
  std::mutex mutex;
  auto work = [&] {
    try {
      for (size_t i; (i = next++) < n;) task(i);
    } catch (...) {
      const std::lock_guard<std::mutex> lock(mutex);
      if (!failed) failed = std::current_exception();
    }
  };
  std::vector<std::thread> pool;
  for (size_t t = 1; t < std::min(threads, n); ++t) pool.emplace_back(work);
  work();
  for (auto& t : pool) t.join();
  if (failed) std::rethrow_exception(failed);
}

}  // namespace magnus
